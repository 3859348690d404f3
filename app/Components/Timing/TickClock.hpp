// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TickClock.hpp
// \brief  The board tick as the timing probe sees it
//
// Implemented once for Zephyr in app/src/TickClock.cpp (a k_timer whose
// expiry function timestamps each tick) and by a fake in host unit tests.
// Timestamps come from the free-running cycle counter (k_cycle_get_32: SysTick
// on Cortex-M3), not Os::RawTime, which is milliseconds on Zephyr.
// ======================================================================
#ifndef KIT_TICKCLOCK_HPP
#define KIT_TICKCLOCK_HPP

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {
namespace TickClock {

//! Ticks whose stamps stay available (a ring); older ones are overwritten
constexpr U32 STAMP_HISTORY = 64;

//! Free-running counter, in cycles
U32 now();
//! Counter cycles per second
U32 cyclesPerSecond();
//! Ticks fired by the timer ISR since start (tick indices 0 .. ticksFired()-1)
U32 ticksFired();
//! Counter value the ISR captured for tick `tick`; valid while
//! ticksFired() - tick <= STAMP_HISTORY
U32 stampOf(U32 tick);

}  // namespace TickClock
}  // namespace Kit

#endif
