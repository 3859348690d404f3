// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Restart.cpp
// \brief  The processor's warm restart: Zephyr's sys_reboot
//
// On Cortex-M both kinds of sys_reboot are the core's system reset request
// (NVIC_SystemReset): the processor and its peripherals restart, RAM keeps
// its contents, and the start-up code loads .data and clears .bss again,
// but not .noinit, where the RAM file system lives (app/src/RamFs.cpp).
// Under QEMU the machine's reset does the same. The boot after it plays the
// scenario this one played (a build that asks the console for one at boot
// would otherwise wait for an answer nobody sends).
// ======================================================================
#include "app/Components/Faults/Restart.hpp"

#include <zephyr/sys/reboot.h>
#include "app/scenarios/Scenario.hpp"

namespace Kit {
namespace Restart {

void warm() {
    Scenario::resumeAfterRestart();
    sys_reboot(SYS_REBOOT_WARM);
}

}  // namespace Restart
}  // namespace Kit
