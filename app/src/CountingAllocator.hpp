// ======================================================================
// \title  CountingAllocator.hpp
// \brief  F´'s memory allocator for the kit: malloc, counted
//
// Registered for every F´ allocation (queues included) before the topology
// is set up. It reports the peak of F´'s heap use and how many allocations
// happened after initialization, which the kit requires to be none.
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
    //! From now on, an allocation counts as after initialization
    void endInitialization() { m_initialized = true; }

    FwSizeType peakBytes() const { return m_peak; }
    FwSizeType currentBytes() const { return m_current; }
    U32 allocations() const { return m_allocations; }
    U32 allocationsAfterInit() const { return m_afterInit; }
    U32 failures() const { return m_failures; }

  private:
    FwSizeType m_current = 0;
    FwSizeType m_peak = 0;
    U32 m_allocations = 0;
    U32 m_afterInit = 0;
    U32 m_failures = 0;
    bool m_initialized = false;
};

}  // namespace Kit

#endif
