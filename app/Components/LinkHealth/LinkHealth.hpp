// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  LinkHealth.hpp
// \brief  The ground link's rejections, by reason, as telemetry
// ======================================================================
#ifndef KIT_LINKHEALTH_HPP
#define KIT_LINKHEALTH_HPP

#include "app/Components/LinkHealth/CountingFrameDetector.hpp"
#include "app/Components/LinkHealth/LinkHealthComponentAc.hpp"

namespace Kit {

class LinkHealth final : public LinkHealthComponentBase {
  public:
    explicit LinkHealth(const char* const compName);
    ~LinkHealth();

    //! \param accumulatorSize the FrameAccumulator's ring size
    void configure(FwSizeType accumulatorSize) { m_detector.setCapacity(accumulatorSize); }

    //! The detector the FrameAccumulator is configured with
    const Svc::FrameDetector& detector() const { return m_detector; }
    CountingFrameDetector::Counts counts() const { return m_detector.counts(); }
    U32 unknownPackets() const { return m_unknownPackets; }

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    void unknownIn_handler(FwIndexType portNum, Fw::Buffer& data, const ComCfg::FrameContext& context) override;

    CountingFrameDetector m_detector;
    U32 m_unknownPackets;
};

}  // namespace Kit

#endif
