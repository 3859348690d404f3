// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  DispatchStages.hpp
// \brief  Where the fastest rate group's dispatch latency goes, stage by stage
//
// The dispatch of the fastest rate group (rg1kHz) crosses, in order: the
// timer ISR's stamp, the main loop taking the tick, the rate group driver
// handing the cycle to the group's queue (serialized, then queued), the
// group's context being picked (a thread switch, or a TaskRunner slice),
// the message taken off the queue, and the group calling its first member
// (Timing's probe). Each crossing is a mark; the intervals between marks are
// the stages. The marks are taken where the crossing happens: the main loop
// (app/src/Session.cpp), the kit's message queue of the watched component
// (rtos/Os, baremetal/Os), baremetal's slice wrapper, and Timing.
//
// A mark costs cycles of its own (a counter read and a store). That cost is
// measured before the run and subtracted: each stage is net of the mark
// that ends it, and the latency Timing records is net of every mark taken
// on the way, so the probes leave the numbers as they would be without them.
//
// Passive rate groups (baremetal_passive) are called, not sent a message:
// their dispatch is direct, the tick taken and then the first member, two
// stages (isr_to_taken, taken_to_member).
//
// The class is plain C++ (host-tested); app/src/Stages.cpp holds the one
// instance and the free functions the OS layers call.
// ======================================================================
#ifndef KIT_DISPATCHSTAGES_HPP
#define KIT_DISPATCHSTAGES_HPP

#include "app/Components/Timing/CycleStats.hpp"

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {

//! The marks between the ISR's stamp and the first member, in dispatch order
enum class StageMark : U8 {
    TICK_TAKEN = 0,  //!< the main loop (or tick thread) took the tick
    SENT,            //!< the driver's cycle reached the group's queue (serialized)
    QUEUED,          //!< the message is in the queue, before the receiver is woken
    PICKED,          //!< the group's context runs (thread switched in, or its slice began)
    RECEIVED,        //!< the message is copied out of the queue
    COUNT
};

class DispatchStages {
  public:
    static constexpr U32 MARKS = static_cast<U32>(StageMark::COUNT);
    //! Stages: ISR stamp -> each mark -> the first member
    static constexpr U32 STAGES = MARKS + 1;

    //! `direct`: the group is called in the tick (passive), its path the
    //! tick taken and the first member; otherwise every mark, through its queue
    explicit DispatchStages(bool direct = false);

    //! Marks on this group's path (MARKS, or 1 when direct) and the stages between them
    U32 marks() const { return m_marks; }
    U32 stageCount() const { return m_marks + 1; }

    //! The stage names, for the record ("isr_to_taken", ...)
    const char* stageName(U32 stage) const;

    //! Cycles one mark costs (measured by the caller before the run)
    void setMarkCost(U32 cycles);
    U32 markCost() const { return m_markCost; }

    //! The tick fired at `isrStamp` and was taken at `now`: a dispatch begins
    //! (one still open is abandoned and counted)
    void begin(U32 isrStamp, U32 now);
    //! Whether `which` is the next mark of an open dispatch (the caller
    //! reads the clock only then: a mark that would be ignored costs nothing)
    bool expects(StageMark which) const { return m_open && m_next < m_marks && static_cast<U32>(which) == m_next; }
    //! A mark at `now`; ignored unless expects(which)
    void mark(StageMark which, U32 now);
    //! The first member ran at `now`: the dispatch closes. Returns the
    //! cycles the marks taken since begin() cost, for the caller to take
    //! out of its own latency
    U32 end(U32 now);
    //! A closed dispatch with every mark becomes a sample of every stage.
    //! Called after the group's last member: the statistics' own work stays
    //! out of the group's execution time and out of the next dispatch
    void settle();

    //! Forget the samples (a new measured segment)
    void reset();

    const CycleStats& stage(U32 index) const;
    //! Dispatches with every mark, and those that missed one (abandoned, or
    //! a mark the path did not take)
    U32 complete() const { return m_complete; }
    U32 incomplete() const { return m_incomplete; }

  private:
    U32 m_stamps[STAGES + 1] = {};  //!< the ISR stamp, each mark, the first member
    U32 m_marks;                    //!< marks on the path: MARKS, or 1 (direct)
    U32 m_next = 0;                 //!< the next mark expected of the open dispatch
    bool m_open = false;
    bool m_closed = false;  //!< a complete dispatch awaits settle()
    U32 m_markCost = 0;
    U32 m_complete = 0;
    U32 m_incomplete = 0;
    CycleStats m_stages[STAGES];
};

//! The deployment's one instance and the calls the OS layers make
//! (app/src/Stages.cpp; a no-op when CONFIG_KIT_DISPATCH_STAGES is off)
namespace Stages {
//! The component whose dispatch is broken down: its queue and its task lie
//! inside [object, object + size). Set before the topology is initialized.
void watch(const void* object, FwSizeType size);
//! Whether `address` (a queue, a task argument) lies inside the watched component
bool watches(const void* address);
//! The main loop took the tick that fired at `isrStamp`
void tickTaken(U32 isrStamp);
//! A mark, by a queue or task of the watched component
void mark(StageMark which);
//! The first member ran at `now`; returns the cycles of marks to subtract
U32 firstMember(U32 now);
//! The group's last member ran: the closed dispatch joins the statistics
void lastMember();
//! Measure one mark's cost over `dispatches` scratch dispatches (before
//! the run) and clear the samples
void calibrate(U32 dispatches);
//! The samples so far, for the record
const DispatchStages& stages();
//! A new measured segment
void reset();
}  // namespace Stages

}  // namespace Kit

#endif
