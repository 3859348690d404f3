// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  load.cpp
// \brief  The background-load sweep: where does each execution model break?
//
// The load component's work is stepped up by command (through the real
// uplink and dispatcher), point by point, in one build and one boot. Each
// point lets the new load settle, then measures a fresh segment and prints
// one SWEEP line per rate group; at the end a BREAK line per axis and rate
// group names the smallest load at which that group missed a deadline.
// Two axes:
//   slice  one uninterruptible computation per 100 Hz dispatch (a long,
//          low-priority job: Betaflight's long serial task);
//   burst  BURST_MESSAGES messages through the load's queue every 10 Hz
//          cycle, each that long (a telemetry or serial burst).
// ======================================================================
#include "Top/KitTopology.hpp"
#include "app/Subtopologies/Instruments/InstrumentIds.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/Report.hpp"
#include "app/src/Session.hpp"

#include <zephyr/sys/printk.h>
#include <zephyr/sys/util.h>

namespace Kit {
namespace Scenario {

namespace {

// A settle segment lets a new setting reach the load (the command is
// dispatched in the first 10 Hz cycle) and the queues reach steady state;
// the measured segment follows. Both last whole hyperperiods (asserted):
// at least these many ticks, rounded up to the deployment's hyperperiod
constexpr U32 SETTLE_TICKS_MIN = 100;
constexpr U32 MEASURE_TICKS_MIN = 200;
constexpr U32 BURST_MESSAGES = 8;  // fits the load's queue (Queues.load)

U32 wholeHyperperiods(U32 ticks) {
    const U32 period = Session::hyperperiod();
    return ((ticks + period - 1) / period) * period;
}

struct Axis {
    const char* name;
    U32 stepsPerPeriod;  //!< the step: the fastest group's period over this
    U32 points;          //!< loads 0, step, ..., (points - 1) x step
    bool burst;
};
// Both reach twice the fastest group's period (2 ms at 1 kHz); the slice
// axis in steps fine enough to place the knee within a tenth of it
const Axis AXES[] = {
    {"slice", 10, 21, false},
    {"burst", 4, 9, true},
};
constexpr U32 NO_BREAK = 0xFFFFFFFFu;

// An axis' step, from the deployment's fastest rate group (RATE_GROUPS[0])
U32 stepUs(const Axis& axis) {
    constexpr U32 TICK_US = 1000000U / CONFIG_KIT_TICK_HZ;
    return RATE_GROUPS[0].divisor * TICK_US / axis.stepsPerPeriod;
}

Uplink::Frame loadCommand(const Axis& axis, U32 us) {
    const FwOpcodeType base = load.getIdBase();
    if (axis.burst) {
        return command(0, base + LoadIds::SET_BURST, Args().add(BURST_MESSAGES).add(us));
    }
    return command(0, base + LoadIds::SET_SLICE, Args().add(us));
}

Uplink::Frame idleCommand(const Axis& axis) {
    return loadCommand(axis, 0);
}

// Where health's warning would first fire along an axis: the first level at
// which a ping waited its warning deadline, and the longest wait on the axis
struct HealthOnAxis {
    bool reached;
    U32 level;
    U32 worst;
};

// Sweep one axis; false if a load command was not accepted
bool sweep(const Axis& axis, U32 breakUs[], HealthOnAxis& health) {
    bool commanded = true;
    health = {false, 0, 0};
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        breakUs[i] = NO_BREAK;
    }
    const U32 settleTicks = wholeHyperperiods(SETTLE_TICKS_MIN);
    const U32 measureTicks = wholeHyperperiods(MEASURE_TICKS_MIN);
    for (U32 point = 0; point < axis.points; point++) {
        const U32 us = point * stepUs(axis);
        Uplink::Frame frame = loadCommand(axis, us);
        uplink.play(&frame, 1);
        Session::run(settleTicks);
        commanded = commanded && frame.asExpected();
        Session::nextSegment();
        Report::startHealthSegment();
        const U32 processedBefore = load.processed();
        const U32 droppedBefore = load.dropped();
        Session::run(measureTicks);
        bool broke[RATE_GROUP_COUNT] = {};
        const Report::SweepPoint measured = {axis.name,
                                             point,
                                             us,
                                             "us",
                                             axis.burst ? BURST_MESSAGES : 0,
                                             measureTicks,
                                             load.processed() - processedBefore,
                                             load.dropped() - droppedBefore};
        Report::sweepPoint(measured, broke);
        const U32 pingWorst = Report::sweepHealth(measured);
        health.worst = (pingWorst > health.worst) ? pingWorst : health.worst;
        if (!health.reached && pingWorst >= Report::pingWarnDeadline()) {
            health = {true, us, health.worst};
        }
        for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
            if (broke[i] && breakUs[i] == NO_BREAK) {
                breakUs[i] = us;
            }
        }
        Session::nextSegment();
    }
    // Back to no load before the next axis
    Uplink::Frame idle = idleCommand(axis);
    uplink.play(&idle, 1);
    Session::run(settleTicks);
    Session::nextSegment();
    return commanded && idle.asExpected();
}

void printBreaks(const Axis& axis, const U32 breakUs[]) {
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        if (breakUs[i] == NO_BREAK) {
            printk("KIT BREAK axis=%s rg=%s level=none unit=us\n", axis.name, timing.record(i).spec.name);
        } else {
            printk("KIT BREAK axis=%s rg=%s level=%u unit=us\n", axis.name, timing.record(i).spec.name,
                   static_cast<unsigned>(breakUs[i]));
        }
    }
}

}  // namespace

