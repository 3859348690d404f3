// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Timing/test/ut/FakeTickClock.hpp"

namespace Kit {
namespace FakeTickClock {
U32 now = 0;
U32 step = 0;
U32 fired = 0;
U32 stamps[TickClock::STAMP_HISTORY] = {};

void reset() {
    now = 0;
    step = 0;
    fired = 0;
    for (U32& stamp : stamps) {
        stamp = 0;
    }
}

void fire(U32 tick, U32 at) {
    stamps[tick % TickClock::STAMP_HISTORY] = at;
    fired = tick + 1;
}
}  // namespace FakeTickClock

namespace TickClock {
U32 now() {
    const U32 reading = FakeTickClock::now;
    FakeTickClock::now += FakeTickClock::step;
    return reading;
}
U32 cyclesPerSecond() {
    return 12000000u;
}
U32 ticksFired() {
    return FakeTickClock::fired;
}
U32 stampOf(U32 tick) {
    return FakeTickClock::stamps[tick % STAMP_HISTORY];
}
}  // namespace TickClock
}  // namespace Kit

namespace Kit {
namespace Stages {
// The host tests run Timing without the deployment's stage probe
U32 firstMember(U32 now) {
    (void)now;
    return 0;
}
void lastMember() {}
}  // namespace Stages
}  // namespace Kit
