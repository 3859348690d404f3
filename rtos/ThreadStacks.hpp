// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/ThreadStacks.hpp
// \brief  Every F´ thread's stack, at its own size from the stack table
// ======================================================================
#ifndef KIT_THREADSTACKS_HPP
#define KIT_THREADSTACKS_HPP

namespace Kit {
namespace ThreadStacks {

//! Before the topology starts its tasks, from the thread that starts them:
//! the stacks fprime-zephyr asks for (k_thread_stack_alloc, one per active
//! component, at the table's size) come from a heap sized for exactly
//! those stacks; and the shared thread, where the build has one
//! (rtos/Os/SharedThread.hpp), on a stack of its own
void provide();

}  // namespace ThreadStacks
}  // namespace Kit

#endif
