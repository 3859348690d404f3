// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  PriorityTask.cpp
// \brief  fprime-zephyr's task with the kit's priority mapping
// ======================================================================
#include "rtos/Os/PriorityTask.hpp"
#include "rtos/Os/PriorityMap.hpp"
#include "rtos/Os/SharedThread.hpp"

#include <zephyr/kernel.h>
#include <Fw/Types/Assert.hpp>
#include <Os/Delegate.hpp>

namespace Kit {

Os::TaskInterface::Status PriorityTask::start(const Arguments& arguments) {
    if (SharedThread::hosts(arguments.m_priority) && SharedThread::running()) {
        return SharedThread::join(arguments);  // no thread of its own
    }
    const int mapped = zephyrPriority(arguments.m_priority, CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY);
    // A priority outside the table is a topology error, not something to clamp
    FW_ASSERT(mapped >= 0, static_cast<FwAssertArgType>(arguments.m_priority));
    Arguments zephyrArguments(arguments);
    zephyrArguments.m_priority = static_cast<FwTaskPriorityType>(mapped);
    return ZephyrTask::start(zephyrArguments);
}

}  // namespace Kit

namespace Os {

TaskInterface* TaskInterface::getDelegate(TaskHandleStorage& aligned_new_memory) {
    return Os::Delegate::makeDelegate<TaskInterface, Kit::PriorityTask>(aligned_new_memory);
}

}  // namespace Os
