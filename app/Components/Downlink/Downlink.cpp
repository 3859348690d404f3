// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Downlink.cpp
// \brief  Event and telemetry packet sink
// ======================================================================
#include "app/Components/Downlink/Downlink.hpp"
#include <Fw/Com/ComPacket.hpp>

namespace Kit {

Downlink::Downlink(const char* const compName)
    : DownlinkComponentBase(compName), m_packets(), m_malformed(0), m_tally(), m_ids(0), m_uncounted(0) {}

Downlink::~Downlink() {}

U32 Downlink::eventCount(FwEventIdType id) const {
    for (FwSizeType i = 0; i < m_ids; i++) {
        if (m_tally[i].id == id) {
            return m_tally[i].count;
        }
    }
    return 0;
}

void Downlink::comIn_handler(FwIndexType portNum, Fw::ComBuffer& data, U32 context) {
    FW_ASSERT(portNum == EVENTS || portNum == TELEMETRY, static_cast<FwAssertArgType>(portNum));
    m_packets[portNum]++;
    if (portNum == EVENTS) {
        tallyEvent(data);
    }
    if (isConnected_comOut_OutputPort(portNum)) {
        comOut_out(portNum, data, context);
    }
}

void Downlink::tallyEvent(Fw::ComBuffer& data) {
    // Event packet: descriptor, event ID, time, arguments
    data.resetDeser();
    FwPacketDescriptorType descriptor = 0;
    FwEventIdType id = 0;
    if (data.deserializeTo(descriptor) != Fw::FW_SERIALIZE_OK ||
        descriptor != static_cast<FwPacketDescriptorType>(Fw::ComPacketType::FW_PACKET_LOG) ||
        data.deserializeTo(id) != Fw::FW_SERIALIZE_OK) {
        m_malformed++;
        return;
    }
    for (FwSizeType i = 0; i < m_ids; i++) {
        if (m_tally[i].id == id) {
            m_tally[i].count++;
            return;
        }
    }
    if (m_ids < EVENT_IDS) {
        m_tally[m_ids] = {id, 1};
        m_ids++;
    } else {
        m_uncounted++;
    }
}

}  // namespace Kit
