// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  fake/zephyr/kernel.h
// \brief  Host stand-in for the Zephyr calls baremetal/Os makes
//
// The host tests compile the model's own sources (BudgetedScheduler.cpp,
// CooperativeQueue.cpp) against this header instead of Zephyr's: the cycle
// counter and the ISR test are the test's to set (FakeKernel.cpp holds them).
// Only what those sources call is here, with Zephyr's signatures.
// ======================================================================
#ifndef KIT_FAKE_ZEPHYR_KERNEL_H
#define KIT_FAKE_ZEPHYR_KERNEL_H

#include <cstdint>

namespace KitFake {
extern uint32_t cycles;      //!< what k_cycle_get_32() returns
extern int cyclesPerSecond;  //!< what sys_clock_hw_cycles_per_sec() returns
extern bool inIsr;           //!< what k_is_in_isr() returns
}  // namespace KitFake

inline uint32_t k_cycle_get_32() {
    return KitFake::cycles;
}

inline int sys_clock_hw_cycles_per_sec() {
    return KitFake::cyclesPerSecond;
}

inline bool k_is_in_isr() {
    return KitFake::inIsr;
}

#endif
