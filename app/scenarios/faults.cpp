// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  faults.cpp
// \brief  Faults the system must survive, injected at run time: malformed
//         commands on the uplink, an overrun of the fastest rate group and
//         an overrun of the background load's queue
//
// Each must be detected, reported as an F´ event, counted, and leave the
// system running: every rate group still completes every cycle, and a
// valid command after the faults is still answered OK.
// ======================================================================
#include "Top/KitTopology.hpp"
#include "app/Subtopologies/Instruments/InstrumentIds.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/Report.hpp"
#include "app/src/ServiceIds.hpp"
#include "app/src/Session.hpp"

#include <zephyr/sys/printk.h>

namespace Kit {
namespace Scenario {

namespace {
constexpr U32 RUN_TICKS = 2000;
constexpr U32 OVERFLOW_BURST = 16;  // more than the load's queue holds
constexpr FwIndexType FASTEST = 0;
constexpr FwSizeType SCRIPT_FRAMES = 10;

// Built in its own frame, which is gone before the run starts: on baremetal
// the main stack is every task's
// An overrun of 1.5 periods of the fastest group, whatever its rate
U32 overrunUs() {
    constexpr U32 TICK_US = 1000000U / CONFIG_KIT_TICK_HZ;
    return RATE_GROUPS[FASTEST].divisor * TICK_US * 3U / 2U;
}

__attribute__((noinline)) void buildScript(Uplink::Frame* const script) {
    // A command with an argument every deployment has: the kit's load's
    const FwOpcodeType setSlice = load.getIdBase() + LoadIds::SET_SLICE;
    const U8 shortArgs[] = {0x00, 0x07};                        // a U32 needs 4 bytes
    const U8 garbage[] = {0xDE, 0xAD, 0xBE, 0xEF, 0x01, 0x02};  // not a command packet
    const U8 truncated[] = {0x00};                              // not even a descriptor
    const Fw::CmdResponse format = Fw::CmdResponse::FORMAT_ERROR;
    const Fw::CmdResponse invalid = Fw::CmdResponse::VALIDATION_ERROR;
    // Into the shared static script frame by frame: a local array of frames
    // would cost the main thread's stack (the sentinel caught that on rtos)
    script[0] = command(2, 0x7FFF, Args());
    script[0].expected = Fw::CmdResponse::INVALID_OPCODE;
    script[1] = Uplink::commandFrame(3, setSlice, shortArgs, sizeof shortArgs);
    script[1].expected = format;
    // Too long: the U32 and two stray bytes
    script[2] = command(4, setSlice, Args().add(static_cast<U32>(0)).add(static_cast<U16>(7)));
    script[2].expected = format;
    script[3] = Uplink::rawFrame(5, garbage, sizeof garbage, invalid);
    script[4] = Uplink::rawFrame(6, truncated, sizeof truncated, invalid);
    script[5] = noOpFrame(7);
    script[6] =
        command(8, faults.getIdBase() + FaultsIds::OVERRUN, Args().add(static_cast<U8>(FASTEST)).add(overrunUs()));
    script[7] = command(9, load.getIdBase() + LoadIds::SET_BURST, Args().add(OVERFLOW_BURST).add(static_cast<U32>(0)));
    script[8] =
        command(11, load.getIdBase() + LoadIds::SET_BURST, Args().add(static_cast<U32>(0)).add(static_cast<U32>(0)));
    script[9] = noOpFrame(12);
}

}  // namespace

bool playFaults(const Context& context) {
    Uplink::Frame* const script = scriptFrames(SCRIPT_FRAMES);
    buildScript(script);
    uplink.play(script, SCRIPT_FRAMES);
    Session::run(RUN_TICKS);

    // The record: the rate groups (slips expected in the fastest only), the
    // commands, and what each detection counted
    (void)Report::rateGroups(RUN_TICKS);
    const bool answered = Report::commands(script, SCRIPT_FRAMES);
    const FwEventIdType dispBase = cmdDisp.getIdBase();
    const U32 invalidEvents = downlink.eventCount(dispBase + CmdDispIds::INVALID_COMMAND);
    const U32 malformedEvents = downlink.eventCount(dispBase + CmdDispIds::MALFORMED_COMMAND);
    const U32 opcodeErrorEvents = downlink.eventCount(dispBase + CmdDispIds::OPCODE_ERROR);
    const U32 slipEvents = downlink.eventCount(timing.getIdBase() + TimingIds::RATE_GROUP_SLIP);
    const U32 dropEvents = downlink.eventCount(load.getIdBase() + LoadIds::MESSAGES_DROPPED);
    bool cyclesOk = true;
    U32 otherSlips = 0;
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        cyclesOk = cyclesOk && timing.record(i).cycles == expectedCycles(i, RUN_TICKS);
        otherSlips += (i == FASTEST) ? 0 : timing.record(i).slips;
    }
    const U32 slips = timing.record(FASTEST).slips;
    printk(
        "KIT FAULTS invalid_opcode_events=%u malformed_events=%u opcode_error_events=%u slips=%u slip_events=%u "
        "other_slips=%u load_dropped=%u drop_events=%u cycles_complete=%s\n",
        static_cast<unsigned>(invalidEvents), static_cast<unsigned>(malformedEvents),
        static_cast<unsigned>(opcodeErrorEvents), static_cast<unsigned>(slips), static_cast<unsigned>(slipEvents),
        static_cast<unsigned>(otherSlips), static_cast<unsigned>(load.dropped()), static_cast<unsigned>(dropEvents),
        cyclesOk ? "yes" : "no");
    const bool heapOk = Report::heap(context.allocator);
    Report::hash();
    const bool downlinked = Report::downlinkAndTicks();
    Report::stacks();
    Report::queues();
    // Every fault detected and reported, nothing lost
    const bool detected = invalidEvents >= 1 && malformedEvents >= 2 && opcodeErrorEvents >= 2 && slips >= 1 &&
                          slipEvents >= 1 && load.dropped() > 0 && dropEvents >= 1;
    return answered && detected && otherSlips == 0 && cyclesOk && heapOk && downlinked;
}

}  // namespace Scenario
}  // namespace Kit
