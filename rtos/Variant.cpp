// ======================================================================
// \title  rtos/Variant.cpp
// \brief  The threaded main loop's half of the tick
//
// The tick ISR wakes the main thread (the most urgent thread) with a
// semaphore; it hands the tick to the rate group driver, whose rate groups are
// threads that preempt everything less urgent. Nothing else to do per tick.
// ======================================================================
#include "app/src/Variant.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Top/KitTopology.hpp"

#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

namespace Kit {
namespace Variant {

namespace {
K_SEM_DEFINE(s_tickSem, 0, 1);
// After the last tick: long enough for the slowest thread to empty its queue
constexpr U32 DRAIN_MS = 50;

// F´ names its threads "ActComp_<n>" when object names are compiled out; a
// thread's entry argument is F´'s task wrapper, a member of the component
// object, so the instance holding it names the thread.
const char* threadName(const struct k_thread* thread) {
    const char* name = Kit::activeInstanceHolding(thread->entry.parameter1);
    if (name == nullptr) {
        name = k_thread_name_get(const_cast<struct k_thread*>(thread));
    }
    return name != nullptr ? name : "?";
}

// Bytes of the thread's stack ever used (the thread analyzer's paint scan)
U32 stackUsed(const struct k_thread* thread) {
    size_t unused = 0;
    const size_t size = thread->stack_info.size;
    if (k_thread_stack_space_get(thread, &unused) != 0) {
        unused = size;  // not measurable: reported as unused, never as fitting
    }
    return static_cast<U32>(size - unused);
}

void printStack(const struct k_thread* thread, void* context) {
    (void)context;
    printk("KIT STACK name=%s size=%u used=%u\n", threadName(thread), static_cast<unsigned>(thread->stack_info.size),
           static_cast<unsigned>(stackUsed(thread)));
}

void addStack(const struct k_thread* thread, void* context) {
    *static_cast<U32*>(context) += stackUsed(thread);
}

void printCpu(const struct k_thread* thread, void* context) {
    const U64 runCycles = *static_cast<const U64*>(context);
    struct k_thread* const mutableThread = const_cast<struct k_thread*>(thread);
    k_thread_runtime_stats_t stats = {};
    if (k_thread_runtime_stats_get(mutableThread, &stats) != 0) {
        return;
    }
    // A run is a scheduling window: from being switched in to switched out
    const U64 runs = stats.average_cycles == 0 ? 0 : stats.total_cycles / stats.average_cycles;
    const U32 share = runCycles == 0 ? 0 : static_cast<U32>((stats.total_cycles * 1000u) / runCycles);
    printk("KIT CPU name=%s runs=%u avg=%u max=%u cpu_permille=%u\n", threadName(thread), static_cast<unsigned>(runs),
           static_cast<unsigned>(stats.average_cycles), static_cast<unsigned>(stats.peak_cycles),
           static_cast<unsigned>(share));
}
}  // namespace

const char* name() {
    return "rtos";
}

const char* contextName() {
    return threadName(k_current_get());
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
    // CONFIG_INIT_STACKS paints every thread stack at creation
}

void reportStacks() {
    k_thread_foreach(printStack, nullptr);
}

U32 stackUsedTotal() {
    U32 total = 0;
    k_thread_foreach(addStack, &total);
    return total;
}

void reportCpu(U64 runCycles) {
    // Counted from boot: the run plus start-up, which is short next to it
    k_thread_foreach(printCpu, &runCycles);
}

}  // namespace Variant
}  // namespace Kit
