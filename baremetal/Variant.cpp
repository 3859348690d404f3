// ======================================================================
// \title  baremetal/Variant.cpp
// \brief  The cooperative main loop's half of the tick
//
// The tick ISR only counts and stamps the tick (app/src/TickClock.cpp): the
// count is the flag. The main loop sleeps until it moves, hands the tick to
// the rate group driver, then gives every task one slice, highest priority
// first. Rate groups never run inside the ISR.
// ======================================================================
#include "app/src/Variant.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Top/KitTopology.hpp"
#include "app/src/Fatal.hpp"
#include "baremetal/Os/TimedTask.hpp"

#include <zephyr/fatal_types.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>
#include <fprime-baremetal/Os/TaskRunner/TaskRunner.hpp>

K_KERNEL_STACK_DECLARE(z_main_stack, CONFIG_MAIN_STACK_SIZE);

namespace Kit {
namespace Variant {

namespace {
// After the last tick: passes enough to empty every queue (the deepest holds 8)
constexpr U32 DRAIN_PASSES = 32;

// The one stack: main's. Painted below the live frame at start-up; the
// high-water mark is where the paint ends.
constexpr U32 PAINT = 0xCAFEF00Du;
constexpr U32 PAINT_GUARD_BYTES = 128;  // below the current frame, left alone
// The stack guard: the lowest words of the stack, painted like the rest. No
// MPU is assumed, so nothing stops an overflow; a guard word that lost its
// paint means the stack reached its last 32 bytes (or went past them), and
// the run stops before corrupted memory is trusted.
constexpr U32 GUARD_WORDS = 8;

// Cycles the main loop spent asleep waiting for a tick, and how often
U64 s_idleCycles = 0;
U32 s_idleWaits = 0;
U32 s_idleMax = 0;

U32 permille(U64 part, U64 whole) {
    return whole == 0 ? 0 : static_cast<U32>((part * 1000u) / whole);
}

U32* stackBottom() {
    return reinterpret_cast<U32*>(K_KERNEL_STACK_BUFFER(z_main_stack));
}

// One pass of every task, then the stack guard
void runPass() {
    Os::Baremetal::TaskRunner::getSingleton().runAll();
    const U32* const bottom = stackBottom();
    for (U32 i = 0; i < GUARD_WORDS; i++) {
        if (bottom[i] != PAINT) {
            printk("KIT FATAL stack=main guard_word=%u address=0x%08x: stack overflow\n", static_cast<unsigned>(i),
                   static_cast<unsigned>(reinterpret_cast<uintptr_t>(&bottom[i])));
            Fatal::halt(K_ERR_STACK_CHK_FAIL);
        }
    }
}
}  // namespace

const char* name() {
    return "baremetal";
}

void onTickIsr() {}

const char* contextName() {
    return "main";  // the only context besides interrupts
}

void waitForTick(U32 handled) {
    const U32 begin = TickClock::now();
    // Check and sleep without a window: on ARMv7-M k_cpu_idle() masks with
    // PRIMASK before it lifts the irq_lock (BASEPRI) and sleeps in WFI, so a
    // tick that fires after the check still wakes it. Not
    // k_cpu_atomic_idle(): it sleeps in WFE, which QEMU executes as a busy
    // spin, costing wall time (a soak ran 5x slower) though not virtual time.
    unsigned int key = irq_lock();
    while (TickClock::ticksFired() == handled) {
        k_cpu_idle();
        key = irq_lock();
    }
    irq_unlock(key);
    const U32 slept = TickClock::now() - begin;
    s_idleCycles += slept;
    s_idleWaits++;
    s_idleMax = slept > s_idleMax ? slept : s_idleMax;
}

void afterTick() {
    runPass();
}

void drain() {
    for (U32 pass = 0; pass < DRAIN_PASSES; pass++) {
        runPass();
    }
}

void prepareStacks() {
    // Paint from the bottom of the stack up to a guard below this frame
    const uintptr_t end = reinterpret_cast<uintptr_t>(__builtin_frame_address(0)) - PAINT_GUARD_BYTES;
    for (U32* word = stackBottom(); reinterpret_cast<uintptr_t>(word) < end; word++) {
        *word = PAINT;
    }
}

U32 stackUsedTotal() {
    // Where the paint ends is the high-water mark
    const U32 size = K_KERNEL_STACK_SIZEOF(z_main_stack);
    const U32* word = stackBottom();
    const U32* const top = word + size / sizeof(U32);
    while (word < top && *word == PAINT) {
        word++;
    }
    return size - static_cast<U32>(reinterpret_cast<const U8*>(word) - reinterpret_cast<const U8*>(stackBottom()));
}

void reportStacks() {
    printk("KIT STACK name=main size=%u used=%u\n", static_cast<unsigned>(K_KERNEL_STACK_SIZEOF(z_main_stack)),
           static_cast<unsigned>(stackUsedTotal()));
}

void reportCpu(U64 runCycles) {
    for (FwSizeType i = 0; i < TimedTask::taskCount(); i++) {
        const SliceRecord& task = TimedTask::record(i);
        const char* const name = activeInstanceHolding(task.argument);
        printk("KIT CPU name=%s runs=%u avg=%u max=%u cpu_permille=%u\n", name != nullptr ? name : "?",
               static_cast<unsigned>(task.slices),
               static_cast<unsigned>(task.slices == 0 ? 0 : task.cycles / task.slices),
               static_cast<unsigned>(task.maxCycles), static_cast<unsigned>(permille(task.cycles, runCycles)));
    }
    printk("KIT CPU name=idle runs=%u avg=%u max=%u cpu_permille=%u\n", static_cast<unsigned>(s_idleWaits),
           static_cast<unsigned>(s_idleWaits == 0 ? 0 : s_idleCycles / s_idleWaits), static_cast<unsigned>(s_idleMax),
           static_cast<unsigned>(permille(s_idleCycles, runCycles)));
}

}  // namespace Variant
}  // namespace Kit
