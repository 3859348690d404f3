// SPDX-License-Identifier: Apache-2.0
// A tick clock the test sets by hand (stands in for app/src/TickClock.cpp)
#ifndef KIT_FAKETICKCLOCK_HPP
#define KIT_FAKETICKCLOCK_HPP

#include "app/Components/Timing/TickClock.hpp"

namespace Kit {
namespace FakeTickClock {
extern U32 now;
//! Cycles the clock moves on at every reading (0: it stands still), so code
//! that computes until a time has passed (Busy.hpp) ends in a test too
extern U32 step;
extern U32 fired;
extern U32 stamps[TickClock::STAMP_HISTORY];
void reset();
//! Fire tick `tick` at counter value `at`
void fire(U32 tick, U32 at);
}  // namespace FakeTickClock
}  // namespace Kit

#endif
