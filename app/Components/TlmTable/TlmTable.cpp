// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TlmTable.cpp
// \brief  The telemetry store in one table, read under its lock
// ======================================================================
#include "app/Components/TlmTable/TlmTable.hpp"
#include <Fw/Types/Assert.hpp>

namespace Kit {

// C++14: the constant's one definition, for a use by reference
constexpr U32 TlmTable::ENTRIES;

TlmTable::TlmTable(const char* const compName) : TlmTableComponentBase(compName) {}

TlmTable::~TlmTable() {}

U32 TlmTable::find(FwChanIdType id) const {
    // A channel's home entry is its ID modulo the table; a taken entry sends
    // the search to the next. Entries are never given back, so the search
    // for a channel ends at the channel or at the first free entry.
    U32 index = static_cast<U32>(id) % ENTRIES;
    for (U32 probe = 0; probe < ENTRIES; probe++) {
        const Entry& entry = this->m_entries[index];
        if (!entry.used || entry.id == id) {
            return index;
        }
        index = (index + 1 == ENTRIES) ? 0 : index + 1;
    }
    return ENTRIES;
}

void TlmTable::TlmRecv_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) {
    // Guarded port: the component's lock is held
    const U32 index = this->find(id);
    // More channels written than the build counted (the build checks its
    // dictionary against ENTRIES, so this is a channel outside it)
    FW_ASSERT(index < ENTRIES, static_cast<FwAssertArgType>(id));
    Entry& entry = this->m_entries[index];
    if (!entry.used) {
        entry.used = true;
        entry.id = id;
        this->m_used++;
    }
    entry.updated = true;
    entry.lastUpdate = timeTag;
    entry.buffer = val;
}

Fw::TlmValid TlmTable::TlmGet_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) {
    // Guarded port: the component's lock is held
    const U32 index = this->find(id);
    if (index < ENTRIES && this->m_entries[index].used) {
        val = this->m_entries[index].buffer;
        timeTag = this->m_entries[index].lastUpdate;
        return Fw::TlmValid::VALID;
    }
    // Not written yet
    val.resetSer();
    return Fw::TlmValid::INVALID;
}

Fw::SerializeStatus TlmTable::pack(Fw::TlmPacket& pkt, U32 index) {
    Fw::SerializeStatus status = Fw::FW_SERIALIZE_OK;
    // One entry under the lock at a time: a writer waits for this copy at
    // most, never for the whole cycle
    this->lock();
    Entry& entry = this->m_entries[index];
    if (entry.used && entry.updated) {
        status = pkt.addValue(entry.id, entry.lastUpdate, entry.buffer);
        if (status == Fw::FW_SERIALIZE_OK) {
            entry.updated = false;
        }
    }
    this->unLock();
    return status;
}

void TlmTable::Run_handler(FwIndexType portNum, U32 context) {
    if (!this->isConnected_PktSend_OutputPort(0)) {
        return;
    }
    Fw::TlmPacket pkt;
    Fw::SerializeStatus status = pkt.resetPktSer();
    FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status));
    for (U32 index = 0; index < ENTRIES; index++) {
        status = this->pack(pkt, index);
        if (status == Fw::FW_SERIALIZE_NO_ROOM_LEFT) {
            // Full: send it (outside the lock), then the entry in a new one
            this->PktSend_out(0, pkt.getBuffer(), 0);
            status = pkt.resetPktSer();
            FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status));
            status = this->pack(pkt, index);
        }
        // Anything else: a channel's value larger than a packet
        FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status),
                  static_cast<FwAssertArgType>(index));
    }
    if (pkt.getNumEntries() > 0) {
        this->PktSend_out(0, pkt.getBuffer(), 0);
    }
}

void TlmTable::pingIn_handler(FwIndexType portNum, U32 key) {
    this->pingOut_out(0, key);
}

}  // namespace Kit
