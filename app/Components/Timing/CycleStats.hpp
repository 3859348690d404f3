// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CycleStats.hpp
// \brief  Running statistics of one timing metric, in board counter cycles
//
// Plain C++ with no OS or F´ component dependency, so the arithmetic (and the
// 32-bit counter wrap handling) is unit-tested on the host.
// ======================================================================
#ifndef KIT_CYCLESTATS_HPP
#define KIT_CYCLESTATS_HPP

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {

//! Elapsed counter cycles from `from` to `to` on a free-running 32-bit counter.
//! Correct across one wrap (the counter wraps every 2^32 cycles, 358 s at 12 MHz).
inline U32 elapsedCycles(U32 from, U32 to) {
    return static_cast<U32>(to - from);
}

//! Fixed-bucket, log-linear histogram of cycle counts. Every power of two is
//! split into SUB buckets (values below 2 * SUB have a bucket each), so a
//! bucket is at most 1/SUB wide relative to its values; values from about
//! 2^18 cycles (21.8 ms at 12 MHz) up share the last bucket. Fixed RAM
//! whatever the run length (512 B at the kit's 8 buckets per power of two,
//! 272 B at 4): percentiles without storing samples.
class Histogram {
  public:
#if defined(CONFIG_KIT_TIMING_SUB_BITS)
    static constexpr U32 SUB_BITS = CONFIG_KIT_TIMING_SUB_BITS;  // app/Kconfig
#else
    static constexpr U32 SUB_BITS = 3;  // the kit's default, where there is no Kconfig (host unit tests)
#endif
    static constexpr U32 SUB = 1u << SUB_BITS;  //!< buckets per power of two
    static constexpr U32 TOP_BITS = 18;         //!< the last bucket starts below 2^TOP_BITS
    static constexpr U32 BUCKETS = SUB * (TOP_BITS - SUB_BITS + 1);
    static constexpr U32 LAST = BUCKETS - 1;  //!< also holds everything beyond its lower bound
    static_assert(SUB_BITS >= 1 && SUB_BITS < TOP_BITS, "SUB_BITS out of range");

    //! Bucket of a value
    static U32 bucketOf(U32 value);
    //! Smallest value in bucket `bucket`
    static U32 lowerBound(U32 bucket);
    //! Largest value in bucket `bucket` (0xFFFFFFFF for the last)
    static U32 upperBound(U32 bucket);

    void add(U32 value);
    void reset();
    U32 total() const { return m_total; }
    U32 count(U32 bucket) const;
    //! Upper bound of the bucket holding the sample of rank ceil(permille/1000 * total);
    //! 0 when empty. Never below the true percentile, at most one bucket above.
    U32 percentileBound(U32 permille) const;

  private:
    U32 m_counts[BUCKETS] = {};
    U32 m_total = 0;
};

//! Count, min, max, sum and distribution of a metric.
class CycleStats {
  public:
    void add(U32 value);
    void reset();
    U32 count() const { return m_count; }
    U32 min() const { return m_count == 0 ? 0 : m_min; }
    U32 max() const { return m_max; }
    //! Mean, rounded down; 0 when empty
    U32 mean() const;
    U64 sum() const { return m_sum; }
    //! Percentile from the histogram, clamped to the exact [min, max]
    U32 percentile(U32 permille) const;
    const Histogram& histogram() const { return m_histogram; }

  private:
    U32 m_count = 0;
    U32 m_min = 0xFFFFFFFFu;
    U32 m_max = 0;
    U64 m_sum = 0;
    Histogram m_histogram;
};

//! FNV-1a over 32-bit samples, in recording order: two runs that recorded the
//! same samples give the same hash.
class SampleHash {
  public:
    void add(U32 sample);
    U32 value() const { return m_hash; }
    U32 samples() const { return m_samples; }

  private:
    U32 m_hash = 2166136261u;
    U32 m_samples = 0;
};

//! True when a cycle released at tick `releaseTick` of a rate group with the
//! given divisor is still running (or only starting) after the tick that
//! releases its next cycle. `ticksFired` counts the ticks fired so far, so tick
//! index t has fired once ticksFired > t. All in modulo-2^32 tick arithmetic.
inline bool pastDeadline(U32 ticksFired, U32 releaseTick, U32 divisor) {
    return static_cast<U32>(ticksFired - releaseTick) > divisor;
}

//! Ticks by which a cycle released at `releaseTick` overran its deadline (0 if none).
inline U32 ticksLate(U32 ticksFired, U32 releaseTick, U32 divisor) {
    const U32 sinceRelease = static_cast<U32>(ticksFired - releaseTick);
    return sinceRelease > divisor ? sinceRelease - divisor : 0;
}

}  // namespace Kit

#endif
