// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  nominal.cpp
// \brief  The comparison run: the deployment at its nominal load for
//         CONFIG_KIT_RUN_TICKS ticks, with a short command script
// ======================================================================
#include "Top/KitTopology.hpp"
#include "app/Subtopologies/Instruments/InstrumentIds.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/Report.hpp"
#include "app/src/Session.hpp"

namespace Kit {
namespace Scenario {

namespace {
constexpr FwSizeType SCRIPT_FRAMES = 3;

// At 10 Hz cycle 2 a NO_OP, then two commands with an argument: dispatch,
// arguments and events are all exercised, in any deployment. Built in
// its own frame, gone before the run: on baremetal the main stack is every
// task's.
__attribute__((noinline)) void buildScript(Uplink::Frame* const script) {
    // Commands with arguments every deployment has: the kit's load's,
    // setting the slice it already has (none), so the run is unchanged
    const FwOpcodeType setSlice = load.getIdBase() + LoadIds::SET_SLICE;
    script[0] = noOpFrame(2);
    script[1] = command(4, setSlice, Args().add(static_cast<U32>(0)));
    script[2] = command(8, setSlice, Args().add(static_cast<U32>(0)));
}
}  // namespace

bool playNominal(const Context& context) {
    Uplink::Frame* const script = scriptFrames(SCRIPT_FRAMES);
    buildScript(script);
    uplink.play(script, SCRIPT_FRAMES);
    Session::run(CONFIG_KIT_RUN_TICKS);

    const bool measured = Report::results(CONFIG_KIT_RUN_TICKS, context.probeCost, context.allocator);
    const bool commanded = Report::commands(script, SCRIPT_FRAMES);
    const bool downlinked = Report::downlinkAndTicks();
    const bool healthy = Report::health();
    Report::stacks();
    Report::queues();
    Report::cpu(Session::cyclesOf(CONFIG_KIT_RUN_TICKS));
    Report::schedule();
    return measured && commanded && downlinked && healthy;
}

}  // namespace Scenario
}  // namespace Kit
