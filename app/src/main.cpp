// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  main.cpp
// \brief  The kit's entry point, shared by both variants
//
// The scenario to play (the build's, or the console's at boot: app/scenarios/
// Scenarios.cpp), boot banner, topology setup, the scenario, the end line. Nothing prints
// while a segment is measured: printing while sampling disturbs what is
// measured.
// ======================================================================
#include <Os/Os.hpp>

#include "Top/KitTopology.hpp"
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/scenarios/Scenario.hpp"
#include "app/src/CountingAllocator.hpp"
#include "app/src/HeapMonitor.hpp"
#include "app/src/RamFs.hpp"
#include "app/src/Report.hpp"
#include "app/src/Variant.hpp"

namespace {

constexpr U32 PROBE_CALIBRATION_PAIRS = 64;
constexpr U32 STAGE_CALIBRATION_DISPATCHES = 64;

Kit::CountingAllocator s_allocator;

}  // namespace

int main() {
    const Kit::Scenario::Play play = Kit::Scenario::choose();
    Kit::Report::banner();
    Kit::Variant::prepareStacks();
    Os::init();
    s_allocator.registerForFprime();
    Kit::Report::fileSystem(Kit::RamFs::mount());
    const Kit::TopologyState state = {s_allocator};
    Kit::setupTopology(state);
    Kit::HeapMonitor::markInitialized();
    // The probes' own cost, measured before the run so it does not disturb it
    Kit::Stages::calibrate(STAGE_CALIBRATION_DISPATCHES);
    const Kit::Scenario::Context context = {Kit::timing.measureProbeCost(PROBE_CALIBRATION_PAIRS), s_allocator};
    const bool passed = play(context);
    Kit::Report::end(passed);
    return 0;
}
