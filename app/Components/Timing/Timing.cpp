// ======================================================================
// \title  Timing.cpp
// \brief  Tick source and rate-group timing probe
//
// Probe handlers run inside the rate group's own context (a thread on the RTOS
// variant, a TaskRunner slice on the baremetal one), at the first and last
// member position, so they time exactly what the rate group runs. They only
// record; nothing prints while sampling.
// ======================================================================
#include "app/Components/Timing/Timing.hpp"
#include "app/Components/Timing/TickClock.hpp"

namespace Kit {

Timing::Timing(const char* const compName)
    : TimingComponentBase(compName), m_records(), m_count(0), m_ticksDriven(0) {}

Timing::~Timing() {}

void Timing::configure(const RateGroupSpec* specs, FwIndexType count) {
    FW_ASSERT(specs != nullptr);
    FW_ASSERT(count > 0 && count <= MAX_RATE_GROUPS, static_cast<FwAssertArgType>(count));
    for (FwIndexType i = 0; i < count; i++) {
        FW_ASSERT(specs[i].divisor > 0, static_cast<FwAssertArgType>(i));
        FW_ASSERT(specs[i].offset < specs[i].divisor, static_cast<FwAssertArgType>(i));
        m_records[i] = RateGroupRecord();
        m_records[i].spec = specs[i];
    }
    m_count = count;
}

void Timing::tick() {
    FW_ASSERT(m_count > 0);  // configure() first
    m_ticksDriven++;
    (void)m_rawTime.now();
    this->CycleOut_out(0, m_rawTime);
}

const RateGroupRecord& Timing::record(FwIndexType rateGroup) const {
    FW_ASSERT(rateGroup >= 0 && rateGroup < m_count, static_cast<FwAssertArgType>(rateGroup));
    return m_records[rateGroup];
}

U32 Timing::totalSlips() const {
    U32 slips = 0;
    for (FwIndexType i = 0; i < m_count; i++) {
        slips += m_records[i].slips;
    }
    return slips;
}

U32 Timing::releaseTick(const RateGroupRecord& rg) const {
    // Svc::RateGroupDriver fires a group on ticks where tick % divisor == offset
    return rg.spec.offset + rg.cycles * rg.spec.divisor;
}

void Timing::cycleStart_handler(FwIndexType portNum, U32 context) {
    (void)context;
    FW_ASSERT(portNum >= 0 && portNum < m_count, static_cast<FwAssertArgType>(portNum));
    RateGroupRecord& rg = m_records[portNum];
    FW_ASSERT(!rg.running, static_cast<FwAssertArgType>(portNum));  // start/end must pair up
    const U32 now = TickClock::now();
    const U32 release = this->releaseTick(rg);
    const U32 fired = TickClock::ticksFired();

    if (static_cast<U32>(fired - release) <= TickClock::STAMP_HISTORY) {
        rg.latency.add(elapsedCycles(TickClock::stampOf(release), now));
    } else {
        rg.lostStamps++;
    }
    if (pastDeadline(fired, release, rg.spec.divisor)) {
        rg.lateStarts++;
    }
    if (rg.cycles > 0) {
        rg.period.add(elapsedCycles(rg.lastStart, now));
    }
    rg.lastStart = now;
    rg.running = true;
}

void Timing::cycleEnd_handler(FwIndexType portNum, U32 context) {
    (void)context;
    FW_ASSERT(portNum >= 0 && portNum < m_count, static_cast<FwAssertArgType>(portNum));
    RateGroupRecord& rg = m_records[portNum];
    FW_ASSERT(rg.running, static_cast<FwAssertArgType>(portNum));
    const U32 now = TickClock::now();
    const U32 release = this->releaseTick(rg);
    const U32 fired = TickClock::ticksFired();
    rg.exec.add(elapsedCycles(rg.lastStart, now));
    rg.running = false;

    const U32 late = ticksLate(fired, release, rg.spec.divisor);
    if (late > 0) {
        rg.slips++;
        this->log_WARNING_HI_RateGroupSlip(static_cast<U8>(portNum), rg.cycles, late);
        this->tlmWrite_Slips(this->totalSlips());
    }
    rg.cycles++;
    // Telemetry at 10 Hz of the fast group: enough for an operator, and it keeps
    // the probe's own cost out of the 1 kHz budget.
    if (portNum == 0 && (rg.cycles % TLM_DECIMATION) == 0) {
        this->tlmWrite_FastCycles(rg.cycles);
        this->tlmWrite_FastMaxLatency(rg.latency.max());
    }
}

}  // namespace Kit
