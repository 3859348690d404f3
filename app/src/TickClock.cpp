// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TickClock.cpp
// \brief  The board tick on Zephyr: a periodic k_timer whose expiry function
//         (run in the system clock ISR) counts and timestamps every tick
// ======================================================================
#include "app/Components/Timing/TickClock.hpp"
#include "app/src/TickControl.hpp"
#include "app/src/TickPath.h"
#include "app/src/Variant.hpp"

#include <zephyr/kernel.h>

namespace Kit {
namespace TickClock {

namespace {
struct k_timer s_timer;
volatile U32 s_fired = 0;
U32 s_stamps[STAMP_HISTORY];

void onExpiry(struct k_timer* timer) {
    (void)timer;
    kit_tick_stamp(&s_fired, s_stamps, STAMP_HISTORY);
    Variant::onTickIsr();
}
}  // namespace

U32 now() {
    return k_cycle_get_32();
}

U32 cyclesPerSecond() {
    return static_cast<U32>(sys_clock_hw_cycles_per_sec());
}

U32 ticksFired() {
    return s_fired;
}

U32 stampOf(U32 tick) {
    return s_stamps[tick % STAMP_HISTORY];
}

}  // namespace TickClock

namespace TickControl {

void start(U32 periodUs) {
    // Each segment numbers its ticks from zero (the timer is stopped here, so
    // the ISR cannot race this store); a tick that fired after the previous
    // segment's last handled one is dropped with it.
    TickClock::s_fired = 0;
    k_timer_init(&TickClock::s_timer, TickClock::onExpiry, nullptr);
    kit_tick_start(&TickClock::s_timer, periodUs);
}

void stop() {
    k_timer_stop(&TickClock::s_timer);
}

}  // namespace TickControl
}  // namespace Kit
