// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CycleStats.cpp
// ======================================================================
#include "app/Components/Timing/CycleStats.hpp"
#include <Fw/Types/Assert.hpp>

namespace Kit {

U32 Histogram::bucketOf(U32 value) {
    if (value < 2 * SUB) {
        return value;
    }
    U32 msb = 31;
    while ((value >> msb) == 0) {  // bounded: value != 0 here
        msb--;
    }
    const U32 shift = msb - SUB_BITS;
    const U32 bucket = shift * SUB + (value >> shift);
    return bucket > LAST ? LAST : bucket;
}

U32 Histogram::lowerBound(U32 bucket) {
    FW_ASSERT(bucket < BUCKETS, static_cast<FwAssertArgType>(bucket));
    if (bucket < 2 * SUB) {
        return bucket;
    }
    const U32 shift = bucket / SUB - 1;
    return (bucket - shift * SUB) << shift;
}

U32 Histogram::upperBound(U32 bucket) {
    FW_ASSERT(bucket < BUCKETS, static_cast<FwAssertArgType>(bucket));
    return bucket == LAST ? 0xFFFFFFFFu : lowerBound(bucket + 1) - 1;
}

void Histogram::add(U32 value) {
    m_counts[bucketOf(value)]++;
    m_total++;
}

void Histogram::reset() {
    // In place: a temporary would put the whole table on the caller's stack
    for (U32& count : m_counts) {
        count = 0;
    }
    m_total = 0;
}

U32 Histogram::count(U32 bucket) const {
    FW_ASSERT(bucket < BUCKETS, static_cast<FwAssertArgType>(bucket));
    return m_counts[bucket];
}

U32 Histogram::percentileBound(U32 permille) const {
    FW_ASSERT(permille <= 1000, static_cast<FwAssertArgType>(permille));
    if (m_total == 0) {
        return 0;
    }
    // Rank of the sample, 1-based: ceil(total * permille / 1000), at least 1
    U64 rank = (static_cast<U64>(m_total) * permille + 999) / 1000;
    rank = rank == 0 ? 1 : rank;
    U64 seen = 0;
    for (U32 bucket = 0; bucket < BUCKETS; bucket++) {
        seen += m_counts[bucket];
        if (seen >= rank) {
            return upperBound(bucket);
        }
    }
    return upperBound(LAST);
}

void SampleHash::add(U32 sample) {
    for (U32 byte = 0; byte < 4; byte++) {
        m_hash ^= (sample >> (8 * byte)) & 0xFFu;
        m_hash *= 16777619u;
    }
    m_samples++;
}

void CycleStats::add(U32 value) {
    m_histogram.add(value);
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
    m_count = 0;
    m_min = 0xFFFFFFFFu;
    m_max = 0;
    m_sum = 0;
    m_histogram.reset();
}

U32 CycleStats::percentile(U32 permille) const {
    if (m_count == 0) {
        return 0;
    }
    const U32 bound = m_histogram.percentileBound(permille);
    return bound < m_min ? m_min : (bound > m_max ? m_max : bound);
}

U32 CycleStats::mean() const {
    return m_count == 0 ? 0 : static_cast<U32>(m_sum / m_count);
}

}  // namespace Kit
