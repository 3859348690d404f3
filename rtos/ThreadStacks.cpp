// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/ThreadStacks.cpp
// \brief  Every F´ thread's stack, at its own size from the stack table
//
// fprime-zephyr starts each active component with k_thread_stack_alloc(its
// stack size from the table). Zephyr's thread pool would give every thread
// one slot size, the largest stack's (2048 B): the kit's stacks run from
// 1152 B to 2048 B (app/Top/Tables.fpp), and on qemu_cortex_m3 the uniform
// slot cost 3448 B of its 64 KiB (rtos static RAM 64252 B, 60804 B without
// the pool). So the stacks come from Zephyr's other allocator
// (CONFIG_DYNAMIC_THREAD_ALLOC, rtos/Kconfig.model): the resource pool of
// the thread that starts them, here a heap of this file's own, sized at
// build time from the deployment's stack table (Top/ActiveStacks.hpp) and
// used once, at start-up, never freed. A stack the heap cannot give fails
// the component's start, and F´ asserts on it (ERROR_RESOURCES): never a
// thread with a smaller stack.
//
// Where the build shares one thread among a band of levels
// (rtos/Os/SharedThread.hpp), the band's tasks ask for no stack: the heap
// holds the shared thread's instead, the largest of theirs in the table
// (one member runs at a time, to the end of its message, so the deepest
// of them is the thread's deepest).
// ======================================================================
#include "rtos/ThreadStacks.hpp"
#include "Top/ActiveStacks.hpp"
#include "rtos/Os/SharedThread.hpp"

#include <zephyr/kernel.h>
#include <Fw/Types/Assert.hpp>

namespace Kit {
namespace ThreadStacks {

namespace {

// What Zephyr's heap takes around each stack (lib/heap/heap.c,
// kernel/mempool.c): its chunk header and the heap reference
// z_thread_aligned_alloc keeps below the block (4 B each on a heap this
// small), the rounding of the block to the 8 B chunk unit, and up to the
// stack's alignment lost in front of it (8 B, or the MPU guard's 32 B)
constexpr FwSizeType PER_STACK_BYTES = 16 + Z_KERNEL_STACK_OBJ_ALIGN;
// Once per heap: its own header and free-list buckets (chunk 0), the end
// marker, and the slack an aligned allocation searches with before it
// trims (the last stack's alignment)
constexpr FwSizeType HEAP_BYTES = 128 + Z_KERNEL_STACK_OBJ_ALIGN;

// The band shares a thread where the deployment lists its tasks' levels
// beside their stacks (ACTIVE_PRIORITIES: the kit's deployment does); one
// that does not keeps a thread for each task, as fprime-zephyr makes them
#if defined(KIT_ACTIVE_PRIORITIES)
constexpr bool SHARING = SharedThread::enabled();
constexpr bool shared(FwSizeType index) {
    return SharedThread::hosts(ACTIVE_PRIORITIES[index]);
}
#else
constexpr bool SHARING = false;
constexpr bool shared(FwSizeType) {
    return false;
}
#endif

//! The shared thread's stack: its members' largest (0: no member)
constexpr FwSizeType sharedStackSize() {
    FwSizeType largest = 0;
    for (FwSizeType i = 0; i < ACTIVE_STACK_ENTRIES; i++) {
        largest = (shared(i) && ACTIVE_STACKS[i] > largest) ? ACTIVE_STACKS[i] : largest;
    }
    return largest;
}
static_assert(!SHARING || sharedStackSize() > 0,
              "CONFIG_KIT_RTOS_SHARED_LEVEL_LOW/HIGH: no active instance of the table has a level in the band");

//! Every thread's stack but the shared band's, and the shared thread's
constexpr FwSizeType heapSize() {
    FwSizeType bytes = HEAP_BYTES;
    for (FwSizeType i = 0; i < ACTIVE_STACK_ENTRIES; i++) {
        bytes += shared(i) ? 0 : K_KERNEL_STACK_LEN(ACTIVE_STACKS[i]) + PER_STACK_BYTES;
    }
    if (SHARING) {
        bytes += K_KERNEL_STACK_LEN(sharedStackSize()) + PER_STACK_BYTES;
    }
    return bytes;
}

alignas(Z_KERNEL_STACK_OBJ_ALIGN) U8 s_memory[heapSize()];
struct k_heap s_heap;

}  // namespace

void provide() {
    k_heap_init(&s_heap, s_memory, sizeof(s_memory));
    // The threads this thread starts inherit its pool; they allocate nothing
    // from it (the kit's queues are F´'s, on the C heap)
    k_thread_heap_assign(k_current_get(), &s_heap);
    // The shared thread's stack from the same heap, as the other threads'
    // (the first of them, where the dispatcher's was: what an overflow
    // runs into below it is what it was)
    if (SHARING) {
        k_thread_stack_t* const stack = k_thread_stack_alloc(sharedStackSize(), 0);
        FW_ASSERT(stack != nullptr, static_cast<FwAssertArgType>(sharedStackSize()));
        SharedThread::start(stack, sharedStackSize());
    }
}

}  // namespace ThreadStacks
}  // namespace Kit
