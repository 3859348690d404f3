// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Report.hpp
// \brief  The console record of a run: banner, per-rate-group results, end line
//
// One "KIT <KIND> key=value ..." line per record, so twister's console
// harness and scripts/kit parse the same text.
// ======================================================================
#ifndef KIT_REPORT_HPP
#define KIT_REPORT_HPP

#include <Fw/FPrimeBasicTypes.hpp>
#include "app/Components/Uplink/Uplink.hpp"
#include "app/src/CountingAllocator.hpp"
#include "app/src/RamFs.hpp"
#include "app/src/Variant.hpp"

namespace Kit {
namespace Report {

//! The BANNER line: the variant (CONFIG_KIT_VARIANT_NAME), the board, the
//! commits and the timing conditions, with the rate groups' hyperperiod
//! (a segment the ground asks for is a whole number of them)
void banner();

//! The LINK line: the ground link is up, on the board's link UART
void linkReady();

//! How the RAM file system was found at mount (KIT RAMFS)
void fileSystem(RamFs::Mount mount);

//! RG, TASK and HIST lines of every rate group over a segment of `ticks`
//! ticks; true when each ran exactly its cycles, without slips
bool rateGroups(U32 ticks);

//! The HEAP line; true when nothing was allocated after init and nothing failed
bool heap(const CountingAllocator& allocator);

//! The HASH line: every timing sample of the run, hashed (determinism check)
void hash();

//! A measured run's record: rateGroups(), heap(), the sample hash and the
//! probe's own cost (cycles per rate-group cycle); true when both passed
bool results(U32 ticks, U32 probeCost, const CountingAllocator& allocator);

//! A CMD line per uplinked frame; true when each was answered as expected
bool commands(const Uplink::Frame* frames, FwSizeType count);

//! One point of a sweep: the axis, its setting in its unit, the segment's
//! length and the background load's work in it
struct SweepPoint {
    const char* axis;
    U32 point;         //!< index along the axis
    U32 level;         //!< the axis' setting
    const char* unit;  //!< of the level: "us", "cmd/s", "pkt/s"
    U32 burst;         //!< messages per load burst (the burst axis), else 0
    U32 ticks;         //!< the measured segment
    U32 loadRuns;
    U32 loadDropped;
};
//! A SWEEP line per rate group over the segment just measured; broke[i]
//! tells whether group i missed a deadline in it
void sweepPoint(const SweepPoint& point, bool broke[]);
//! A PING line per health ping entry (its round trips, in counter cycles,
//! and health's warning deadline), a HEALTH line (the warnings and fatals
//! health's events reported) and a VERSION line (the version events that
//! reached the downlink); true when every entry was answered, none late
bool health();

//! Health's warnings (HLTH_PING_WARN) downlinked so far; 0 where the build
//! has no health
U32 healthWarnings();
//! Health's side of a load sweep (where the build has health): a segment
//! starts on every ping probe; sweepHealth() prints the segment's longest
//! wait for a ping's answer (SWEEPHEALTH) and returns its cycles;
//! healthBreak() prints the first level of an axis where that wait reached
//! health's warning deadline (HEALTHBREAK), or none
void startHealthSegment();
//! Health's warning deadline in counter cycles (never reached where the
//! build has no health)
U32 pingWarnDeadline();
U32 sweepHealth(const SweepPoint& point);
void healthBreak(const char* axis, U32 level, bool reached, U32 worst);
//! DOWNLINK and TICKS lines; true when every packet was decoded and counted
bool downlinkAndTicks();

//! A STACK line per stack of the model, with its high-water mark
void stacks();

//! A QUEUE line per active instance: its message queue's depth, bytes per
//! slot and high-water mark
void queues();

//! The model's stacks' high-water marks added up, in bytes
U32 stackUsedTotal();

//! A CPU line per execution context (thread, or cooperative task, and
//! idle): runs, average and worst cycles per run, share of `runCycles`
void cpu(U64 runCycles);

//! A SCHED line per context of a time-budgeted policy (its anticipated
//! slice, deferrals, expedited and late slices) and one for its guard
//! margin; nothing for a model that does not budget its work
void schedule();

//! The name of an execution context: the active instance whose object
//! holds its owner, else its own name
const char* contextName(const Variant::Context& context);

//! The FATAL line of a stack guard that lost its paint
void guardBreach(const Variant::GuardBreach& breach);

//! The HALT line of a fatal error (reason: K_ERR_*), in the running context
void halt(const char* reasonName, unsigned int reason, bool expected);

//! The END line (and twister's failure marker when the run failed)
void end(bool passed);

}  // namespace Report
}  // namespace Kit

#endif
