// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TlmTable.hpp
// \brief  The telemetry store in one table, read through a sequence lock (see
//         TlmTable.fpp and docs/sdd.md)
// ======================================================================
#ifndef KIT_TLMTABLE_HPP
#define KIT_TLMTABLE_HPP

#include <Fw/Tlm/TlmPacket.hpp>
#include <atomic>
#include <config/TlmChanImplCfg.hpp>
#include <type_traits>
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
    //! A write's sequence number marks each entry: odd while a writer is in
    //! it, even when it is whole, 0 while no channel holds it. The 10 Hz
    //! read copies an entry and keeps the copy only when the number did not
    //! move meanwhile (a sequence lock): it never blocks a writer, and a
    //! writer never waits for it.
    //! A value's size: one byte where the build's largest value fits in it
    //! (the boards' builds), else two (F´'s default sizes, the host tests)
    using ValueSize = std::conditional<FW_TLM_BUFFER_MAX_SIZE <= 0xFF, U8, U16>::type;
    static_assert(FW_TLM_BUFFER_MAX_SIZE <= 0xFFFF, "a value's size fits its entry");

    //! The value and its time are kept as their bytes and fields, not as
    //! F´'s Fw::TlmBuffer and Fw::Time (each a serializable object with its
    //! own bookkeeping): 40 B an entry where those made 72 B
    struct Entry {
        FwChanIdType id = 0;
        std::atomic<U32> sequence{0};
        U32 sentSequence = 0;  //!< The sequence of the value the last Run sent (Run's alone)
        U32 seconds = 0;
        U32 useconds = 0;
        FwTimeBaseStoreType timeBase = 0;
        FwTimeContextStoreType context = 0;
        ValueSize size = 0;  //!< The value's bytes
        U8 value[FW_TLM_BUFFER_MAX_SIZE] = {};
    };

    //! One entry's value as Run copied it
    struct Snapshot {
        FwChanIdType id = 0;
        U32 sequence = 0;
        Fw::Time time;
        Fw::TlmBuffer buffer;
    };

    //! Copies Run makes of one entry before it gives it up to the next cycle:
    //! each failed one was a writer preempting the copy
    static constexpr U32 READ_ATTEMPTS = 3;

    void TlmRecv_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) override;
    Fw::TlmValid TlmGet_handler(FwIndexType portNum, FwChanIdType id, Fw::Time& timeTag, Fw::TlmBuffer& val) override;
    void Run_handler(FwIndexType portNum, U32 context) override;
    void pingIn_handler(FwIndexType portNum, U32 key) override;

    //! The entry that holds channel id, or the free entry where it would go
    //! (open addressing: from id's home entry on, one entry at a time);
    //! ENTRIES when the table is full and id is not in it. Writers' (under
    //! the guarded ports' lock)
    U32 find(FwChanIdType id) const;

    //! An entry's value and time into F´'s types
    static void read(const Entry& entry, Fw::Time& time, Fw::TlmBuffer& buffer);

    //! Entry index's value into copy, when it was written since the last Run
    //! sent it and the copy is whole: false when nothing is new, when a
    //! writer this call preempted is in the entry (it cannot go on before
    //! this call ends), or after READ_ATTEMPTS copies a writer broke into;
    //! the value then goes in the next cycle
    bool snapshot(U32 index, Snapshot& copy) const;

    Entry m_entries[ENTRIES];
    U32 m_used = 0;
};

}  // namespace Kit

#endif
