// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Housekeeping/test/ut/HousekeepingTester.hpp"

namespace Kit {

HousekeepingTester::HousekeepingTester()
    : HousekeepingGTestBase("HousekeepingTester", MAX_HISTORY_SIZE), component("Housekeeping") {
    this->initComponents();
    this->connectPorts();
}

HousekeepingTester::~HousekeepingTester() {}

void HousekeepingTester::runPass() {
    for (FwSizeType i = 0; i < Housekeeping::TABLE_SIZE / Housekeeping::SLICE_SIZE; i++) {
        this->invoke_to_schedIn(0, 0);
    }
}

void HousekeepingTester::crcMatchesTheStandardCheckValue() {
    // CRC-32/IEEE of "123456789" is 0xCBF43926 (after the final inversion)
    const U8 check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    EXPECT_EQ(~Housekeeping::crc32(0xFFFFFFFFu, check, sizeof check), 0xCBF43926u);
}

void HousekeepingTester::intactTablePassesQuietly() {
    runPass();
    runPass();
    EXPECT_EQ(component.passes(), 2u);
    ASSERT_EVENTS_ScrubMismatch_SIZE(0);
    ASSERT_TLM_ScrubPasses(1, 2u);
}

void HousekeepingTester::corruptedTableRaisesAnEvent() {
    runPass();
    component.table()[Housekeeping::TABLE_SIZE - 1] ^= 0x01;  // one flipped bit, in the last slice
    runPass();
    ASSERT_EVENTS_ScrubMismatch_SIZE(1);
}

}  // namespace Kit
