// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Housekeeping.hpp
// \brief  10 Hz configuration-table scrub
// ======================================================================
#ifndef KIT_HOUSEKEEPING_HPP
#define KIT_HOUSEKEEPING_HPP

#include "app/Components/Housekeeping/HousekeepingComponentAc.hpp"

namespace Kit {

class Housekeeping final : public HousekeepingComponentBase {
  public:
    static constexpr FwSizeType TABLE_SIZE = 1024;
    static constexpr FwSizeType SLICE_SIZE = 256;  //!< bytes scrubbed per cycle

    explicit Housekeeping(const char* const compName);
    ~Housekeeping();

    //! The table under scrub; tests (and fault injection) may alter it
    U8* table() { return m_table; }
    U32 passes() const { return m_passes; }

    //! CRC-32 (IEEE, reflected) continued over `size` bytes
    static U32 crc32(U32 crc, const U8* data, FwSizeType size);

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;

    U8 m_table[TABLE_SIZE];
    U32 m_golden;
    U32 m_running;
    FwSizeType m_offset;
    U32 m_passes;
    U32 m_cycles;
};

}  // namespace Kit

#endif
