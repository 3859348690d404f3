// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  LinkHealth.cpp
// \brief  The ground link's rejections, by reason, as telemetry
// ======================================================================
#include "app/Components/LinkHealth/LinkHealth.hpp"

namespace Kit {

LinkHealth::LinkHealth(const char* const compName)
    : LinkHealthComponentBase(compName), m_detector(), m_unknownPackets(0) {}

LinkHealth::~LinkHealth() {}

void LinkHealth::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    const CountingFrameDetector::Counts counts = m_detector.counts();
    tlmWrite_FramesDetected(counts.detected);
    tlmWrite_BadChecksums(counts.badChecksums);
    tlmWrite_BytesDiscarded(counts.bytesDiscarded);
    tlmWrite_Oversized(counts.oversized);
    tlmWrite_UnknownPackets(m_unknownPackets);
}

void LinkHealth::unknownIn_handler(FwIndexType portNum, Fw::Buffer& data, const ComCfg::FrameContext& context) {
    (void)portNum;
    (void)context;
    m_unknownPackets++;
    unknownReturnOut_out(0, data);
}

}  // namespace Kit
