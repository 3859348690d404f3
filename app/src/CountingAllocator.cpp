// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CountingAllocator.cpp
// ======================================================================
#include "app/src/CountingAllocator.hpp"
#include <Fw/Types/Assert.hpp>

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
