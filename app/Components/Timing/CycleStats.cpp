// ======================================================================
// \title  CycleStats.cpp
// ======================================================================
#include "app/Components/Timing/CycleStats.hpp"

namespace Kit {

void CycleStats::add(U32 value) {
    m_count++;
    m_sum += value;
    if (value < m_min) {
        m_min = value;
    }
    if (value > m_max) {
        m_max = value;
    }
}

void CycleStats::reset() {
    *this = CycleStats();
}

U32 CycleStats::mean() const {
    return m_count == 0 ? 0 : static_cast<U32>(m_sum / m_count);
}

}  // namespace Kit
