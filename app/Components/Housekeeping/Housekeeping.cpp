// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Housekeeping.cpp
// \brief  10 Hz configuration-table scrub
// ======================================================================
#include "app/Components/Housekeeping/Housekeeping.hpp"

namespace Kit {

namespace {
constexpr U32 CRC_INIT = 0xFFFFFFFFu;
}

Housekeeping::Housekeeping(const char* const compName)
    : HousekeepingComponentBase(compName),
      m_table(),
      m_golden(0),
      m_running(CRC_INIT),
      m_offset(0),
      m_passes(0),
      m_cycles(0) {
    // A deterministic "configuration" pattern; its CRC is the reference
    for (FwSizeType i = 0; i < TABLE_SIZE; i++) {
        m_table[i] = static_cast<U8>((i * 31u + 7u) & 0xFFu);
    }
    m_golden = crc32(CRC_INIT, m_table, TABLE_SIZE);
}

Housekeeping::~Housekeeping() {}

U32 Housekeeping::crc32(U32 crc, const U8* data, FwSizeType size) {
    FW_ASSERT(data != nullptr);
    for (FwSizeType i = 0; i < size; i++) {
        crc ^= data[i];
        for (U32 bit = 0; bit < 8; bit++) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return crc;
}

void Housekeeping::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    static_assert(TABLE_SIZE % SLICE_SIZE == 0, "slices must tile the table");
    m_running = crc32(m_running, &m_table[m_offset], SLICE_SIZE);
    m_offset += SLICE_SIZE;
    if (m_offset == TABLE_SIZE) {
        if (m_running != m_golden) {
            this->log_WARNING_HI_ScrubMismatch(m_golden, m_running);
        }
        m_passes++;
        m_offset = 0;
        m_running = CRC_INIT;
        this->tlmWrite_ScrubPasses(m_passes);
    }
    m_cycles++;
    this->tlmWrite_Cycles(m_cycles);
}

}  // namespace Kit
