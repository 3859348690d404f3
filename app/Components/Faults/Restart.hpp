// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Restart.hpp
// \brief  The processor's warm restart, for the Faults component
//
// On a target: Zephyr's sys_reboot(SYS_REBOOT_WARM) (app/src/Restart.cpp),
// a reset that leaves RAM as it was. In the host tests: a count
// (test/ut/FakeRestart.cpp).
// ======================================================================
#ifndef KIT_RESTART_HPP
#define KIT_RESTART_HPP

namespace Kit {
namespace Restart {

//! Restarts the processor, RAM kept; does not return on a target
void warm();

}  // namespace Restart
}  // namespace Kit

#endif
