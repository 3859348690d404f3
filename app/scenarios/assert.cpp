// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  assert.cpp
// \brief  An F´ assert, injected by command
//
// The assert must reach F´'s fatal path (AssertFatalAdapter prints file and
// line and raises a FATAL event; the kit's FatalHandler stops the system),
// and the run must end with the failure marker twister reads at once. If
// the scenario gets past the assert, the fatal path is broken: it FAILs.
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
constexpr U32 ASSERT_CODE = 42;  // travels as the assert's argument
}  // namespace

bool playAssert(const Context& context) {
    (void)context;
    Uplink::Frame script[] = {
        noOpFrame(2),
        command(4, faults.getIdBase() + FaultsIds::ASSERT, Args().add(ASSERT_CODE)),
    };
    Fatal::expect(K_ERR_KERNEL_PANIC);
    uplink.play(script, FW_NUM_ARRAY_ELEMENTS(script));
    Session::run(RUN_TICKS);
    printk("KIT ASSERTFAULT undetected: the run went on after an F´ assert\n");
    return false;
}

}  // namespace Scenario
}  // namespace Kit
