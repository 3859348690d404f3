// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Monitor.hpp
// \brief  100 Hz control-error monitor with persistence
// ======================================================================
#ifndef KIT_MONITOR_HPP
#define KIT_MONITOR_HPP

#include "app/Components/Monitor/MonitorComponentAc.hpp"

namespace Kit {

class Monitor final : public MonitorComponentBase {
  public:
    //! An error beyond ERROR_LIMIT for PERSISTENCE consecutive checks raises the alarm
    static constexpr I32 ERROR_LIMIT = 2000;
    static constexpr U32 PERSISTENCE = 3;
    static constexpr U32 TLM_DECIMATION = 10;

    explicit Monitor(const char* const compName);
    ~Monitor();

    bool alarmed() const { return m_alarmed; }

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;

    I32 m_maxError;
    U32 m_overLimit;  //!< consecutive checks beyond the limit
    U32 m_checks;
    bool m_alarmed;
};

}  // namespace Kit

#endif
