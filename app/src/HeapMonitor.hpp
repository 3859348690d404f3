// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  HeapMonitor.hpp
// \brief  Every use of the C heap (the malloc arena), whoever the caller
//
// The link wraps the C allocation functions (-Wl,--wrap=..., app/kit.cmake),
// so F´'s allocator, libstdc++ and Zephyr's libc users are all counted. The
// kit frees nothing after start-up, so with frees() == 0 the bytes requested
// are the heap's peak use (chunk headers not included).
// ======================================================================
#ifndef KIT_HEAPMONITOR_HPP
#define KIT_HEAPMONITOR_HPP

#include <Fw/FPrimeBasicTypes.hpp>
#include <cstddef>

namespace Kit {
namespace HeapMonitor {

U32 bytesRequested();
U32 allocations();
U32 frees();
U32 failures();
//! Allocations made after markInitialized(): the kit requires none
U32 allocationsAfterInit();
void markInitialized();
//! The largest block the arena can still give (bytes): what it has left
//! after start-up, chunk headers and alignment included. The arena
//! (CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE) less this is what the run used of
//! it: the figure a board's tight arena is sized from. Probes the heap with
//! uncounted allocations, each freed at once.
U32 arenaLeft();

//! For the link-time wrappers only
void* counted(void* block, size_t size);
void countFree(void* block);

}  // namespace HeapMonitor
}  // namespace Kit

#endif
