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

namespace Kit {
namespace Report {

void banner(const char* variant);

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

//! DOWNLINK and TICKS lines; true when every packet was decoded and counted
bool downlinkAndTicks();

void end(const char* variant, bool passed);

}  // namespace Report
}  // namespace Kit

#endif
