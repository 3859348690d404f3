// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TickControl.hpp
// \brief  Start and stop the board tick (see TickClock.hpp for reading it)
// ======================================================================
#ifndef KIT_TICKCONTROL_HPP
#define KIT_TICKCONTROL_HPP

#include <Fw/FPrimeBasicTypes.hpp>

namespace Kit {
namespace TickControl {
void start(U32 periodUs);
void stop();
}  // namespace TickControl
}  // namespace Kit

#endif
