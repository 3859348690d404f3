// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Variant.cpp
// \brief  The rtos model's tick and rate-group dispatch: the threaded main loop's half
//
// The tick ISR wakes the main thread with a semaphore; it hands the tick to
// the rate group driver, whose rate groups are threads. The main thread sits
// just below the 1 kHz group and above every other thread (rtos/Kconfig.model):
// handing that group its cycle switches to it at once, then the tick goes on
// to the slower groups, which preempt everything less urgent. Nothing else to
// do per tick.
// ======================================================================
#include "app/src/Variant.hpp"
#include "rtos/AssertReport.hpp"
#include "rtos/Os/SharedThread.hpp"
#include "rtos/ThreadStacks.hpp"

#include <zephyr/kernel.h>
#include <Fw/Types/Assert.hpp>

namespace Kit {
namespace Variant {

namespace {
K_SEM_DEFINE(s_tickSem, 0, 1);
// After the last tick: long enough for the slowest thread to empty its queue
constexpr U32 DRAIN_MS = 50;

// A thread's entry argument is F´'s task wrapper, a member of the component
// object: app/ names the thread after the instance holding it. Zephyr's
// own threads (main, idle) go by their Zephyr names.
Context contextOf(const struct k_thread* thread) {
    return {k_thread_name_get(const_cast<struct k_thread*>(thread)), thread->entry.parameter1};
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

// k_thread_foreach's callbacks fill a bounded table: threads beyond it are
// counted, and the caller asserts there were none
template <typename Entry>
struct Table {
    Entry (&entries)[MAX_CONTEXTS];
    U32 count;
    U32 overflow;
};

void addStack(const struct k_thread* thread, void* context) {
    Table<StackUse>& table = *static_cast<Table<StackUse>*>(context);
    if (table.count >= MAX_CONTEXTS) {
        table.overflow++;
        return;
    }
    table.entries[table.count++] = {contextOf(thread), static_cast<U32>(thread->stack_info.size), stackUsed(thread)};
}

void addCpu(const struct k_thread* thread, void* context) {
    Table<CpuUse>& table = *static_cast<Table<CpuUse>*>(context);
    k_thread_runtime_stats_t stats = {};
    if (k_thread_runtime_stats_get(const_cast<struct k_thread*>(thread), &stats) != 0) {
        return;
    }
    if (table.count >= MAX_CONTEXTS) {
        table.overflow++;
        return;
    }
    // A run is a scheduling window: from being switched in to switched out
    const U64 runs = stats.average_cycles == 0 ? 0 : stats.total_cycles / stats.average_cycles;
    table.entries[table.count++] = {contextOf(thread), static_cast<U32>(runs), static_cast<U32>(stats.average_cycles),
                                    static_cast<U32>(stats.peak_cycles), stats.total_cycles};
}
}  // namespace

ContextKind contextKind() {
    return ContextKind::THREAD;
}

Context currentContext() {
    return contextOf(k_current_get());
}

StackUse currentStack() {
    const struct k_thread* const thread = k_current_get();
    return {contextOf(thread), static_cast<U32>(thread->stack_info.size), stackUsed(thread)};
}

void onTickIsr() {
    k_sem_give(&s_tickSem);
}

void waitForTick(U32 (*ticksFired)(), U32 handled) {
    // The semaphore only wakes us; the tick count says what to do, so a give
    // that coalesced two ticks loses nothing.
    while (ticksFired() == handled) {
        (void)k_sem_take(&s_tickSem, K_FOREVER);
    }
}

GuardBreach afterTick(U32 nextTickAt) {
    (void)nextTickAt;      // Zephyr's scheduler preempts: nothing to budget
    return {false, 0, 0};  // Zephyr's own detectors (sentinel, MPU guard) end the run themselves
}

GuardBreach guardState() {
    return {false, 0, 0};  // Zephyr's own detectors name an overflow themselves
}

GuardBreach drain() {
    k_sleep(K_MSEC(DRAIN_MS));
    return {false, 0, 0};
}

void prepareStacks() {
    // Each thread's stack at its size in the table (rtos/ThreadStacks.cpp);
    // CONFIG_INIT_STACKS paints every one at creation
    ThreadStacks::provide();
    // An assert's report on a stack of its own, so that no thread's holds it
    // (rtos/AssertReport.cpp)
    AssertReport::start();
}

U32 stacks(StackUse (&out)[MAX_CONTEXTS]) {
    Table<StackUse> table{out, 0, 0};
    k_thread_foreach(addStack, &table);
    FW_ASSERT(table.overflow == 0, static_cast<FwAssertArgType>(table.overflow));
    return table.count;
}

U32 schedule(ScheduleUse (&out)[MAX_CONTEXTS], GuardMargin& guard) {
    (void)out;
    guard = {0, 0};
    return 0;  // Zephyr's priorities decide, nothing is budgeted
}

U32 cpu(CpuUse (&out)[MAX_CONTEXTS]) {
    // Counted from boot: the run plus start-up, which is short next to it
    Table<CpuUse> table{out, 0, 0};
    k_thread_foreach(addCpu, &table);
    // The shared thread's members, each its share of that thread's cycles
    // (the thread's own line holds them all)
    for (U32 i = 0; i < SharedThread::memberCount(); i++) {
        if (table.count >= MAX_CONTEXTS) {
            table.overflow++;
            continue;
        }
        const SharedThread::MemberUse use = SharedThread::memberUse(i);
        const U32 average = use.runs == 0 ? 0 : static_cast<U32>(use.cycles / use.runs);
        table.entries[table.count++] = {{nullptr, use.owner}, use.runs, average, use.maxCycles, use.cycles, true};
    }
    FW_ASSERT(table.overflow == 0, static_cast<FwAssertArgType>(table.overflow));
    return table.count;
}

}  // namespace Variant
}  // namespace Kit
