// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  HeapMonitor.cpp
// ======================================================================
#include "app/src/HeapMonitor.hpp"

#include <cstddef>

extern "C" {
void* __real_malloc(size_t size);
void* __real_calloc(size_t count, size_t size);
void* __real_realloc(void* ptr, size_t size);
void* __real_aligned_alloc(size_t alignment, size_t size);
void* __real_memalign(size_t alignment, size_t size);
void __real_free(void* ptr);
}

namespace Kit {
namespace HeapMonitor {

namespace {
// Written by every allocating context; the RTOS variant allocates only during
// single-threaded start-up, so plain counters suffice (after_init proves it).
U32 s_bytes = 0;
U32 s_allocations = 0;
U32 s_frees = 0;
U32 s_failures = 0;
U32 s_afterInit = 0;
bool s_initialized = false;
}  // namespace

void* counted(void* block, size_t size) {
    if (block == nullptr) {
        s_failures++;
        return nullptr;
    }
    s_bytes += static_cast<U32>(size);
    s_allocations++;
    s_afterInit += s_initialized ? 1u : 0u;
    return block;
}

void countFree(void* block) {
    s_frees += (block != nullptr) ? 1u : 0u;
}

U32 bytesRequested() {
    return s_bytes;
}
U32 allocations() {
    return s_allocations;
}
U32 frees() {
    return s_frees;
}
U32 failures() {
    return s_failures;
}
U32 allocationsAfterInit() {
    return s_afterInit;
}
void markInitialized() {
    s_initialized = true;
}

U32 arenaLeft() {
    // Halving between what fits and what does not: log2(arena) probes at
    // most. Zephyr's heap merges a freed block back into its neighbour, so
    // every probe sees the same free space.
    size_t fits = 0;
    size_t tooBig = static_cast<size_t>(CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE) + 1u;
    while (tooBig - fits > 1u) {
        const size_t size = fits + (tooBig - fits) / 2u;
        void* const block = __real_malloc(size);
        if (block != nullptr) {
            __real_free(block);
            fits = size;
        } else {
            tooBig = size;
        }
    }
    return static_cast<U32>(fits);
}

}  // namespace HeapMonitor
}  // namespace Kit

extern "C" {
void* __wrap_malloc(size_t size) {
    return Kit::HeapMonitor::counted(__real_malloc(size), size);
}
void* __wrap_calloc(size_t count, size_t size) {
    return Kit::HeapMonitor::counted(__real_calloc(count, size), count * size);
}
void* __wrap_realloc(void* ptr, size_t size) {
    return Kit::HeapMonitor::counted(__real_realloc(ptr, size), size);
}
void* __wrap_aligned_alloc(size_t alignment, size_t size) {
    return Kit::HeapMonitor::counted(__real_aligned_alloc(alignment, size), size);
}
void* __wrap_memalign(size_t alignment, size_t size) {
    return Kit::HeapMonitor::counted(__real_memalign(alignment, size), size);
}
void __wrap_free(void* ptr) {
    Kit::HeapMonitor::countFree(ptr);
    __real_free(ptr);
}
}
