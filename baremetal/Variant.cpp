// ======================================================================
// \title  baremetal/Variant.cpp
// \brief  The cooperative main loop's half of the tick
//
// The tick ISR only counts and stamps the tick (app/src/TickClock.cpp): the
// count is the flag. The main loop sleeps until it moves, hands the tick to
// the rate group driver, then gives every task one slice, highest priority
// first. Rate groups never run inside the ISR.
// ======================================================================
#include "app/Components/Timing/TickClock.hpp"
#include "app/src/Variant.hpp"

#include <fprime-baremetal/Os/TaskRunner/TaskRunner.hpp>
#include <zephyr/kernel.h>

namespace Kit {
namespace Variant {

namespace {
// After the last tick: passes enough to empty every queue (the deepest holds 8)
constexpr U32 DRAIN_PASSES = 32;
}  // namespace

const char* name() {
    return "baremetal";
}

void onTickIsr() {}

void waitForTick(U32 handled) {
    // Check and sleep atomically, so a tick between the check and the WFI
    // cannot be slept through.
    unsigned int key = irq_lock();
    while (TickClock::ticksFired() == handled) {
        k_cpu_atomic_idle(key);
        key = irq_lock();
    }
    irq_unlock(key);
}

void afterTick() {
    Os::Baremetal::TaskRunner::getSingleton().runAll();
}

void drain() {
    for (U32 pass = 0; pass < DRAIN_PASSES; pass++) {
        Os::Baremetal::TaskRunner::getSingleton().runAll();
    }
}

}  // namespace Variant
}  // namespace Kit
