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
// ======================================================================
#include "rtos/ThreadStacks.hpp"
#include "Top/ActiveStacks.hpp"

#include <zephyr/kernel.h>

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

constexpr FwSizeType heapSize() {
    FwSizeType bytes = HEAP_BYTES;
    for (FwSizeType i = 0; i < ACTIVE_STACK_ENTRIES; i++) {
        bytes += K_KERNEL_STACK_LEN(ACTIVE_STACKS[i]) + PER_STACK_BYTES;
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
}

}  // namespace ThreadStacks
}  // namespace Kit
