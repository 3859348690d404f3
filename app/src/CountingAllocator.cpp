// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CountingAllocator.cpp
// ======================================================================
#include "app/src/CountingAllocator.hpp"
#include <Fw/Types/Assert.hpp>

#include <zephyr/sys/printk.h>
#include <cstdlib>

namespace Kit {

namespace {
// Each block carries its size in front, so deallocate knows what it frees;
// the header keeps malloc's alignment for the caller.
constexpr FwSizeType HEADER = alignof(std::max_align_t);
}  // namespace

void* CountingAllocator::allocate(const FwEnumStoreType identifier,
                                  FwSizeType& size,
                                  bool& recoverable,
                                  FwSizeType alignment) {
    (void)identifier;
    FW_ASSERT(alignment <= HEADER, static_cast<FwAssertArgType>(alignment));
    recoverable = false;
    U8* const block = static_cast<U8*>(std::malloc(size + HEADER));
    if (block == nullptr) {
        // The caller asserts on it at start-up; this line says why first. The
        // arena is sized per board and model from a run's KIT HEAP arena_left
        printk("KIT ARENA exhausted request=%u arena=%u (raise CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE)\n",
               static_cast<unsigned>(size), static_cast<unsigned>(CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE));
        size = 0;  // HeapMonitor counts the failure
        return nullptr;
    }
    *reinterpret_cast<FwSizeType*>(block) = size;
    m_current += size;
    m_peak = m_current > m_peak ? m_current : m_peak;
    m_allocations++;
    return block + HEADER;
}

void CountingAllocator::deallocate(const FwEnumStoreType identifier, void* ptr) {
    (void)identifier;
    if (ptr == nullptr) {
        return;
    }
    U8* const block = static_cast<U8*>(ptr) - HEADER;
    const FwSizeType size = *reinterpret_cast<FwSizeType*>(block);
    FW_ASSERT(size <= m_current, static_cast<FwAssertArgType>(size));
    m_current -= size;
    std::free(block);
}

void CountingAllocator::registerForFprime() {
    Fw::MemAllocatorRegistry& registry = Fw::MemAllocatorRegistry::getInstance();
    registry.registerAllocator(Fw::MemoryAllocation::MemoryAllocatorType::SYSTEM, *this);
    registry.registerAllocator(Fw::MemoryAllocation::MemoryAllocatorType::OS_GENERIC_PRIORITY_QUEUE, *this);
}

}  // namespace Kit
