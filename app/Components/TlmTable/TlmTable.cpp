// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TlmTable.cpp
// \brief  The telemetry store in one table, read through a sequence lock
// ======================================================================
#include "app/Components/TlmTable/TlmTable.hpp"
#include <Fw/Types/Assert.hpp>
#include <cstring>

namespace Kit {

// C++14: the constants' one definitions, for a use by reference
constexpr U32 TlmTable::ENTRIES;
constexpr U32 TlmTable::READ_ATTEMPTS;

TlmTable::TlmTable(const char* const compName) : TlmTableComponentBase(compName) {}

TlmTable::~TlmTable() {}

U32 TlmTable::find(FwChanIdType id) const {
    // A channel's home entry is its ID modulo the table; a taken entry sends
    // the search to the next. Entries are never given back, so the search
    // for a channel ends at the channel or at the first free entry.
    U32 index = static_cast<U32>(id) % ENTRIES;
    for (U32 probe = 0; probe < ENTRIES; probe++) {
        const Entry& entry = this->m_entries[index];
        if (entry.sequence.load(std::memory_order_relaxed) == 0 || entry.id == id) {
            return index;
        }
        index = (index + 1 == ENTRIES) ? 0 : index + 1;
    }
    return ENTRIES;
}

void TlmTable::TlmRecv_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) {
    // Guarded port: the component's lock keeps the other writers out; Run
    // does not take it, and sees this write through the entry's sequence
    const U32 index = this->find(id);
    // More channels written than the build counted (the build checks its
    // dictionary against ENTRIES, so this is a channel outside it)
    FW_ASSERT(index < ENTRIES, static_cast<FwAssertArgType>(id));
    Entry& entry = this->m_entries[index];
    const U32 sequence = entry.sequence.load(std::memory_order_relaxed);
    if (sequence == 0) {
        this->m_used++;
    }
    // Odd: a writer is in the entry
    entry.sequence.store(sequence + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    entry.id = id;
    entry.seconds = timeTag.getSeconds();
    entry.useconds = timeTag.getUSeconds();
    entry.timeBase = static_cast<FwTimeBaseStoreType>(timeTag.getTimeBase().e);
    entry.context = timeTag.getContext();
    // A TlmBuffer holds at most FW_TLM_BUFFER_MAX_SIZE bytes: the entry's size
    const FwSizeType size = val.getSize();
    FW_ASSERT(size <= sizeof(entry.value), static_cast<FwAssertArgType>(size));
    entry.size = static_cast<ValueSize>(size);
    (void)std::memcpy(entry.value, val.getBuffAddr(), size);
    // Even again, never 0 (a free entry's) across the counter's wrap
    const U32 next = (sequence + 2 == 0) ? 2 : sequence + 2;
    entry.sequence.store(next, std::memory_order_release);
}

Fw::TlmValid TlmTable::TlmGet_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) {
    // Guarded port: no writer is in any entry
    const U32 index = this->find(id);
    if (index < ENTRIES && this->m_entries[index].sequence.load(std::memory_order_relaxed) != 0) {
        read(this->m_entries[index], timeTag, val);
        return Fw::TlmValid::VALID;
    }
    // Not written yet
    val.resetSer();
    return Fw::TlmValid::INVALID;
}

void TlmTable::read(const Entry& entry, Fw::Time& time, Fw::TlmBuffer& buffer) {
    time.set(TimeBase(static_cast<TimeBase::T>(entry.timeBase)), entry.context, entry.seconds, entry.useconds);
    // size is at most the buffer's capacity: a torn copy is thrown away by
    // snapshot(), never a larger one
    const Fw::SerializeStatus status = buffer.setBuff(entry.value, entry.size);
    FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status));
}

bool TlmTable::snapshot(U32 index, Snapshot& copy) const {
    const Entry& entry = this->m_entries[index];
    for (U32 attempt = 0; attempt < READ_ATTEMPTS; attempt++) {
        const U32 before = entry.sequence.load(std::memory_order_acquire);
        if (before == entry.sentSequence || (before & 1U) != 0) {
            return false;
        }
        copy.id = entry.id;
        read(entry, copy.time, copy.buffer);
        std::atomic_thread_fence(std::memory_order_acquire);
        if (entry.sequence.load(std::memory_order_relaxed) == before) {
            copy.sequence = before;
            return true;
        }
    }
    return false;
}

void TlmTable::Run_handler(FwIndexType portNum, U32 context) {
    if (!this->isConnected_PktSend_OutputPort(0)) {
        return;
    }
    Fw::TlmPacket pkt;
    Fw::SerializeStatus status = pkt.resetPktSer();
    FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status));
    Snapshot copy;
    for (U32 index = 0; index < ENTRIES; index++) {
        if (!this->snapshot(index, copy)) {
            continue;
        }
        status = pkt.addValue(copy.id, copy.time, copy.buffer);
        if (status == Fw::FW_SERIALIZE_NO_ROOM_LEFT) {
            // Full: send it, then the value in a new one
            this->PktSend_out(0, pkt.getBuffer(), 0);
            status = pkt.resetPktSer();
            FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status));
            status = pkt.addValue(copy.id, copy.time, copy.buffer);
        }
        // Anything else: a channel's value larger than a packet
        FW_ASSERT(status == Fw::FW_SERIALIZE_OK, static_cast<FwAssertArgType>(status),
                  static_cast<FwAssertArgType>(index));
        this->m_entries[index].sentSequence = copy.sequence;
    }
    if (pkt.getNumEntries() > 0) {
        this->PktSend_out(0, pkt.getBuffer(), 0);
    }
}

void TlmTable::pingIn_handler(FwIndexType portNum, U32 key) {
    this->pingOut_out(0, key);
}

}  // namespace Kit
