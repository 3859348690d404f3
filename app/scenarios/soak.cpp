// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  soak.cpp
// \brief  A long run in virtual time: CONFIG_KIT_SOAK_CHECKPOINTS checkpoints
//         of CONFIG_KIT_SOAK_CHECKPOINT_SECONDS, each with a NO_OP on the
//         uplink
//
// Passes when no rate group ever slipped or missed a cycle, every NO_OP was
// answered, nothing was allocated after init, and the stacks' high-water
// marks stopped growing after the first checkpoint (flat: whatever the run
// does in checkpoint 10 it already did in checkpoint 1, the checkpoint's own report
// included: the reference is taken after it, since printing the line and
// starting the next segment run on the main stack too). Each context's mark
// is held to its own, with room for one interrupt's frame: an interrupt
// taken at a thread's deepest point stacks its frame there, and when that
// first happens depends only on where the tick falls (mps2/an385 rtos: the
// file downlink's mark grew 16 B in minute 2, 728 -> 744 B, a mark an
// earlier build had reached in minute 1), not on a new path or a leak.
// "stack_grown" is the most any context grew, in bytes, allowed or not.
// ======================================================================
#include "Top/KitTopology.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/HeapMonitor.hpp"
#include "app/src/Report.hpp"
#include "app/src/Session.hpp"
#include "app/src/Variant.hpp"

#include <zephyr/arch/cpu.h>
#include <zephyr/sys/printk.h>
#include <zephyr/sys/util.h>

namespace Kit {
namespace Scenario {

namespace {
// The ticks of one checkpoint
constexpr U32 SOAK_CHECKPOINT_TICKS = static_cast<U32>(CONFIG_KIT_SOAK_CHECKPOINT_SECONDS) * CONFIG_KIT_TICK_HZ;

// An interrupt's frame on the interrupted thread's stack (Cortex-M: the
// basic frame, and the floating-point one where the build shares the FPU),
// and the 4 B the entry may add to align the stack to 8 B
constexpr U32 INTERRUPT_FRAME_BYTES = static_cast<U32>(sizeof(struct arch_esf)) + 4U;

// Each context's high-water mark after the first checkpoint
struct Settled {
    U32 used[Variant::MAX_CONTEXTS];
    U32 count;
};
Settled s_settled = {};

void settle() {
    Variant::StackUse entries[Variant::MAX_CONTEXTS];
    s_settled.count = Variant::stacks(entries);
    for (U32 i = 0; i < s_settled.count; i++) {
        s_settled.used[i] = entries[i].used;
    }
}

// The most any context's mark grew past its settled one (the contexts are
// the same, in the same order: no thread is made or ended after start-up)
U32 mostGrown() {
    Variant::StackUse entries[Variant::MAX_CONTEXTS];
    const U32 count = Variant::stacks(entries);
    FW_ASSERT(count == s_settled.count, static_cast<FwAssertArgType>(count),
              static_cast<FwAssertArgType>(s_settled.count));
    U32 grown = 0;
    for (U32 i = 0; i < count; i++) {
        const U32 more = entries[i].used > s_settled.used[i] ? entries[i].used - s_settled.used[i] : 0;
        grown = more > grown ? more : grown;
    }
    return grown;
}
}  // namespace

bool playSoak(const Context& context) {
    const U32 checkpoints = CONFIG_KIT_SOAK_CHECKPOINTS;
    bool passed = true;
    for (U32 checkpoint = 1; checkpoint <= checkpoints; checkpoint++) {
        Uplink::Frame noOp = noOpFrame(2);
        uplink.play(&noOp, 1);
        Session::run(SOAK_CHECKPOINT_TICKS);
        U32 slips = 0;
        bool cyclesOk = true;
        for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
            slips += timing.record(i).slips + timing.record(i).lateStarts;
            cyclesOk = cyclesOk && timing.record(i).cycles == expectedCycles(i, SOAK_CHECKPOINT_TICKS);
        }
        const U32 stackUse = Report::stackUsedTotal();
        const U32 grown = (checkpoint == 1) ? 0 : mostGrown();
        const bool flat = grown <= INTERRUPT_FRAME_BYTES;
        printk(
            "KIT SOAK checkpoint=%u seconds=%u slips=%u cycles_complete=%s rg1kHz_latency_max=%u stack_used=%u "
            "stack_grown=%u stack_flat=%s heap_bytes=%u heap_after_init=%u health_warnings=%u noop=%s\n",
            static_cast<unsigned>(checkpoint), static_cast<unsigned>(CONFIG_KIT_SOAK_CHECKPOINT_SECONDS),
            static_cast<unsigned>(slips), cyclesOk ? "yes" : "no",
            static_cast<unsigned>(timing.record(0).latency.max()), static_cast<unsigned>(stackUse),
            static_cast<unsigned>(grown), flat ? "yes" : "no", static_cast<unsigned>(HeapMonitor::bytesRequested()),
            static_cast<unsigned>(HeapMonitor::allocationsAfterInit()), static_cast<unsigned>(Report::healthWarnings()),
            noOp.asExpected() ? "OK" : "FAILED");
        passed = passed && (slips == 0 || !IS_ENABLED(CONFIG_KIT_DEADLINES_EXPECTED)) && cyclesOk && flat &&
                 noOp.asExpected() && HeapMonitor::allocationsAfterInit() == 0;
        Session::nextSegment();
        if (checkpoint == 1) {
            settle();
        }
    }
    const bool heapOk = Report::heap(context.allocator);
    Report::hash();
    const bool downlinked = Report::downlinkAndTicks();
    // Health's pings over the whole soak: every entry answered, no warning
    const bool healthy = Report::health();
    Report::stacks();
    Report::queues();
    return passed && heapOk && downlinked && healthy;
}

}  // namespace Scenario
}  // namespace Kit
