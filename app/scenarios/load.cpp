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
//   slice  one uninterruptible computation per message of the load's
//          sliceIn (100 Hz in the reference deployment: a long,
//          low-priority job, Betaflight's long serial task);
//   burst  a burst of messages through the load's queue per call of its
//          burstIn (10 Hz in the reference), each message that long (a
//          telemetry or serial burst).
// Both axes reach twice the fastest group's period, the level at which a
// cooperative model must show its break, whatever the deployment's rates;
// the load stays within half of the CPU at the top (shapeOf).
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
constexpr U32 BURST_MESSAGES_MAX = 8;  // fits the load's queue (Queues.load)
constexpr U32 TICK_US = 1000000U / CONFIG_KIT_TICK_HZ;

U32 wholeHyperperiods(U32 ticks) {
    const U32 period = Session::hyperperiod();
    return ((ticks + period - 1) / period) * period;
}

struct Axis {
    const char* name;
    U32 points;  //!< loads 0, step, ..., (points - 1) x step
    bool burst;
};
// The slice axis in steps fine enough to place the knee within a tenth of
// the fastest group's period
const Axis AXES[] = {
    {"slice", 21, false},
    {"burst", 9, true},
};
constexpr U32 NO_BREAK = 0xFFFFFFFFu;

//! An axis' levels and the load's pace along it
struct Shape {
    U32 stepUs;
    U32 messages;  //!< per burst (burst axis), else 0
    U32 every;     //!< calls of the load's port per slice or burst (Load.SET_PACE)
};

// The top of every axis: twice the deployment's fastest group's period
U32 topUs() {
    return 2U * RATE_GROUPS[0].divisor * TICK_US;
}

// An axis' shape from the period of the rate group driving its load (its
// port's calls counted over its first point). At the top the load's work
// stays within half of the calls' time: past it the load is more than the
// CPU, every model overflows the load's queue, and the axis would measure
// that queue, not the scheduling (measured: tests/team/Thermal, a 40 ms slice each
// 20 ms, dropped 289 messages in its rtos build). So a burst has as many
// messages as fit, up to BURST_MESSAGES_MAX, and a load that does not fit
// with one is paced: one slice or burst each `every` calls. The reference
// deployment's loads (2 ms each 10 ms, 8 x 2 ms each 100 ms) fit unpaced.
Shape shapeOf(const Axis& axis, U32 periodUs) {
    const U32 top = topUs();
    U32 messages = 0;
    U32 workUs = top;
    if (axis.burst) {
        messages = periodUs / (2U * top);
        messages = (messages < 1U) ? 1U : ((messages > BURST_MESSAGES_MAX) ? BURST_MESSAGES_MAX : messages);
        workUs = messages * top;
    }
    const U32 every = (2U * workUs + periodUs - 1U) / periodUs;
    return {top / (axis.points - 1U), messages, (every < 1U) ? 1U : every};
}

Uplink::Frame loadCommand(const Axis& axis, const Shape& shape, U32 us) {
    const FwOpcodeType base = load.getIdBase();
    if (axis.burst) {
        return command(0, base + LoadIds::SET_BURST, Args().add(shape.messages).add(us));
    }
    return command(0, base + LoadIds::SET_SLICE, Args().add(us));
}

Uplink::Frame paceCommand(const Axis& axis, U32 every) {
    return command(0, load.getIdBase() + LoadIds::SET_PACE,
                   Args().add(axis.burst ? 1U : every).add(axis.burst ? every : 1U));
}

// The calls of an axis' load port so far
U32 loadCalls(const Axis& axis) {
    return axis.burst ? load.bursts() : load.slices();
}

// Where health's warning would first fire along an axis: the first level at
// which a ping waited its warning deadline, and the longest wait on the axis
struct HealthOnAxis {
    bool reached;
    U32 level;
    U32 worst;
};

// Sweep one axis; false if a load command was not accepted. Its first
// point (no work) counts the calls of the axis' load port over its measured
// segment: their period shapes the other points (shapeOf).
bool sweep(const Axis& axis, U32 breakUs[], HealthOnAxis& health) {
    bool commanded = true;
    health = {false, 0, 0};
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        breakUs[i] = NO_BREAK;
    }
    const U32 settleTicks = wholeHyperperiods(SETTLE_TICKS_MIN);
    const U32 measureTicks = wholeHyperperiods(MEASURE_TICKS_MIN);
    Shape shape = {0, axis.burst ? BURST_MESSAGES_MAX : 0U, 1};
    for (U32 point = 0; point < axis.points; point++) {
        const U32 us = point * shape.stepUs;
        // The pace goes up with the first point that has work
        Uplink::Frame frames[] = {loadCommand(axis, shape, us), paceCommand(axis, shape.every)};
        const FwSizeType framesPlayed = (point == 1 && shape.every != 1U) ? 2 : 1;
        uplink.play(frames, framesPlayed);
        Session::run(settleTicks);
        for (FwSizeType f = 0; f < framesPlayed; f++) {
            commanded = commanded && frames[f].asExpected();
        }
        Session::nextSegment();
        Report::startHealthSegment();
        const U32 processedBefore = load.processed();
        const U32 droppedBefore = load.dropped();
        const U32 callsBefore = loadCalls(axis);
        Session::run(measureTicks);
        bool broke[RATE_GROUP_COUNT] = {};
        const Report::SweepPoint measured = {axis.name,
                                             point,
                                             us,
                                             "us",
                                             shape.messages,
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
        if (point == 0) {
            const U32 calls = loadCalls(axis) - callsBefore;
            if (calls == 0) {
                printk(
                    "KIT ERROR axis=%s: no call of the load's %s in %u ticks: the topology must wire it to a rate "
                    "group (docs/your-deployment.md)\n",
                    axis.name, axis.burst ? "burstIn" : "sliceIn", static_cast<unsigned>(measureTicks));
                commanded = false;
                break;
            }
            shape = shapeOf(axis, measureTicks * TICK_US / calls);
            printk("KIT AXIS name=%s period_us=%u step_us=%u top_us=%u burst=%u every=%u\n", axis.name,
                   static_cast<unsigned>(measureTicks * TICK_US / calls), static_cast<unsigned>(shape.stepUs),
                   static_cast<unsigned>(shape.stepUs * (axis.points - 1U)), static_cast<unsigned>(shape.messages),
                   static_cast<unsigned>(shape.every));
        }
    }
    // Back to no load, and the load unpaced, before the next axis
    Uplink::Frame idle[] = {loadCommand(axis, shape, 0), paceCommand(axis, 1)};
    const FwSizeType idlePlayed = (shape.every != 1U) ? 2 : 1;
    uplink.play(idle, idlePlayed);
    Session::run(settleTicks);
    Session::nextSegment();
    for (FwSizeType f = 0; f < idlePlayed; f++) {
        commanded = commanded && idle[f].asExpected();
    }
    return commanded;
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
