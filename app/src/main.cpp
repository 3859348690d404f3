// ======================================================================
// \title  main.cpp
// \brief  The kit's entry point, shared by both variants
//
// Boot banner, topology setup, the tick loop, then one report of what every
// rate group, the uplink and the downlink did. Nothing prints between the
// banner and the report: printing while sampling disturbs what is measured.
// ======================================================================
#include <Os/Os.hpp>

#include "app/Components/Timing/TickClock.hpp"
#include "app/Top/KitTopology.hpp"
#include "app/src/CountingAllocator.hpp"
#include "app/src/HeapMonitor.hpp"
#include "app/src/Report.hpp"
#include "app/src/TickControl.hpp"
#include "app/src/Variant.hpp"

#include <zephyr/kernel.h>

namespace {

constexpr U32 PROBE_CALIBRATION_PAIRS = 64;

Kit::CountingAllocator s_allocator;

void runTicks(U32 ticks) {
    const U32 periodUs = 1000000u / CONFIG_KIT_TICK_HZ;
    U32 handled = 0;
    Kit::TickControl::start(periodUs);
    // A run of CONFIG_KIT_RUN_TICKS == 0 never ends (flight-like); otherwise
    // the loop is bounded by the tick count.
    while (ticks == 0 || handled < ticks) {
        Kit::Variant::waitForTick(handled);
        const U32 fired = Kit::TickClock::ticksFired();
        // Hand over every tick that fired, in order: a main loop that fell
        // behind shows up as latency and slips, never as lost cycles.
        while (handled != fired && (ticks == 0 || handled < ticks)) {
            Kit::timing.tick();
            handled++;
            Kit::Variant::afterTick();
        }
    }
    Kit::TickControl::stop();
    Kit::Variant::drain();
}

}  // namespace

int main() {
    Kit::Report::banner(Kit::Variant::name());
    Kit::Variant::prepareStacks();
    Os::init();
    s_allocator.registerForFprime();
    Kit::TopologyState state;
    Kit::setupTopology(state);
    Kit::HeapMonitor::markInitialized();
    // The probe's own cost, measured before the run so it does not disturb it
    const U32 probeCost = Kit::timing.measureProbeCost(PROBE_CALIBRATION_PAIRS);
    runTicks(CONFIG_KIT_RUN_TICKS);
    // The run's length from its tick count: a counter difference would wrap
    // after 2^32 cycles (358 s at 12 MHz)
    const U64 runCycles =
        static_cast<U64>(CONFIG_KIT_RUN_TICKS) * (Kit::TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);
    const bool passed = Kit::Report::results(CONFIG_KIT_RUN_TICKS, probeCost, s_allocator);
    Kit::Variant::reportStacks();
    Kit::Variant::reportCpu(runCycles);
    Kit::Report::end(Kit::Variant::name(), passed);
    return 0;
}
