// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TimedTask.hpp
// \brief  fprime-baremetal's cooperative task, each slice timed
//
// The TaskRunner calls a task's routine once per slice; this task hands it a
// trampoline instead, which times the routine with the cycle counter. What a
// thread-level CPU table is on the RTOS variant, this is on baremetal.
// ======================================================================
#ifndef KIT_TIMEDTASK_HPP
#define KIT_TIMEDTASK_HPP

#include "fprime-baremetal/Os/Baremetal/Task.hpp"

namespace Kit {

//! What one cooperative task's slices cost
struct SliceRecord {
    Os::TaskInterface::taskRoutine routine;
    void* argument;               //!< the routine's own argument (F´'s task wrapper, inside the component)
    FwTaskPriorityType priority;  //!< F´'s: higher is more urgent (app/Top/Tables.fpp)
    U32 slices;
    U64 cycles;
    U32 maxCycles;
    bool watched;  //!< its component's dispatch is broken into stages (app/Components/Timing/DispatchStages.hpp)
};

class TimedTask final : public Os::Baremetal::BaremetalTask {
  public:
    //! The kit's table of timed tasks (the TaskRunner's own holds 100): the
    //! topology's active instances must fit (baremetal/ModelChecks.cpp)
    static constexpr FwSizeType MAX_TASKS = CONFIG_KIT_BAREMETAL_TASKS;

    Status start(const Arguments& arguments) override;

    static FwSizeType taskCount();
    static const SliceRecord& record(FwSizeType index);

    //! Run one slice of a task directly (a policy other than the
    //! TaskRunner's pass: baremetal/Os/BudgetedScheduler); returns its cycles
    static U32 runSlice(FwSizeType index);
};

}  // namespace Kit

#endif
