// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ground.cpp
// \brief  The deployment serves the ground link, and measures on request
// ======================================================================
//
// No built-in command sequence: every command comes up the ground link
// (fprime-gds, `kit gds`, the integration suite in tests/integration), and
// the run never ends, as a flight deployment's does. The one thing it adds
// is the serial-load sweep's measurement: when the ground asks
// (Timing.MEASURE_SEGMENT), the main loop stops at the next hyperperiod,
// measures the requested segment under whatever load the ground applies
// (commands up the link, Load.SET_DOWNLINK's packets down it, or the file
// downlink's SendPartial files down it) and prints
// its SWEEP lines, then serves on. scripts/kittools/link/serial_sweep.py drives it.

#include "Top/KitTopology.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/Report.hpp"
#include "app/src/Session.hpp"

namespace Kit {
namespace Scenario {

namespace {

bool segmentRequested() {
    return timing.segmentRequested();
}

// The axis' name and unit in the SWEEP record
Report::SweepPoint pointOf(const Timing::Segment& segment) {
    const char* name = "uplink";
    const char* unit = "cmd/s";
    switch (segment.axis.e) {
        case SegmentAxis::UPLINK:
            break;
        case SegmentAxis::DOWNLINK:
            name = "downlink";
            unit = "pkt/s";
            break;
        case SegmentAxis::NOISE:
            name = "noise";
            unit = "%";  // of the line rate
            break;
        case SegmentAxis::FILE_DOWNLINK:
            name = "file";
            unit = "B/s";  // of file data
            break;
        case SegmentAxis::SEQUENCE:
            name = "sequence";  // commands the sequencer runs
            break;
        default:
            FW_ASSERT(0, static_cast<FwAssertArgType>(segment.axis.e));
            break;
    }
    return {name, segment.point, segment.level, unit, 0, segment.ticks, 0, 0};
}

}  // namespace

bool playGround(const Context& context) {
    (void)context;
    timing.serveSegments(Session::hyperperiod());
    Report::linkReady();
    // The one loop without a bound: a flight deployment serves until power-off
    for (;;) {
        Session::serve(segmentRequested);
        const Timing::Segment segment = timing.takeSegment();
        // One more hyperperiod before the segment: the request's own
        // dispatch and events (queued at whatever phase the ground's bytes
        // arrived) drain there, so the segment starts from the load's
        // periodic state, not from the request's leftovers
        Session::run(Session::hyperperiod());
        Session::nextSegment();
        Report::SweepPoint point = pointOf(segment);
        const U32 processedBefore = load.processed();
        const U32 droppedBefore = load.dropped();
        Session::run(segment.ticks);
        point.loadRuns = load.processed() - processedBefore;
        point.loadDropped = load.dropped() - droppedBefore;
        bool broke[RATE_GROUP_COUNT] = {};
        Report::sweepPoint(point, broke);
        // The stacks' high-water marks so far: the ground link's paths (file
        // transfers, sequences, fuzzing) reach no other scenario's
        Report::stacks();
        Session::nextSegment();
        timing.segmentDone();
    }
    return true;
}

}  // namespace Scenario
}  // namespace Kit
