// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TlmTable.hpp
// \brief  The telemetry store in one table, read under its lock (see
//         TlmTable.fpp and docs/sdd.md)
// ======================================================================
#ifndef KIT_TLMTABLE_HPP
#define KIT_TLMTABLE_HPP

#include <Fw/Tlm/TlmPacket.hpp>
#include <config/TlmChanImplCfg.hpp>
#include "app/Components/TlmTable/TlmTableComponentAc.hpp"

namespace Kit {

class TlmTable final : public TlmTableComponentBase {
    friend class TlmTableTester;

  public:
    //! One entry per channel the build can write: the same count as
    //! TlmChan's buckets (config/TlmChanImplCfg.hpp), which the build checks
    //! against its dictionary
    static constexpr U32 ENTRIES = TLMCHAN_HASH_BUCKETS;

    explicit TlmTable(const char* const compName);
    ~TlmTable();

    //! Entries taken so far (a channel takes one the first time it is
    //! written, for good)
    U32 entriesUsed() const { return m_used; }

  private:
    struct Entry {
        FwChanIdType id = 0;
        bool used = false;     //!< A channel holds this entry
        bool updated = false;  //!< Written since the last Run sent it
        Fw::Time lastUpdate;
        Fw::TlmBuffer buffer;
    };

    void TlmRecv_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) override;
    Fw::TlmValid TlmGet_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) override;
    void Run_handler(FwIndexType portNum, U32 context) override;
    void pingIn_handler(FwIndexType portNum, U32 key) override;

    //! The entry that holds channel id, or the free entry where it would go
    //! (open addressing: from id's home entry on, one entry at a time);
    //! ENTRIES when the table is full and id is not in it
    U32 find(FwChanIdType id) const;

    //! Entry index, under the lock: when written since the last Run, added to
    //! pkt and marked sent, unless pkt has no room (FW_SERIALIZE_NO_ROOM_LEFT:
    //! it stays marked)
    Fw::SerializeStatus pack(Fw::TlmPacket& pkt, U32 index);

    Entry m_entries[ENTRIES];
    U32 m_used = 0;
};

}  // namespace Kit

#endif
