// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Stages.cpp
// \brief  The deployment's dispatch-stage probe (app/Components/Timing/DispatchStages.hpp)
//
// One instance, marked from the main loop, the watched component's queue
// and task, and Timing. The marks hand over in dispatch order, each through
// the queue or the tick that orders the contexts taking them, so no lock is
// needed. CONFIG_KIT_DISPATCH_STAGES off: every call does nothing, and the
// probe takes no RAM whether or not the build optimizes at link time.
// ======================================================================
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"

#include <zephyr/sys/util.h>
#include <Fw/Types/Assert.hpp>

namespace Kit {
namespace Stages {

#if defined(CONFIG_KIT_DISPATCH_STAGES)

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
    return at >= s_begin && at < s_end;
}

void tickTaken(U32 isrStamp) {
    s_stages.begin(isrStamp, TickClock::now());
}

void mark(StageMark which) {
    if (s_stages.expects(which)) {
        s_stages.mark(which, TickClock::now());
    }
}

U32 firstMember(U32 now) {
    return s_stages.end(now);
}

void lastMember() {
    s_stages.settle();
}

void calibrate(U32 dispatches) {
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
    s_stages.reset();
}

#else  // CONFIG_KIT_DISPATCH_STAGES off: every call does nothing, and no probe is linked

void watch(const void* object, FwSizeType size) {
    (void)object;
    (void)size;
}

bool watches(const void* address) {
    (void)address;
    return false;
}

void tickTaken(U32 isrStamp) {
    (void)isrStamp;
}

void mark(StageMark which) {
    (void)which;
}

U32 firstMember(U32 now) {
    (void)now;
    return 0;
}

void lastMember() {}

void calibrate(U32 dispatches) {
    (void)dispatches;
}

const DispatchStages& stages() {
    // Never read without the probe (Report checks the option first); an
    // empty one, constant-initialized, where a caller does
    static const DispatchStages none;
    return none;
}

void reset() {}

#endif

}  // namespace Stages
}  // namespace Kit
