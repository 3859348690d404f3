// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CountingAllocator.hpp
// \brief  F´'s memory allocator for the kit: malloc, counted
//
// Registered for every F´ allocation (queues included) before the topology
// is set up, it reports the peak of F´'s own heap use. (Every heap user,
// F´ included, is counted by HeapMonitor.)
// ======================================================================
#ifndef KIT_COUNTINGALLOCATOR_HPP
#define KIT_COUNTINGALLOCATOR_HPP

#include <Fw/Types/MemAllocator.hpp>

namespace Kit {

class CountingAllocator final : public Fw::MemAllocator {
  public:
    void* allocate(const FwEnumStoreType identifier,
                   FwSizeType& size,
                   bool& recoverable,
                   FwSizeType alignment = alignof(std::max_align_t)) override;
    void deallocate(const FwEnumStoreType identifier, void* ptr) override;

    //! Register for all of F´'s allocator types
    void registerForFprime();
    FwSizeType peakBytes() const { return m_peak; }
    FwSizeType currentBytes() const { return m_current; }
    U32 allocations() const { return m_allocations; }

  private:
    FwSizeType m_current = 0;
    FwSizeType m_peak = 0;
    U32 m_allocations = 0;
};

}  // namespace Kit

#endif
