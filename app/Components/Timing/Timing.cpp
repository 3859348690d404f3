// SPDX-License-Identifier: Apache-2.0
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
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"

namespace Kit {

Timing::Timing(const char* const compName)
    : TimingComponentBase(compName),
      m_records(),
      m_count(0),
      m_cyclesPerTick(0),
      m_ticksDriven(0),
      m_segmentState(SEGMENTS_OFF),
      m_hyperperiod(0),
      m_segment() {}

Timing::~Timing() {}

void Timing::configure(const RateGroupSpec* specs, FwIndexType count, U32 cyclesPerTick) {
    FW_ASSERT(specs != nullptr);
    FW_ASSERT(count > 0 && count <= MAX_RATE_GROUPS, static_cast<FwAssertArgType>(count));
    FW_ASSERT(cyclesPerTick > 0);
    m_cyclesPerTick = cyclesPerTick;
    for (FwIndexType i = 0; i < count; i++) {
        FW_ASSERT(specs[i].divisor > 0, static_cast<FwAssertArgType>(i));
        FW_ASSERT(specs[i].offset < specs[i].divisor, static_cast<FwAssertArgType>(i));
        m_records[i].spec = specs[i];
        this->resetRecord(i);
    }
    m_count = count;
}

void Timing::resetRecord(FwIndexType rateGroup) {
    RateGroupRecord& rg = m_records[rateGroup];
    rg.nominalPeriod = rg.spec.divisor * m_cyclesPerTick;
    rg.cycles = 0;
    rg.slips = 0;
    rg.lateStarts = 0;
    rg.lostStamps = 0;
    rg.latency.reset();
    rg.exec.reset();
    rg.periodError.reset();
    rg.periodMin = 0xFFFFFFFFu;
    rg.periodMax = 0;
    rg.lastStart = 0;
    rg.running = false;
}

void Timing::tick() {
    FW_ASSERT(m_count > 0);  // configure() first
    m_ticksDriven++;
    (void)m_rawTime.now();
    this->CycleOut_out(0, m_rawTime);
}

void Timing::restart(U32 hyperperiod) {
    FW_ASSERT(hyperperiod > 0);
    FW_ASSERT((m_ticksDriven % hyperperiod) == 0, static_cast<FwAssertArgType>(m_ticksDriven),
              static_cast<FwAssertArgType>(hyperperiod));
    for (FwIndexType i = 0; i < m_count; i++) {
        FW_ASSERT(!m_records[i].running, static_cast<FwAssertArgType>(i));
        this->resetRecord(i);
    }
    m_ticksDriven = 0;
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

void Timing::recordStart(RateGroupRecord& rg, U32 now, U32 fired, U32 probeCycles) {
    FW_ASSERT(!rg.running);  // start and end must pair up
    const U32 release = this->releaseTick(rg);
    if (static_cast<U32>(fired - release) <= TickClock::STAMP_HISTORY) {
        const U32 raw = elapsedCycles(TickClock::stampOf(release), now);
        const U32 latency = raw > probeCycles ? raw - probeCycles : 0;
        rg.latency.add(latency);
        m_hash.add(latency);
    } else {
        rg.lostStamps++;
    }
    if (pastDeadline(fired, release, rg.spec.divisor)) {
        rg.lateStarts++;
    }
    if (rg.cycles > 0) {
        const U32 period = elapsedCycles(rg.lastStart, now);
        rg.periodMin = period < rg.periodMin ? period : rg.periodMin;
        rg.periodMax = period > rg.periodMax ? period : rg.periodMax;
        rg.periodError.add(period > rg.nominalPeriod ? period - rg.nominalPeriod : rg.nominalPeriod - period);
        m_hash.add(period);
    }
    rg.lastStart = now;
    rg.running = true;
}

U32 Timing::recordEnd(RateGroupRecord& rg, U32 now, U32 fired) {
    FW_ASSERT(rg.running);
    const U32 exec = elapsedCycles(rg.lastStart, now);
    rg.exec.add(exec);
    m_hash.add(exec);
    rg.running = false;
    const U32 late = ticksLate(fired, this->releaseTick(rg), rg.spec.divisor);
    if (late > 0) {
        rg.slips++;
    }
    rg.cycles++;
    return late;
}

U32 Timing::measureProbeCost(U32 pairs) {
    FW_ASSERT(pairs > 0 && m_count > 0);
    FW_ASSERT(m_ticksDriven == 0);  // before the run: the scratch record must not disturb it
    // Cycle 0 of the fastest group, released at tick 0 and never late, over
    // and over; the record and the hash are then put back to their start state.
    RateGroupRecord& rg = m_records[0];
    const U32 begin = TickClock::now();
    for (U32 i = 0; i < pairs; i++) {
        rg.cycles = 0;
        this->recordStart(rg, TickClock::now(), 1);
        (void)this->recordEnd(rg, TickClock::now(), 1);
    }
    const U32 total = elapsedCycles(begin, TickClock::now());
    this->resetRecord(0);
    m_hash = SampleHash();
    return total / pairs;
}

void Timing::cycleStart_handler(FwIndexType portNum, U32 context) {
    (void)context;
    FW_ASSERT(portNum >= 0 && portNum < m_count, static_cast<FwAssertArgType>(portNum));
    const U32 now = TickClock::now();
    // The fastest group's dispatch is broken into stages (DispatchStages.hpp):
    // its first member closes the breakdown, and the marks' cost comes out
    const U32 probeCycles = (portNum == 0) ? Stages::firstMember(now) : 0;
    this->recordStart(m_records[portNum], now, TickClock::ticksFired(), probeCycles);
}

void Timing::cycleEnd_handler(FwIndexType portNum, U32 context) {
    (void)context;
    FW_ASSERT(portNum >= 0 && portNum < m_count, static_cast<FwAssertArgType>(portNum));
    RateGroupRecord& rg = m_records[portNum];
    const U32 late = this->recordEnd(rg, TickClock::now(), TickClock::ticksFired());
    if (late > 0) {
        this->log_WARNING_HI_RateGroupSlip(static_cast<U8>(portNum), rg.cycles - 1, late);
        this->tlmWrite_Slips(this->totalSlips());
    }
    // Telemetry of the fast group at 10 Hz: enough for an operator, and it
    // keeps the probe's own cost out of the fastest group's budget.
    if (portNum == 0 && (rg.cycles % tlmDecimation(rg.spec)) == 0) {
        this->tlmWrite_FastCycles(rg.cycles);
        this->tlmWrite_FastMaxLatency(rg.latency.max());
    }
    if (portNum == 0) {
        Stages::lastMember();  // the stage statistics, after the group's measured window
    }
}

void Timing::serveSegments(U32 hyperperiod) {
    FW_ASSERT(hyperperiod > 0);
    m_hyperperiod = hyperperiod;
    m_segmentState.store(SEGMENT_IDLE);
}

bool Timing::segmentRequested() const {
    return m_segmentState.load() == SEGMENT_REQUESTED;
}

Timing::Segment Timing::takeSegment() const {
    FW_ASSERT(this->segmentRequested());
    return m_segment;
}

void Timing::segmentDone() {
    FW_ASSERT(this->segmentRequested());
    m_segmentState.store(SEGMENT_IDLE);
}

void Timing::MEASURE_SEGMENT_cmdHandler(FwOpcodeType opCode,
                                        U32 cmdSeq,
                                        SegmentAxis axis,
                                        U32 point,
                                        U32 level,
                                        U32 ticks) {
    const U32 state = m_segmentState.load();
    SegmentRefusal refusal = SegmentRefusal::NOT_SERVED;
    bool refused = true;
    if (state == SEGMENT_REQUESTED) {
        refusal = SegmentRefusal::BUSY;
    } else if (state == SEGMENT_IDLE) {
        refused = ticks == 0 || ticks > SEGMENT_MAX_TICKS || (ticks % m_hyperperiod) != 0;
        refusal = SegmentRefusal::BAD_LENGTH;
    }
    if (refused) {
        this->log_WARNING_LO_SegmentRefused(refusal, ticks);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_segment = {axis, point, level, ticks};
    m_segmentState.store(SEGMENT_REQUESTED);
    this->log_ACTIVITY_HI_SegmentRequested(axis, point, level, ticks);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

}  // namespace Kit
