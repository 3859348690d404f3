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
#include "app/src/CountingAllocator.hpp"

namespace Kit {
namespace Report {

void banner(const char* variant);

//! Print the results of a run of `ticks` ticks; true when every check passed.
//! probeCost: the timing probe's cycles per rate-group cycle (start + end);
//! heap: F´'s allocator, whose use is reported.
bool results(U32 ticks, U32 probeCost, const CountingAllocator& heap);

void end(const char* variant, bool passed);

}  // namespace Report
}  // namespace Kit

#endif
