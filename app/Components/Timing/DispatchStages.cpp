// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  DispatchStages.cpp
// ======================================================================
#include "app/Components/Timing/DispatchStages.hpp"

#include <Fw/Types/Assert.hpp>

namespace Kit {

namespace {
const char* const STAGE_NAMES[DispatchStages::STAGES] = {
    "isr_to_taken",        // the ISR's return and the main loop waking
    "taken_to_sent",       // the rate group driver, the group's port, serializing the cycle
    "sent_to_queued",      // the queue's insert
    "queued_to_picked",    // waking the group's context: a thread switch, or the rest of the tick and the pass
    "picked_to_received",  // the queue's remove and copy
    "received_to_member",  // deserializing, the group's handler, up to its first member
};
// A passive group's: no queue between the tick and the group
const char* const DIRECT_STAGE_NAMES[2] = {
    "isr_to_taken",     // as above
    "taken_to_member",  // the rate group driver, the group's port and handler, up to its first member
};
}  // namespace

DispatchStages::DispatchStages(bool direct) : m_marks(direct ? 1 : MARKS) {}

const char* DispatchStages::stageName(U32 stage) const {
    FW_ASSERT(stage < this->stageCount(), static_cast<FwAssertArgType>(stage));
    return m_marks == MARKS ? STAGE_NAMES[stage] : DIRECT_STAGE_NAMES[stage];
}

void DispatchStages::setMarkCost(U32 cycles) {
    m_markCost = cycles;
}

void DispatchStages::begin(U32 isrStamp, U32 now) {
    this->settle();  // normally done after the last member already
    if (m_open) {
        m_incomplete++;  // the previous tick's dispatch never reached its first member
    }
    m_stamps[0] = isrStamp;
    m_stamps[1] = now;
    m_next = static_cast<U32>(StageMark::TICK_TAKEN) + 1;
    m_open = true;
}

void DispatchStages::mark(StageMark which, U32 now) {
    const U32 index = static_cast<U32>(which);
    FW_ASSERT(index < MARKS, static_cast<FwAssertArgType>(index));
    if (this->expects(which)) {
        m_stamps[index + 1] = now;
        m_next++;
    }
}

U32 DispatchStages::end(U32 now) {
    if (!m_open) {
        return 0;  // a cycle before the first tick was taken, or the probes are off
    }
    m_open = false;
    const U32 marks = m_next;  // taken since (and including) the tick
    if (marks != m_marks) {
        m_incomplete++;
        return marks * m_markCost;
    }
    m_stamps[m_marks + 1] = now;
    m_closed = true;
    return marks * m_markCost;
}

void DispatchStages::settle() {
    if (!m_closed) {
        return;
    }
    m_closed = false;
    m_complete++;
    for (U32 i = 0; i < this->stageCount(); i++) {
        const U32 raw = elapsedCycles(m_stamps[i], m_stamps[i + 1]);
        // Each stage ends at a mark of ours but the last (Timing's own stamp,
        // which its latency has always included): that mark's cost is ours
        const U32 probe = (i + 1 < this->stageCount()) ? m_markCost : 0;
        m_stages[i].add(raw > probe ? raw - probe : 0);
    }
}

void DispatchStages::reset() {
    for (CycleStats& stats : m_stages) {
        stats.reset();
    }
    m_complete = 0;
    m_incomplete = 0;
    m_open = false;
    m_closed = false;
    m_next = 0;
}

const CycleStats& DispatchStages::stage(U32 index) const {
    FW_ASSERT(index < STAGES, static_cast<FwAssertArgType>(index));
    return m_stages[index];
}

}  // namespace Kit
