// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_TLMTABLETESTER_HPP
#define KIT_TLMTABLETESTER_HPP

#include <map>
#include "app/Components/TlmTable/TlmTable.hpp"
#include "app/Components/TlmTable/TlmTableGTestBase.hpp"

namespace Kit {

class TlmTableTester : public TlmTableGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = TlmTable::ENTRIES;
    static const FwSizeType TEST_INSTANCE_QUEUE_DEPTH = 4;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;

    TlmTableTester();
    ~TlmTableTester();

    void valuesAreKeptAndRead();
    void aCycleSendsEachWrittenChannelOnce();
    void channelsSharingAHomeEntryKeepTheirOwn();
    void aCycleSpansPacketsAndLosesNone();
    void aChannelPastTheTableAsserts();
    void aValueBeingWrittenGoesInTheNextCycle();

  private:
    void connectPorts();
    void initComponents();

    //! Writes channel id with value (a U32) at time seconds
    void write(FwChanIdType id, U32 value, U32 seconds = 1);
    //! Runs one cycle and returns every channel's value it sent, by ID
    //! (a channel sent twice fails the test)
    std::map<FwChanIdType, U32> cycle();

    TlmTable component;
};

}  // namespace Kit

#endif
