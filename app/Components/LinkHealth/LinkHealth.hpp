// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  LinkHealth.hpp
// \brief  The ground link's rejections, by reason, as telemetry
// ======================================================================
#ifndef KIT_LINKHEALTH_HPP
#define KIT_LINKHEALTH_HPP

#include "app/Components/LinkHealth/CountingFrameDetector.hpp"
#include "app/Components/LinkHealth/LinkHealthComponentAc.hpp"

#include <atomic>

namespace Kit {

class LinkHealth final : public LinkHealthComponentBase {
  public:
    explicit LinkHealth(const char* const compName);
    ~LinkHealth();

    //! \param accumulatorSize the FrameAccumulator's ring size
    //! \param commandsInFlight ground commands the dispatcher may hold at once
    void configure(FwSizeType accumulatorSize, U32 commandsInFlight);

    //! The detector the FrameAccumulator is configured with
    const Svc::FrameDetector& detector() const { return m_detector; }
    CountingFrameDetector::Counts counts() const { return m_detector.counts(); }
    U32 unknownPackets() const { return m_unknownPackets; }
    U32 commandsDropped() const { return m_commandsDropped.load(); }

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    void unknownIn_handler(FwIndexType portNum, Fw::Buffer& data, const ComCfg::FrameContext& context) override;
    void commandIn_handler(FwIndexType portNum, Fw::ComBuffer& data, U32 context) override;
    void commandStatusIn_handler(FwIndexType portNum,
                                 FwOpcodeType opCode,
                                 U32 cmdSeq,
                                 const Fw::CmdResponse& response) override;

    CountingFrameDetector m_detector;
    U32 m_unknownPackets;
    // Commands come in on the link's context (a rate group) and their
    // answers on the dispatcher's: one counter both update
    std::atomic<U32> m_inFlight;
    std::atomic<U32> m_commandsDropped;
    U32 m_inFlightLimit;
};

}  // namespace Kit

#endif
