// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Session.cpp
// \brief  The shared main loop, segment by segment
// ======================================================================
#include "app/src/Session.hpp"
#include "Top/KitTopology.hpp"
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/src/Fatal.hpp"
#include "app/src/Report.hpp"
#include "app/src/TickControl.hpp"
#include "app/src/Variant.hpp"

#include <Fw/Types/Assert.hpp>

#include <zephyr/fatal_types.h>

namespace Kit {
namespace Session {

namespace {
// A model's stack guard that lost its paint ends the run before corrupted
// memory is trusted
void haltOnBreach(const Variant::GuardBreach& breach) {
    if (breach.breached) {
        Report::guardBreach(breach);
        Fatal::halt(K_ERR_STACK_CHK_FAIL);
    }
}

U32 gcd(U32 a, U32 b) {
    // Euclid on dividers of at most a few thousand: a handful of steps
    while (b != 0) {
        const U32 rest = a % b;
        a = b;
        b = rest;
    }
    return a;
}
}  // namespace

U32 hyperperiod() {
    U32 lcm = 1;
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        lcm = (lcm / gcd(lcm, RATE_GROUPS[i].divisor)) * RATE_GROUPS[i].divisor;
    }
    return lcm;
}

namespace {

// The fastest group (RATE_GROUPS[0]) is dispatched at the tick being handed
// over: the rate group driver's rule, on the ticks the timing probe counts
bool fastestDue() {
    const RateGroupSpec& fastest = RATE_GROUPS[0];
    return (timing.ticksDriven() % fastest.divisor) == fastest.offset;
}

// The main loop: `ticks` ticks (0: no limit), or, when `until` is given,
// until it holds at the end of a hyperperiod
void loop(U32 ticks, bool (*until)()) {
    const U32 periodUs = 1000000u / CONFIG_KIT_TICK_HZ;
    const U32 tickCycles = TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ;
    const U32 period = hyperperiod();
    U32 handled = 0;
    bool stop = false;
    TickControl::start(periodUs);
    // A run of 0 ticks never ends by count (flight-like); otherwise the loop
    // is bounded by the tick count.
    while (!stop && (ticks == 0 || handled < ticks)) {
        Variant::waitForTick(TickClock::ticksFired, handled);
        const U32 fired = TickClock::ticksFired();
        // Hand over every tick that fired, in order: a main loop that fell
        // behind shows up as latency and slips, never as lost cycles.
        while (!stop && handled != fired && (ticks == 0 || handled < ticks)) {
            // The stage probe follows the fastest group's dispatch: a tick
            // that dispatches it (every tick where it runs at the tick rate)
            if (fastestDue()) {
                Stages::tickTaken(TickClock::stampOf(handled));
            }
            timing.tick();
            // The tick just handed over fired at its stamp; the next is due
            // a period later (already past if the loop is behind)
            const U32 nextTickAt = TickClock::stampOf(handled) + tickCycles;
            handled++;
            haltOnBreach(Variant::afterTick(nextTickAt));
            stop = until != nullptr && (handled % period) == 0 && until();
        }
    }
    TickControl::stop();
    haltOnBreach(Variant::drain());
}

}  // namespace

void run(U32 ticks) {
    loop(ticks, nullptr);
}

void serve(bool (*until)()) {
    FW_ASSERT(until != nullptr);
    loop(0, until);
}

void nextSegment() {
    timing.restart(hyperperiod());
    Stages::reset();
}

U64 cyclesOf(U32 ticks) {
    // From the tick count, not a counter difference: that wraps after 2^32
    // cycles (358 s at 12 MHz)
    return static_cast<U64>(ticks) * (TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);
}

}  // namespace Session
}  // namespace Kit
