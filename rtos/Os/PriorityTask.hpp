// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  PriorityTask.hpp
// \brief  fprime-zephyr's task with the kit's priority mapping
// ======================================================================
#ifndef KIT_PRIORITYTASK_HPP
#define KIT_PRIORITYTASK_HPP

#include "fprime-zephyr/Os/Task.hpp"

namespace Kit {

class PriorityTask final : public Os::Zephyr::Task::ZephyrTask {
  public:
    //! Start with the F´ priority mapped onto Zephyr's (asserts if it cannot
    //! be), or on the shared thread where its level is one it hosts
    Status start(const Arguments& arguments) override;
};

}  // namespace Kit

#endif
