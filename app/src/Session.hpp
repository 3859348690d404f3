// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Session.hpp
// \brief  Run the deployment for a number of ticks: the one main loop both
//         variants share, split into segments a scenario can measure apart
// ======================================================================
#ifndef KIT_SESSION_HPP
#define KIT_SESSION_HPP

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {
namespace Session {

//! Ticks after which every rate group is back at its phase of tick 0 (the
//! least common multiple of the dividers). A segment that is followed by
//! another must last a whole number of them.
U32 hyperperiod();

//! Start the tick, hand every tick that fires to the rate group driver until
//! `ticks` were handled (0: forever), stop the tick and let queued work
//! finish. The timing records then hold this segment (see nextSegment()).
void run(U32 ticks);

//! Run the tick, as run(0) does, until `until()` holds at the end of a
//! hyperperiod (it is asked once per hyperperiod, from the main loop); then
//! stop the tick and let queued work finish, as run() does. The ground
//! scenario serves the link this way between the segments it measures.
void serve(bool (*until)());

//! Empty the timing records for the next segment (see Timing::restart)
void nextSegment();

//! Counter cycles `ticks` ticks last
U64 cyclesOf(U32 ticks);

}  // namespace Session
}  // namespace Kit

#endif
