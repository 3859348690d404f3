// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Report.cpp
// \brief  The console record of a run
// ======================================================================
#include "app/src/Report.hpp"
#include "KitDictionary.hpp"  // generated: app/dictionary_header.cmake
#include "Top/KitTopology.hpp"
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Subtopologies/GroundLink/GroundLink.hpp"
#include "app/src/HeapMonitor.hpp"
#include "app/src/RamFs.hpp"
#include "app/src/ServiceIds.hpp"
#include "app/src/Session.hpp"

#include <zephyr/device.h>
#include <zephyr/devicetree.h>
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>
#include <zephyr/sys/util.h>
#include <zephyr/version.h>

#if defined(CONFIG_INIT_STACKS)
// Zephyr's interrupt stack (kernel_internal.h declares it for the kernel)
K_KERNEL_STACK_ARRAY_DECLARE(z_interrupt_stacks, CONFIG_MP_MAX_NUM_CPUS, CONFIG_ISR_STACK_SIZE);
#endif

#ifndef CONFIG_QEMU_ICOUNT_SHIFT
#define CONFIG_QEMU_ICOUNT_SHIFT 0
#endif

namespace Kit {
namespace Report {

namespace {

const char* contextKindName(Variant::ContextKind kind) {
    return kind == Variant::ContextKind::THREAD ? "thread" : "slice";
}

// Twister's failure marker: a failed run fails its scenario at once instead
// of waiting for the time-out
void failureMarker() {
    printk("PROJECT EXECUTION FAILED\n");
}

U32 permille(U64 part, U64 whole) {
    return whole == 0 ? 0 : static_cast<U32>((part * 1000u) / whole);
}

const char* responseName(const Fw::CmdResponse& response) {
    switch (response.e) {
        case Fw::CmdResponse::OK:
            return "OK";
        case Fw::CmdResponse::INVALID_OPCODE:
            return "INVALID_OPCODE";
        case Fw::CmdResponse::VALIDATION_ERROR:
            return "VALIDATION_ERROR";
        case Fw::CmdResponse::FORMAT_ERROR:
            return "FORMAT_ERROR";
        case Fw::CmdResponse::EXECUTION_ERROR:
            return "EXECUTION_ERROR";
        case Fw::CmdResponse::BUSY:
            return "BUSY";
        default:
            return "UNKNOWN";
    }
}

void printHistogram(const char* rateGroup, const char* metric, const Histogram& histogram) {
    // Non-empty buckets as lower_bound:count, in cycles
    printk("KIT HIST rg=%s metric=%s buckets=", rateGroup, metric);
    bool first = true;
    for (U32 bucket = 0; bucket < Histogram::BUCKETS; bucket++) {
        if (histogram.count(bucket) == 0) {
            continue;
        }
        printk("%s%u:%u", first ? "" : ",", static_cast<unsigned>(Histogram::lowerBound(bucket)),
               static_cast<unsigned>(histogram.count(bucket)));
        first = false;
    }
    printk("\n");
}

void printStats(const char* name, const CycleStats& stats) {
    printk(" %s_min=%u %s_p50=%u %s_p99=%u %s_max=%u", name, static_cast<unsigned>(stats.min()), name,
           static_cast<unsigned>(stats.percentile(500)), name, static_cast<unsigned>(stats.percentile(990)), name,
           static_cast<unsigned>(stats.max()));
}

}  // namespace

void sweepPoint(const SweepPoint& point, bool broke[]) {
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        const RateGroupRecord& rg = timing.record(i);
        broke[i] = rg.slips > 0 || rg.lateStarts > 0;
        printk(
            "KIT SWEEP axis=%s point=%u level=%u unit=%s burst=%u rg=%s hz=%u cycles=%u expected=%u slips=%u "
            "late_starts=%u latency_p99=%u latency_max=%u jitter_p99=%u jitter_max=%u exec_max=%u load_runs=%u "
            "load_dropped=%u\n",
            point.axis, static_cast<unsigned>(point.point), static_cast<unsigned>(point.level), point.unit,
            static_cast<unsigned>(point.burst), rg.spec.name,
            static_cast<unsigned>(CONFIG_KIT_TICK_HZ / rg.spec.divisor), static_cast<unsigned>(rg.cycles),
            static_cast<unsigned>(expectedCycles(i, point.ticks)), static_cast<unsigned>(rg.slips),
            static_cast<unsigned>(rg.lateStarts), static_cast<unsigned>(rg.latency.percentile(990)),
            static_cast<unsigned>(rg.latency.max()), static_cast<unsigned>(rg.periodError.percentile(990)),
            static_cast<unsigned>(rg.periodError.max()), static_cast<unsigned>(rg.exec.max()),
            static_cast<unsigned>(point.loadRuns), static_cast<unsigned>(point.loadDropped));
    }
}

bool rateGroups(U32 ticks) {
    bool passed = true;
    const U64 runCycles = static_cast<U64>(ticks) * (TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        const RateGroupRecord& rg = timing.record(i);
        const U32 expected = expectedCycles(i, ticks);
        // A miss fails the run where the model is expected to hold its
        // deadlines on this board (CONFIG_KIT_DEADLINES_EXPECTED, app/Kconfig)
        const bool deadlinesOk = rg.slips == 0 || !IS_ENABLED(CONFIG_KIT_DEADLINES_EXPECTED);
        const bool ok = (ticks == 0 || rg.cycles == expected) && deadlinesOk && rg.lostStamps == 0 && !rg.running;
        passed = passed && ok;
        printk("KIT RG name=%s hz=%u cycles=%u expected=%u slips=%u late_starts=%u lost_stamps=%u", rg.spec.name,
               static_cast<unsigned>(CONFIG_KIT_TICK_HZ / rg.spec.divisor), static_cast<unsigned>(rg.cycles),
               static_cast<unsigned>(expected), static_cast<unsigned>(rg.slips), static_cast<unsigned>(rg.lateStarts),
               static_cast<unsigned>(rg.lostStamps));
        printStats("latency", rg.latency);
        printStats("exec", rg.exec);
        printStats("jitter", rg.periodError);
        printk(" period_min=%u period_max=%u\n", static_cast<unsigned>(rg.periodMin),
               static_cast<unsigned>(rg.periodMax));
        // Betaflight-style task line: runs, average and worst execution, late
        // starts, share of the CPU (per mille of the run)
        printk("KIT TASK name=%s context=%s runs=%u exec_avg=%u exec_max=%u late=%u cpu_permille=%u\n", rg.spec.name,
               contextKindName(Variant::contextKind()), static_cast<unsigned>(rg.cycles),
               static_cast<unsigned>(rg.exec.mean()), static_cast<unsigned>(rg.exec.max()),
               static_cast<unsigned>(rg.lateStarts), static_cast<unsigned>(permille(rg.exec.sum(), runCycles)));
        printHistogram(rg.spec.name, "latency", rg.latency.histogram());
        printHistogram(rg.spec.name, "exec", rg.exec.histogram());
        printHistogram(rg.spec.name, "jitter", rg.periodError.histogram());
    }
    return passed;
}

void banner() {
    printk(
        "KIT BANNER variant=%s board=%s kit=%s zephyr=%s/%s fprime=%s tick_hz=%u sys_tick_hz=%u "
        "cycles_hz=%u icount_shift=%u run_ticks=%u hyperperiod_ticks=%u timing_buckets=%u\n",
        CONFIG_KIT_VARIANT_NAME, CONFIG_BOARD_TARGET, KIT_GIT_SHA, KERNEL_VERSION_STRING, ZEPHYR_GIT_SHA,
        FPRIME_GIT_SHA, static_cast<unsigned>(CONFIG_KIT_TICK_HZ),
        static_cast<unsigned>(CONFIG_SYS_CLOCK_TICKS_PER_SEC), static_cast<unsigned>(TickClock::cyclesPerSecond()),
        static_cast<unsigned>(CONFIG_QEMU_ICOUNT_SHIFT), static_cast<unsigned>(CONFIG_KIT_RUN_TICKS),
        static_cast<unsigned>(Session::hyperperiod()), static_cast<unsigned>(1U << CONFIG_KIT_TIMING_SUB_BITS));
}

void linkReady() {
    // The dictionary id lets the ground refuse another build's dictionary
    // The line rate paces the ground tools' bytes; uart_errors says whether
    // the UART's receive errors can be counted on this board
    printk("KIT LINK ready uart=%s baud=%u uart_errors=%s dictionary=%s\n",
           DEVICE_DT_GET(DT_CHOSEN(kit_link_uart))->name, static_cast<unsigned>(GroundLink::baudRate()),
           GroundLink::uartErrorsReported() ? "reported" : "unsupported", KIT_DICTIONARY_ID);
}

void fileSystem(RamFs::Mount mount) {
#if defined(CONFIG_KIT_RAMFS)
    printk("KIT RAMFS mount=%s files=%u file_bytes=%u bulk_bytes=%u bytes=%u\n",
           mount == RamFs::Mount::KEPT ? "kept" : "formatted", static_cast<unsigned>(CONFIG_KIT_RAMFS_FILES),
           static_cast<unsigned>(CONFIG_KIT_RAMFS_FILE_SIZE), static_cast<unsigned>(CONFIG_KIT_RAMFS_BULK_FILE_SIZE),
           static_cast<unsigned>(RamFs::regionBytes()));
#else
    FW_ASSERT(mount == RamFs::Mount::ABSENT, static_cast<FwAssertArgType>(mount));
    printk("KIT RAMFS mount=absent\n");
#endif
}

bool commands(const Uplink::Frame* frames, FwSizeType count) {
    FW_ASSERT(frames != nullptr || count == 0);
    bool passed = true;
    for (FwSizeType i = 0; i < count; i++) {
        const Uplink::Frame& frame = frames[i];
        passed = passed && frame.asExpected();
        printk("KIT CMD frame=%u opcode=0x%x noop=%s response=%s expected=%s\n", static_cast<unsigned>(i),
               static_cast<unsigned>(frame.result.opcode), (frame.result.opcode == noOpOpcode()) ? "yes" : "no",
               frame.result.answered ? responseName(frame.result.response) : "NONE", responseName(frame.expected));
    }
    return passed;
}

bool downlinkAndTicks() {
    const FwEventIdType noOpEvent = cmdDisp.getIdBase() + CmdDispIds::NO_OP_RECEIVED;
    // Packets the link's queue had no room for: a result of the model (a
    // cooperative loop hands it a burst at once), not a failure of the run
    const FwEventIdType overflowEvent = comQueue.getIdBase() + ComQueueIds::QUEUE_OVERFLOW;
    printk("KIT DOWNLINK events=%u telemetry=%u malformed=%u noop_events=%u uncounted=%u queue_overflows=%u\n",
           static_cast<unsigned>(downlink.eventPackets()), static_cast<unsigned>(downlink.telemetryPackets()),
           static_cast<unsigned>(downlink.malformedPackets()), static_cast<unsigned>(downlink.eventCount(noOpEvent)),
           static_cast<unsigned>(downlink.uncountedEvents()),
           static_cast<unsigned>(downlink.eventCount(overflowEvent)));
    printk("KIT TICKS driven=%u fired=%u\n", static_cast<unsigned>(timing.ticksDriven()),
           static_cast<unsigned>(TickClock::ticksFired()));
    return downlink.malformedPackets() == 0 && downlink.uncountedEvents() == 0;
}

U32 pingWarnDeadline() {
#if defined(CONFIG_KIT_SERVICE_CDH)
    // Health pings each entry once per run of its rate group, and warns
    // when an answer has not come back by its WARN-th run after the ping
    return PING_WARN_CYCLES * RATE_GROUPS[HEALTH_RATE_GROUP].divisor *
           (TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);
#else
    return 0xFFFFFFFFu;
#endif
}

void startHealthSegment() {
#if defined(CONFIG_KIT_SERVICE_CDH)
    startPingSegment();
#endif
}

U32 sweepHealth(const SweepPoint& point) {
#if defined(CONFIG_KIT_SERVICE_CDH)
    const U32 now = TickClock::now();
    U32 worst = 0;
    FwIndexType worstEntry = 0;
    for (FwIndexType entry = 0; entry < PING_ENTRY_COUNT; entry++) {
        const U32 wait = pingProbe(entry).segmentWorst(now);
        if (wait > worst) {
            worst = wait;
            worstEntry = entry;
        }
    }
    printk("KIT SWEEPHEALTH axis=%s point=%u level=%u unit=%s ping_max=%u entry=%s warn=%u\n", point.axis,
           static_cast<unsigned>(point.point), static_cast<unsigned>(point.level), point.unit,
           static_cast<unsigned>(worst), pingEntryName(worstEntry), static_cast<unsigned>(pingWarnDeadline()));
    return worst;
#else
    (void)point;
    return 0;
#endif
}

void healthBreak(const char* axis, U32 level, bool reached, U32 worst) {
#if defined(CONFIG_KIT_SERVICE_CDH)
    if (reached) {
        printk("KIT HEALTHBREAK axis=%s level=%u ping_max=%u warn=%u\n", axis, static_cast<unsigned>(level),
               static_cast<unsigned>(worst), static_cast<unsigned>(pingWarnDeadline()));
    } else {
        printk("KIT HEALTHBREAK axis=%s level=none ping_max=%u warn=%u\n", axis, static_cast<unsigned>(worst),
               static_cast<unsigned>(pingWarnDeadline()));
    }
#else
    (void)level;
    (void)reached;
    (void)worst;
    printk("KIT HEALTHBREAK axis=%s services=absent\n", axis);
#endif
}

U32 healthWarnings() {
#if defined(CONFIG_KIT_SERVICE_CDH)
    return downlink.eventCount(Kit::health.getIdBase() + HealthIds::PING_WARN);
#else
    return 0;
#endif
}

bool health() {
#if !defined(CONFIG_KIT_SERVICE_CDH)
    // The board's profile leaves the services out for this model (its Kconfig.defconfig says why)
    printk("KIT HEALTH services=absent\n");
    return true;
#else
    const U32 warnCycles = pingWarnDeadline();
    bool answered = true;
    for (FwIndexType entry = 0; entry < PING_ENTRY_COUNT; entry++) {
        const PingProbe& probe = pingProbe(entry);
        const PingRoundTrips& trips = probe.roundTrips();
        answered = answered && trips.count() > 0;
        printk("KIT PING name=%s pings=%u held=%u p50=%u p99=%u max=%u warn=%u outstanding=%s deferred=%u\n",
               pingEntryName(entry), static_cast<unsigned>(trips.count()), static_cast<unsigned>(trips.held()),
               static_cast<unsigned>(trips.percentile(500)), static_cast<unsigned>(trips.percentile(990)),
               static_cast<unsigned>(trips.max()), static_cast<unsigned>(warnCycles),
               probe.outstanding() ? "yes" : "no", static_cast<unsigned>(probe.deferredPings()));
    }
    const FwEventIdType base = Kit::health.getIdBase();
    const U32 warnings = healthWarnings();
    const U32 fatals =
        downlink.eventCount(base + HealthIds::PING_LATE) + downlink.eventCount(base + HealthIds::PING_WRONG_KEY);
    printk("KIT HEALTH services=present entries=%u warnings=%u fatals=%u\n", static_cast<unsigned>(PING_ENTRY_COUNT),
           static_cast<unsigned>(warnings), static_cast<unsigned>(fatals));
    // Version reports at startup, once (Svc.Version's config(true))
    const FwEventIdType versionBase = version.getIdBase();
    const U32 framework = downlink.eventCount(versionBase + VersionIds::FRAMEWORK_VERSION);
    const U32 project = downlink.eventCount(versionBase + VersionIds::PROJECT_VERSION);
    printk("KIT VERSION framework_events=%u project_events=%u\n", static_cast<unsigned>(framework),
           static_cast<unsigned>(project));
    return answered && warnings == 0 && fatals == 0 && framework == 1 && project == 1;
#endif
}

bool heap(const CountingAllocator& allocator) {
    printk(
        "KIT HEAP fprime_peak=%u fprime_allocations=%u bytes=%u allocations=%u frees=%u after_init=%u "
        "failures=%u arena=%u arena_left=%u link_buffers=%u\n",
        static_cast<unsigned>(allocator.peakBytes()), static_cast<unsigned>(allocator.allocations()),
        static_cast<unsigned>(HeapMonitor::bytesRequested()), static_cast<unsigned>(HeapMonitor::allocations()),
        static_cast<unsigned>(HeapMonitor::frees()), static_cast<unsigned>(HeapMonitor::allocationsAfterInit()),
        static_cast<unsigned>(HeapMonitor::failures()), static_cast<unsigned>(CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE),
        static_cast<unsigned>(HeapMonitor::arenaLeft()), static_cast<unsigned>(GroundLink::bufferBytes()));
    return HeapMonitor::allocationsAfterInit() == 0 && HeapMonitor::failures() == 0;
}

void hash() {
    printk("KIT HASH samples=%u fnv=0x%08x\n", static_cast<unsigned>(timing.sampleHash().samples()),
           static_cast<unsigned>(timing.sampleHash().value()));
}

namespace {
void stages() {
    // The fastest group's dispatch, stage by stage, net of the marks' cost;
    // its latency line (KIT RG) is net of them too
    const DispatchStages& stages = Stages::stages();
    printk("KIT STAGES rg=%s complete=%u incomplete=%u marks=%u mark_cycles=%u\n", RATE_GROUPS[0].name,
           static_cast<unsigned>(stages.complete()), static_cast<unsigned>(stages.incomplete()),
           static_cast<unsigned>(stages.marks()), static_cast<unsigned>(stages.markCost()));
    for (U32 i = 0; i < stages.stageCount(); i++) {
        printk("KIT STAGE rg=%s name=%s", RATE_GROUPS[0].name, stages.stageName(i));
        printStats("cycles", stages.stage(i));
        printk("\n");
    }
}
}  // namespace

bool results(U32 ticks, U32 probeCost, const CountingAllocator& allocator) {
    const bool rgOk = rateGroups(ticks);
    if (IS_ENABLED(CONFIG_KIT_DISPATCH_STAGES)) {
        stages();
    }
    const bool heapOk = heap(allocator);
    hash();
    printk("KIT PROBE cycles_per_cycle=%u\n", static_cast<unsigned>(probeCost));
    return rgOk && heapOk;
}

const char* contextName(const Variant::Context& context) {
    const char* const instance = activeInstanceHolding(context.owner);
    if (instance != nullptr) {
        return instance;
    }
    return context.name != nullptr ? context.name : "?";
}

namespace {

void stackLine(const Variant::StackUse& use) {
    printk("KIT STACK name=%s size=%u used=%u\n", contextName(use.context), static_cast<unsigned>(use.size),
           static_cast<unsigned>(use.used));
}

// The interrupt stack, which every model has: painted at reset (Zephyr's
// reset.S, CONFIG_INIT_STACKS), used by the boot before main, by every
// interrupt since and by a fault's handler; where the paint ends is its
// high-water mark. A line of its own, not in stackUsedTotal(): the soak
// holds the contexts the model runs, and an interrupt's depth at a rare
// moment is not a leak.
void interruptStack() {
#if defined(CONFIG_INIT_STACKS)
    const U8* const bottom = reinterpret_cast<const U8*>(K_KERNEL_STACK_BUFFER(z_interrupt_stacks[0]));
    const U32 size = static_cast<U32>(K_KERNEL_STACK_SIZEOF(z_interrupt_stacks[0]));
    U32 unused = 0;
    while (unused < size && bottom[unused] == 0xAAu) {
        unused++;
    }
    stackLine({{"isr", nullptr}, size, size - unused});
#endif
}

}  // namespace

void stacks() {
    Variant::StackUse entries[Variant::MAX_CONTEXTS];
    const U32 count = Variant::stacks(entries);
    for (U32 i = 0; i < count; i++) {
        stackLine(entries[i]);
    }
    interruptStack();
}

void queues() {
    for (const ActiveInstance& instance : ACTIVE_INSTANCES) {
        const QueueUse use = queueUse(instance);
        printk("KIT QUEUE name=%s depth=%u slot_bytes=%u high_water=%u dropped=%u\n", instance.name,
               static_cast<unsigned>(use.depth), static_cast<unsigned>(use.slotBytes),
               static_cast<unsigned>(use.highWater), static_cast<unsigned>(use.dropped));
    }
}

U32 stackUsedTotal() {
    Variant::StackUse entries[Variant::MAX_CONTEXTS];
    const U32 count = Variant::stacks(entries);
    U32 total = 0;
    for (U32 i = 0; i < count; i++) {
        total += entries[i].used;
    }
    return total;
}

void cpu(U64 runCycles) {
    Variant::CpuUse entries[Variant::MAX_CONTEXTS];
    const U32 count = Variant::cpu(entries);
    const char* const kind = contextKindName(Variant::contextKind());
    for (U32 i = 0; i < count; i++) {
        const Variant::CpuUse& use = entries[i];
        printk("KIT CPU name=%s context=%s runs=%u avg=%u max=%u cpu_permille=%u\n", contextName(use.context),
               use.shared ? "shared" : kind, static_cast<unsigned>(use.runs), static_cast<unsigned>(use.avgCycles),
               static_cast<unsigned>(use.maxCycles), static_cast<unsigned>(permille(use.cycles, runCycles)));
    }
}

void schedule() {
    Variant::ScheduleUse entries[Variant::MAX_CONTEXTS];
    Variant::GuardMargin guard = {0, 0};
    const U32 count = Variant::schedule(entries, guard);
    for (U32 i = 0; i < count; i++) {
        const Variant::ScheduleUse& use = entries[i];
        printk("KIT SCHED name=%s critical=%s anticipated=%u deferrals=%u expedited=%u late=%u\n",
               contextName(use.context), use.critical ? "yes" : "no", static_cast<unsigned>(use.anticipatedCycles),
               static_cast<unsigned>(use.deferrals), static_cast<unsigned>(use.expedited),
               static_cast<unsigned>(use.late));
    }
    if (count > 0) {
        printk("KIT SCHED name=guard guard=%u guard_max=%u\n", static_cast<unsigned>(guard.cycles),
               static_cast<unsigned>(guard.maxCycles));
    }
}

void guardBreach(const Variant::GuardBreach& breach) {
    printk("KIT FATAL stack=%s guard_word=%u address=0x%08x: stack overflow\n", contextName(Variant::currentContext()),
           static_cast<unsigned>(breach.word), static_cast<unsigned>(breach.address));
}

void halt(const char* reasonName, unsigned int reason, bool expected) {
    // The halted context's stack and the interrupt stack, with their
    // high-water marks: the depth of the path that led here (an assert's
    // message, its FATAL event; a fault's handler runs on the interrupt
    // stack), which no run that ends reaches. The boards' stacks
    // (boards/<board>/Kconfig.defconfig) are sized from these lines; one
    // entry each, so that this report adds little to the depth it measures.
    stackLine(Variant::currentStack());
    interruptStack();
    printk("KIT HALT reason=%s code=%u context=%s expected=%s\n", reasonName, reason,
           contextName(Variant::currentContext()), expected ? "yes" : "no");
    if (!expected) {
        failureMarker();
    }
}

void end(bool passed) {
    printk("KIT END variant=%s result=%s uptime_ms=%u\n", CONFIG_KIT_VARIANT_NAME, passed ? "PASS" : "FAIL",
           static_cast<unsigned>(k_uptime_get_32()));
    if (!passed) {
        failureMarker();
    }
}

}  // namespace Report
}  // namespace Kit