bool playLoad(const Context& context) {
    bool commanded = true;
    U32 breakUs[FW_NUM_ARRAY_ELEMENTS(AXES)][RATE_GROUP_COUNT] = {};
    HealthOnAxis health[FW_NUM_ARRAY_ELEMENTS(AXES)] = {};
    for (FwSizeType a = 0; a < FW_NUM_ARRAY_ELEMENTS(AXES); a++) {
        commanded = sweep(AXES[a], breakUs[a], health[a]) && commanded;
    }
    for (FwSizeType a = 0; a < FW_NUM_ARRAY_ELEMENTS(AXES); a++) {
        printBreaks(AXES[a], breakUs[a]);
    }
    for (FwSizeType a = 0; a < FW_NUM_ARRAY_ELEMENTS(AXES); a++) {
        Report::healthBreak(AXES[a].name, health[a].level, health[a].reached, health[a].worst);
    }
    printk("KIT LOAD commands=%s processed=%u dropped=%u\n", commanded ? "OK" : "FAILED",
           static_cast<unsigned>(load.processed()), static_cast<unsigned>(load.dropped()));
    const bool heapOk = Report::heap(context.allocator);
    Report::hash();
    const bool downlinked = Report::downlinkAndTicks();
    Report::stacks();
    Report::queues();
    Report::schedule();
    // Where the model is expected to hold its deadlines on this board
    // (CONFIG_KIT_DEADLINES_EXPECTED), no group may miss one at zero load
    bool idleMet = true;
    for (FwSizeType a = 0; a < FW_NUM_ARRAY_ELEMENTS(AXES); a++) {
        for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
            idleMet = idleMet && breakUs[a][i] != 0;
        }
    }
    // A queue the sweep overflowed would make its points meaningless, unless
    // the model sheds load by design (CONFIG_KIT_MODEL_SHEDS_LOAD): then the
    // drops are its trade for the deadlines, counted per point (load_dropped)
    return commanded && heapOk && downlinked && (load.dropped() == 0 || IS_ENABLED(CONFIG_KIT_MODEL_SHEDS_LOAD)) &&
           (idleMet || !IS_ENABLED(CONFIG_KIT_DEADLINES_EXPECTED));
}

}  // namespace Scenario
}  // namespace Kit
