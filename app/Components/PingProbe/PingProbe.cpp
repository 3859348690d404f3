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

PingProbe* PingProbe::s_deferring[PingProbe::MAX_DEFERRED] = {};
U32 PingProbe::s_deferredCount = 0;

PingProbe::PingProbe(const char* const compName)
    : PingProbeComponentBase(compName),
      m_targetQueue(nullptr),
      m_deferred(false),
      m_deferredKey(0),
      m_deferredPings(0),
      m_sentAt(0),
      m_outstanding(false),
      m_trips(),
      m_segmentMax(0) {}

PingProbe::~PingProbe() {
    for (U32 index = 0; index < s_deferredCount; index++) {
        if (s_deferring[index] == this) {
            s_deferredCount--;
            s_deferring[index] = s_deferring[s_deferredCount];
            s_deferring[s_deferredCount] = nullptr;
            break;
        }
    }
}

void PingProbe::watchQueue(const Os::Queue& queue) {
    m_targetQueue = &queue;
}

bool PingProbe::targetFull() const {
    return (m_targetQueue != nullptr) && (m_targetQueue->getMessagesAvailable() >= m_targetQueue->getDepth());
}

void PingProbe::sendDeferredPings() {
    U32 index = 0;
    while (index < s_deferredCount) {  // bounded: each turn moves on or shrinks the list
        PingProbe* const probe = s_deferring[index];
        FW_ASSERT(probe != nullptr && probe->m_deferred);
        if (probe->targetFull()) {
            index++;
            continue;
        }
        s_deferredCount--;
        s_deferring[index] = s_deferring[s_deferredCount];
        s_deferring[s_deferredCount] = nullptr;
        probe->m_deferred = false;
        probe->pingOut_out(0, probe->m_deferredKey);
    }
}

void PingProbe::pingIn_handler(FwIndexType portNum, U32 key) {
    sendDeferredPings();
    m_sentAt = TickClock::now();
    m_outstanding = true;
    if (m_deferred) {
        // Health pings an entry again only once its answer is in, or after
        // a restart of the deployment: the newer key replaces the old
        m_deferredKey = key;
        return;
    }
    if (targetFull()) {
        FW_ASSERT(s_deferredCount < MAX_DEFERRED, static_cast<FwAssertArgType>(s_deferredCount));
        s_deferring[s_deferredCount] = this;
        s_deferredCount++;
        m_deferred = true;
        m_deferredKey = key;
        m_deferredPings++;
        return;
    }
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
