// SPDX-License-Identifier: Apache-2.0
// The dispatch-stage probe's bookkeeping: stages from the marks, the marks'
// cost out of each stage and handed back for the latency, marks out of
// order ignored, dispatches missing a mark counted and left out; a passive
// group's direct path (the tick, then the member).
#include <gtest/gtest.h>
#include "app/Components/Timing/DispatchStages.hpp"

namespace {

using Kit::DispatchStages;
using Kit::StageMark;

// A dispatch with every mark: ISR stamp at `at`, then the stages' raw widths
void dispatch(DispatchStages& stages, U32 at, const U32 (&widths)[DispatchStages::STAGES]) {
    U32 now = at + widths[0];
    stages.begin(at, now);
    for (U32 m = static_cast<U32>(StageMark::SENT); m < DispatchStages::MARKS; m++) {
        now += widths[m];
        stages.mark(static_cast<StageMark>(m), now);
    }
    now += widths[DispatchStages::MARKS];
    (void)stages.end(now);
    stages.settle();
}

TEST(DispatchStages, StagesNetOfTheMarkThatEndsThem) {
    DispatchStages stages;
    stages.setMarkCost(10);
    dispatch(stages, 1000, {50, 60, 70, 80, 90, 100});
    EXPECT_EQ(stages.complete(), 1u);
    EXPECT_EQ(stages.stage(0).max(), 40u);
    EXPECT_EQ(stages.stage(4).max(), 80u);
    EXPECT_EQ(stages.stage(5).max(), 100u);  // ends at Timing's own stamp: nothing to take out
}

TEST(DispatchStages, EndReturnsTheMarksCost) {
    DispatchStages stages;
    stages.setMarkCost(7);
    stages.begin(0, 10);
    for (U32 m = static_cast<U32>(StageMark::SENT); m < DispatchStages::MARKS; m++) {
        stages.mark(static_cast<StageMark>(m), 10 + m);
    }
    EXPECT_EQ(stages.end(100), DispatchStages::MARKS * 7);
}

TEST(DispatchStages, AcrossTheCounterWrap) {
    DispatchStages stages;
    dispatch(stages, 0xFFFFFFF0u, {20, 20, 20, 20, 20, 20});
    for (U32 i = 0; i < DispatchStages::STAGES; i++) {
        EXPECT_EQ(stages.stage(i).max(), 20u);
    }
}

TEST(DispatchStages, MissingMarkIsIncompleteAndLeftOut) {
    DispatchStages stages;
    stages.setMarkCost(5);
    stages.begin(0, 10);
    stages.mark(StageMark::SENT, 20);
    stages.mark(StageMark::PICKED, 30);  // QUEUED never came: ignored, out of order
    EXPECT_EQ(stages.end(40), 2u * 5u);  // the tick and SENT were taken
    stages.settle();
    EXPECT_EQ(stages.complete(), 0u);
    EXPECT_EQ(stages.incomplete(), 1u);
    EXPECT_EQ(stages.stage(0).count(), 0u);
}

TEST(DispatchStages, AbandonedDispatchIsCounted) {
    DispatchStages stages;
    stages.begin(0, 10);
    stages.begin(100, 110);  // the first never reached its member
    EXPECT_EQ(stages.incomplete(), 1u);
    EXPECT_EQ(stages.end(200), 0u);  // only the tick's mark, at no cost set
    EXPECT_EQ(stages.incomplete(), 2u);
}

TEST(DispatchStages, EndWithoutBeginChangesNothing) {
    DispatchStages stages;
    stages.setMarkCost(9);
    EXPECT_EQ(stages.end(5), 0u);
    EXPECT_EQ(stages.complete() + stages.incomplete(), 0u);
}

TEST(DispatchStages, DirectPathIsTheTickThenTheMember) {
    DispatchStages stages(true);  // a passive group: called in the tick
    stages.setMarkCost(10);
    EXPECT_EQ(stages.marks(), 1u);
    EXPECT_EQ(stages.stageCount(), 2u);
    EXPECT_STREQ(stages.stageName(1), "taken_to_member");
    stages.begin(1000, 1050);
    EXPECT_FALSE(stages.expects(StageMark::SENT));  // no queue on its path: a stray mark costs nothing
    stages.mark(StageMark::SENT, 1060);
    EXPECT_EQ(stages.end(1200), 10u);  // the tick's mark only
    stages.settle();
    EXPECT_EQ(stages.complete(), 1u);
    EXPECT_EQ(stages.incomplete(), 0u);
    EXPECT_EQ(stages.stage(0).max(), 40u);   // net of the tick's mark
    EXPECT_EQ(stages.stage(1).max(), 150u);  // ends at Timing's own stamp
}

}  // namespace
