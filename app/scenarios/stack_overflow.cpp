// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  stack_overflow.cpp
// \brief  A stack overflow, injected by command: the command dispatcher's
//         context (its thread on rtos, the main stack on baremetal) uses
//         more stack than it has
//
// The run must end in a fatal report naming the overflow: Zephyr's stack
// sentinel (or MPU guard) on rtos, the kit's stack guard on baremetal. If
// the scenario gets past the overflow, nothing detected it: the run FAILs.
// ======================================================================
#include "Top/KitTopology.hpp"
#include "app/Subtopologies/Instruments/InstrumentIds.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/Fatal.hpp"
#include "app/src/Session.hpp"

#include <zephyr/fatal_types.h>
#include <zephyr/sys/printk.h>

namespace Kit {
namespace Scenario {

namespace {
constexpr U32 RUN_TICKS = 1000;
// As much as the largest stack of the deployment holds (2 KiB): on top of
// the handler's own depth and each frame's overhead, the recursion passes
// the bottom of the stack by several hundred bytes
constexpr U32 OVERFLOW_BYTES = 2048;
}  // namespace

bool playStackOverflow(const Context& context) {
    (void)context;
    Uplink::Frame script[] = {
        noOpFrame(2),
        command(4, faults.getIdBase() + FaultsIds::STACK_OVERFLOW, Args().add(OVERFLOW_BYTES)),
        noOpFrame(6),
    };
    Fatal::expect(K_ERR_STACK_CHK_FAIL);
    uplink.play(script, FW_NUM_ARRAY_ELEMENTS(script));
    Session::run(RUN_TICKS);
    printk("KIT STACKFAULT undetected: the run went on after a %u-byte overflow\n",
           static_cast<unsigned>(OVERFLOW_BYTES));
    return false;
}

}  // namespace Scenario
}  // namespace Kit
