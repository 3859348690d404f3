// ======================================================================
// \title  rtos/Variant.cpp
// \brief  The threaded main loop's half of the tick
//
// The tick ISR wakes the main thread (the most urgent thread) with a
// semaphore; it hands the tick to the rate group driver, whose rate groups are
// threads that preempt everything less urgent. Nothing else to do per tick.
// ======================================================================
#include "app/Components/Timing/TickClock.hpp"
#include "app/src/Variant.hpp"

#include <zephyr/debug/thread_analyzer.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

namespace Kit {
namespace Variant {

namespace {
K_SEM_DEFINE(s_tickSem, 0, 1);
// After the last tick: long enough for the slowest thread to empty its queue
constexpr U32 DRAIN_MS = 50;

void printStack(struct thread_analyzer_info* info) {
    printk("KIT STACK name=%s size=%u used=%u\n", info->name, static_cast<unsigned>(info->stack_size),
           static_cast<unsigned>(info->stack_used));
}
}  // namespace

const char* name() {
    return "rtos";
}

void onTickIsr() {
    k_sem_give(&s_tickSem);
}

void waitForTick(U32 handled) {
    // The semaphore only wakes us; the tick count says what to do, so a give
    // that coalesced two ticks loses nothing.
    while (TickClock::ticksFired() == handled) {
        (void)k_sem_take(&s_tickSem, K_FOREVER);
    }
}

void afterTick() {}

void drain() {
    k_sleep(K_MSEC(DRAIN_MS));
}

void prepareStacks() {
    // CONFIG_THREAD_ANALYZER paints every thread stack at creation
}

void reportStacks() {
    thread_analyzer_run(printStack, 0);
}

}  // namespace Variant
}  // namespace Kit
