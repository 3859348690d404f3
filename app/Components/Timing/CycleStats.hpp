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

//! Count, min, max and sum of a metric.
class CycleStats {
  public:
    void add(U32 value);
    void reset();
    U32 count() const { return m_count; }
    U32 min() const { return m_count == 0 ? 0 : m_min; }
    U32 max() const { return m_max; }
    //! Mean, rounded down; 0 when empty
    U32 mean() const;

  private:
    U32 m_count = 0;
    U32 m_min = 0xFFFFFFFFu;
    U32 m_max = 0;
    U64 m_sum = 0;
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
