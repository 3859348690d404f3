// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TimedTask.cpp
// ======================================================================
#include "baremetal/Os/TimedTask.hpp"
#include "app/Components/Timing/DispatchStages.hpp"

#include <zephyr/kernel.h>
#include <Fw/Types/Assert.hpp>
#include <Os/Delegate.hpp>

namespace Kit {

namespace {
SliceRecord s_records[TimedTask::MAX_TASKS];
FwSizeType s_count = 0;

U32 timeSlice(SliceRecord& record) {
    if (record.watched) {
        Stages::mark(StageMark::PICKED);  // the TaskRunner reached the watched component's slice
    }
    const U32 begin = k_cycle_get_32();
    record.routine(record.argument);
    const U32 cycles = k_cycle_get_32() - begin;  // modulo 2^32: one wrap is fine
    record.slices++;
    record.cycles += cycles;
    record.maxCycles = cycles > record.maxCycles ? cycles : record.maxCycles;
    return cycles;
}

void timedSlice(void* argument) {
    (void)timeSlice(*static_cast<SliceRecord*>(argument));
}
}  // namespace

Os::TaskInterface::Status TimedTask::start(const Arguments& arguments) {
    FW_ASSERT(s_count < MAX_TASKS, static_cast<FwAssertArgType>(s_count));  // raise MAX_TASKS with the topology
    SliceRecord& record = s_records[s_count];
    record = {arguments.m_routine,
              arguments.m_routine_argument,
              arguments.m_priority,
              0,
              0,
              0,
              Stages::watches(arguments.m_routine_argument)};
    s_count++;
    Arguments timed(arguments);
    timed.m_routine = timedSlice;
    timed.m_routine_argument = &record;
    return BaremetalTask::start(timed);
}

FwSizeType TimedTask::taskCount() {
    return s_count;
}

const SliceRecord& TimedTask::record(FwSizeType index) {
    FW_ASSERT(index < s_count, static_cast<FwAssertArgType>(index));
    return s_records[index];
}

U32 TimedTask::runSlice(FwSizeType index) {
    FW_ASSERT(index < s_count, static_cast<FwAssertArgType>(index));
    return timeSlice(s_records[index]);
}

}  // namespace Kit

namespace Os {

TaskInterface* TaskInterface::getDelegate(TaskHandleStorage& aligned_new_memory) {
    return Os::Delegate::makeDelegate<TaskInterface, Kit::TimedTask>(aligned_new_memory);
}

}  // namespace Os
