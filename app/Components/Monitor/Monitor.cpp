// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Monitor.cpp
// \brief  100 Hz control-error monitor with persistence
// ======================================================================
#include "app/Components/Monitor/Monitor.hpp"

namespace Kit {

Monitor::Monitor(const char* const compName)
    : MonitorComponentBase(compName), m_maxError(0), m_overLimit(0), m_checks(0), m_alarmed(false) {}

Monitor::~Monitor() {}

void Monitor::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    const ControlStatus status = this->statusGet_out(0);
    const I32 error = status.get_setpoint() - status.get_measurement();
    const I32 magnitude = error < 0 ? -error : error;
    m_checks++;
    if (magnitude > m_maxError) {
        m_maxError = magnitude;
    }
    if (magnitude > ERROR_LIMIT) {
        m_overLimit++;
        if (m_overLimit == PERSISTENCE && !m_alarmed) {
            m_alarmed = true;
            this->log_WARNING_HI_ErrorLimitExceeded(error, ERROR_LIMIT);
        }
    } else {
        m_overLimit = 0;
        if (m_alarmed) {
            m_alarmed = false;
            this->log_ACTIVITY_HI_ErrorRecovered(error);
        }
    }
    if ((m_checks % TLM_DECIMATION) == 0) {
        this->tlmWrite_MaxError(m_maxError);
        this->tlmWrite_Checks(m_checks);
    }
}

}  // namespace Kit
