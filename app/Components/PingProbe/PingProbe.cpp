// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  PingProbe.cpp
// \brief  Svc.Health's pings, timed per entry
// ======================================================================
#include "app/Components/PingProbe/PingProbe.hpp"
#include <Fw/Types/Assert.hpp>
#include "app/Components/Timing/CycleStats.hpp"
#include "app/Components/Timing/TickClock.hpp"

namespace Kit {

void PingRoundTrips::add(U32 cycles) {
    m_window[m_count % WINDOW] = cycles;
    m_count++;
    if (cycles > m_max) {
        m_max = cycles;
    }
}

U32 PingRoundTrips::percentile(U32 permille) const {
    FW_ASSERT(permille <= 1000, static_cast<FwAssertArgType>(permille));
    const U32 n = held();
    if (n == 0) {
        return 0;
    }
    // Nearest rank over a sorted copy (at most WINDOW values: an insertion sort)
    U32 sorted[WINDOW];
    for (U32 i = 0; i < n; i++) {
        U32 j = i;
        for (; j > 0 && sorted[j - 1] > m_window[i]; j--) {
            sorted[j] = sorted[j - 1];
        }
        sorted[j] = m_window[i];
    }
    const U32 rank = (permille * n + 999) / 1000;  // ceil, 1-based
    return sorted[(rank == 0 ? 1 : rank) - 1];
}

PingProbe::PingProbe(const char* const compName)
    : PingProbeComponentBase(compName), m_sentAt(0), m_outstanding(false), m_trips(), m_segmentMax(0) {}

PingProbe::~PingProbe() {}

void PingProbe::pingIn_handler(FwIndexType portNum, U32 key) {
    m_sentAt = TickClock::now();
    m_outstanding = true;
    this->pingOut_out(portNum, key);
}

void PingProbe::returnIn_handler(FwIndexType portNum, U32 key) {
    // An answer with no ping out is health's to judge (a wrong key is its
    // FATAL); it is passed on, not timed
    if (m_outstanding) {
        const U32 trip = elapsedCycles(m_sentAt, TickClock::now());
        m_trips.add(trip);
        m_segmentMax = (trip > m_segmentMax) ? trip : m_segmentMax;
        m_outstanding = false;
    }
    this->returnOut_out(portNum, key);
}

void PingProbe::startSegment() {
    m_segmentMax = 0;
}

U32 PingProbe::segmentWorst(U32 now) const {
    // A ping still out may never be answered: its wait so far counts
    const U32 waiting = m_outstanding ? elapsedCycles(m_sentAt, now) : 0;
    return (waiting > m_segmentMax) ? waiting : m_segmentMax;
}

}  // namespace Kit
