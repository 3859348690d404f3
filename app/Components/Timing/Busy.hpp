// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Busy.hpp
// \brief  Computation that lasts a given time: the load and fault injectors'
//         stand-in for real work (a filter, a checksum, a serial parser)
// ======================================================================
#ifndef KIT_BUSY_HPP
#define KIT_BUSY_HPP

#include "app/Components/Timing/TickClock.hpp"

namespace Kit {

//! Compute (an LCG, so the loop is work the optimizer cannot drop) until
//! `us` microseconds of the cycle counter have passed, without yielding:
//! under a cooperative scheduler nothing else runs meanwhile, under an RTOS
//! a more urgent thread preempts it. Returns the last LCG value. The loop is
//! bounded by time: callers bound `us` (command validation).
inline U32 busyFor(U32 us, U32 seed) {
    const U32 cycles = static_cast<U32>((static_cast<U64>(us) * TickClock::cyclesPerSecond()) / 1000000u);
    const U32 begin = TickClock::now();
    U32 value = seed;
    while (static_cast<U32>(TickClock::now() - begin) < cycles) {
        value = value * 1664525u + 1013904223u;
    }
    return value;
}

}  // namespace Kit

#endif
