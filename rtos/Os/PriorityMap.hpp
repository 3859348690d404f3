// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  PriorityMap.hpp
// \brief  F´ task priority (higher is more urgent) -> Zephyr thread priority
//         (lower is more urgent)
//
// fprime-zephyr passes F´ priorities to k_thread_create unchanged and clamps
// anything above 14, which inverts a topology written in F´'s convention and
// silently merges its top priorities. The kit maps instead, and refuses what
// cannot be mapped. Pure and header-only so host tests cover it.
// ======================================================================
#ifndef KIT_PRIORITYMAP_HPP
#define KIT_PRIORITYMAP_HPP

namespace Kit {

//! Map F´ priority `fprime` onto a preemptive Zephyr priority.
//! `preemptLevels` is CONFIG_NUM_PREEMPT_PRIORITIES (Zephyr priorities
//! 0 .. preemptLevels-1); `tick` is the level of the kit's own tick thread
//! (CONFIG_MAIN_THREAD_PRIORITY), which no task may share: a task there
//! would neither preempt the tick nor be preempted by it. The board's
//! table decides which tasks sit above the tick (the fastest rate group)
//! and which below. Returns -1 when `fprime` does not fit.
constexpr int zephyrPriority(unsigned long fprime, int preemptLevels, int tick) {
    return (fprime > static_cast<unsigned long>(preemptLevels - 1) ||
            (preemptLevels - 1) - static_cast<int>(fprime) == tick)
               ? -1
               : (preemptLevels - 1) - static_cast<int>(fprime);
}

}  // namespace Kit

#endif
