// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Stages.cpp
// \brief  The deployment's dispatch-stage probe (app/Components/Timing/DispatchStages.hpp)
//
// One instance, marked from the main loop, the watched component's queue
// and task, and Timing. The marks hand over in dispatch order, each through
// the queue or the tick that orders the contexts taking them, so no lock is
// needed. CONFIG_KIT_DISPATCH_STAGES off: every call does nothing.
// ======================================================================
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"

#include <zephyr/sys/util.h>
#include <Fw/Types/Assert.hpp>

namespace Kit {
namespace Stages {

namespace {
// Passive rate groups are called in the tick, with no queue to mark
DispatchStages s_stages(IS_ENABLED(CONFIG_KIT_RATE_GROUPS_PASSIVE));
const U8* s_begin = nullptr;
const U8* s_end = nullptr;
}  // namespace

void watch(const void* object, FwSizeType size) {
    s_begin = static_cast<const U8*>(object);
    s_end = s_begin + size;
}

bool watches(const void* address) {
    const U8* const at = static_cast<const U8*>(address);
    return IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES) && at >= s_begin && at < s_end;
}

void tickTaken(U32 isrStamp) {
    if (IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES)) {
        s_stages.begin(isrStamp, TickClock::now());
    }
}

void mark(StageMark which) {
    if (IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES) && s_stages.expects(which)) {
        s_stages.mark(which, TickClock::now());
    }
}

U32 firstMember(U32 now) {
    return IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES) ? s_stages.end(now) : 0;
}

void lastMember() {
    if (IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES)) {
        s_stages.settle();
    }
}

void calibrate(U32 dispatches) {
    if (!IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES)) {
        return;
    }
    // Whole dispatches on the scratch state, through the same calls the run
    // makes (the tick, then every mark); the end, which the run takes after
    // its stamp, is left out of the time
    FW_ASSERT(dispatches > 0);
    s_stages.setMarkCost(0);
    U32 total = 0;
    for (U32 i = 0; i < dispatches; i++) {
        const U32 begin = TickClock::now();
        tickTaken(begin);
        for (U32 m = static_cast<U32>(StageMark::SENT); m < s_stages.marks(); m++) {
            mark(static_cast<StageMark>(m));
        }
        total += TickClock::now() - begin;
        (void)s_stages.end(begin);
        s_stages.settle();
    }
    s_stages.reset();
    s_stages.setMarkCost(total / (dispatches * s_stages.marks()));
}

const DispatchStages& stages() {
    return s_stages;
}

void reset() {
    if (IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES)) {
        s_stages.reset();
    }
}

}  // namespace Stages
}  // namespace Kit
