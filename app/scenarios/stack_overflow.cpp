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
#include "app/Top/GeneratedIds.hpp"
#include "app/Top/KitTopology.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/Fatal.hpp"
#include "app/src/Session.hpp"

#include <zephyr/sys/printk.h>

namespace Kit {
namespace Scenario {

namespace {
constexpr U32 RUN_TICKS = 1000;
// More than any stack of the deployment holds (the largest is 2 KiB); the
// recursion's frames carry some overhead on top, so the overflow passes the
// guard by a few hundred bytes and stays well short of 2x
constexpr U32 OVERFLOW_BYTES = 2048;
}  // namespace

bool run(const Context& context) {
    (void)context;
    Uplink::Frame script[] = {
        noOpFrame(2),
        command(4, faults.getIdBase() + FaultsIds::STACK_OVERFLOW, Args().add(OVERFLOW_BYTES)),
        noOpFrame(6),
    };
    Fatal::expect();
    uplink.play(script, FW_NUM_ARRAY_ELEMENTS(script));
    Session::run(RUN_TICKS);
    printk("KIT STACKFAULT undetected: the run went on after a %u-byte overflow\n",
           static_cast<unsigned>(OVERFLOW_BYTES));
    return false;
}

}  // namespace Scenario
}  // namespace Kit
