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
// starting the next segment run on the main stack too).
// ======================================================================
#include "Top/KitTopology.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/HeapMonitor.hpp"
#include "app/src/Report.hpp"
#include "app/src/Session.hpp"

#include <zephyr/sys/printk.h>
#include <zephyr/sys/util.h>

namespace Kit {
namespace Scenario {

namespace {
// The ticks of one checkpoint
constexpr U32 SOAK_CHECKPOINT_TICKS = static_cast<U32>(CONFIG_KIT_SOAK_CHECKPOINT_SECONDS) * CONFIG_KIT_TICK_HZ;
}  // namespace

bool playSoak(const Context& context) {
    const U32 checkpoints = CONFIG_KIT_SOAK_CHECKPOINTS;
    bool passed = true;
    U32 settledStackUse = 0;
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
        const bool flat = (checkpoint == 1) || (stackUse == settledStackUse);
        printk(
            "KIT SOAK checkpoint=%u seconds=%u slips=%u cycles_complete=%s rg1kHz_latency_max=%u stack_used=%u "
            "stack_flat=%s heap_bytes=%u heap_after_init=%u health_warnings=%u noop=%s\n",
            static_cast<unsigned>(checkpoint), static_cast<unsigned>(CONFIG_KIT_SOAK_CHECKPOINT_SECONDS),
            static_cast<unsigned>(slips), cyclesOk ? "yes" : "no",
            static_cast<unsigned>(timing.record(0).latency.max()), static_cast<unsigned>(stackUse), flat ? "yes" : "no",
            static_cast<unsigned>(HeapMonitor::bytesRequested()),
            static_cast<unsigned>(HeapMonitor::allocationsAfterInit()), static_cast<unsigned>(Report::healthWarnings()),
            noOp.asExpected() ? "OK" : "FAILED");
        passed = passed && (slips == 0 || !IS_ENABLED(CONFIG_KIT_DEADLINES_EXPECTED)) && cyclesOk && flat &&
                 noOp.asExpected() && HeapMonitor::allocationsAfterInit() == 0;
        Session::nextSegment();
        settledStackUse = (checkpoint == 1) ? Report::stackUsedTotal() : settledStackUse;
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
