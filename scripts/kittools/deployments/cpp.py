# SPDX-License-Identifier: Apache-2.0
"""The seam's C++ files `kit new-deployment` writes (app/src/Deployment.hpp
gives what they define): the counts (Top/KitTopology.hpp), the rate table,
the active instances and the setup (Top/KitTopology.cpp), the stacks
(Top/ActiveStacks.hpp), from kittools.deployments.seam's plan."""

from __future__ import annotations

from fractions import Fraction

from kittools.deployments import fpp
from kittools.deployments.seam import Plan
from kittools.deployments.template import HOST_CLOCKS, Deployment


def _period(period: Fraction) -> tuple[int, int]:
    return period.numerator, period.denominator


def kit_topology_hpp(result: Plan) -> str:
    deployment = result.deployment
    guard = f"{deployment.name.upper()}_KITTOPOLOGY_HPP"
    groups = result.rate_group_names
    priorities = ", ".join(f"Priorities::{name}" for name in groups)
    dispatcher = deployment.patterns.get("command", "cmdDisp")
    health = next((index for index, group in enumerate(groups)
                   if any(member.endswith("health.Run") for member in result.members.get(group, []))), 0)
    return f"""// ======================================================================
// \\title  KitTopology.hpp
// \\brief  The {deployment.name} deployment's side of the kit's seam
//         (app/src/Deployment.hpp): its counts; its tables and setup are
//         KitTopology.cpp. Written by kit new-deployment.
// ======================================================================
#ifndef {guard}
#define {guard}

#include "app/src/ActiveForms.hpp"
#include "{deployment.include_root}/Top/{deployment.topology}TopologyAc.hpp"

namespace Kit {{

// The deployment's dispatcher, where the kit's code reads its IDs
using {deployment.cpp(dispatcher).rsplit("::", 1)[0]}::{deployment.cpp(dispatcher).rsplit("::", 1)[1]};

//! Rate groups, in the order of the rate group driver's outputs (their
//! table: KitTopology.cpp), and their priorities in the same order
constexpr FwIndexType RATE_GROUP_COUNT = {len(groups)};
constexpr FwTaskPriorityType RATE_GROUP_PRIORITIES[RATE_GROUP_COUNT] = {{{priorities}}};

//! The active instances: the rate groups in their active form, the
//! deployment's other tasks (its dispatcher is active in every model), and
//! the kit's load and comQueue
constexpr FwSizeType ACTIVE_INSTANCE_COUNT = {len(result.tasks) + 2} + activeRateGroups(RATE_GROUP_COUNT);

//! The group that runs health
constexpr FwIndexType HEALTH_RATE_GROUP = {health};

}}  // namespace Kit

// What the kit's code asks of a deployment, with these counts
#include "app/src/Deployment.hpp"

#endif
"""


def active_stacks_hpp(result: Plan) -> str:
    deployment = result.deployment
    guard = f"{deployment.name.upper()}_ACTIVESTACKS_HPP"
    groups = ", ".join(f"Stacks::{name}" for name in result.rate_group_names)
    tasks = ", ".join([stack for _, _, stack in result.tasks] + ["Stacks::load", "Stacks::comQueue"])
    return f"""// ======================================================================
// \\title  ActiveStacks.hpp
// \\brief  The stack of every active instance this build has, in
//         ACTIVE_INSTANCES' order (the rtos model gives each thread its
//         stack from it: rtos/ThreadStacks.cpp). Written by kit
//         new-deployment.
// ======================================================================
#ifndef {guard}
#define {guard}

#include "{deployment.include_root}/Top/KitTopology.hpp"

namespace Kit {{

constexpr FwSizeType ACTIVE_STACKS[] = {{
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    {groups},
#endif
    {tasks},
}};
constexpr FwSizeType ACTIVE_STACK_ENTRIES = sizeof(ACTIVE_STACKS) / sizeof(ACTIVE_STACKS[0]);
static_assert(ACTIVE_STACK_ENTRIES == ACTIVE_INSTANCE_COUNT, "ACTIVE_STACKS and ACTIVE_INSTANCES disagree");

}}  // namespace Kit

#endif
"""


def kit_topology_cpp(result: Plan) -> str:
    deployment = result.deployment
    ns = deployment.namespace
    fastest = deployment.rate_groups[0].name
    specs = []
    checks = []
    for index, group in enumerate(deployment.rate_groups):
        numerator, denominator = _period(group.period)
        specs.append(f'    {{"{group.name}", CONFIG_KIT_TICK_HZ * {numerator} / {denominator}, {index}}},')
        checks.append(f"static_assert((CONFIG_KIT_TICK_HZ * {numerator}) % {denominator} == 0, "
                      f'"the tick must divide into {group.name}\'s period");')
    rollover = " * ".join(f"(1ULL * CONFIG_KIT_TICK_HZ * {group.period.numerator} / {group.period.denominator})"
                          for group in deployment.rate_groups)
    groups = "\n".join(f'    {{"{name}", &{ns}::{name}, sizeof({ns}::{name}), &{ns}::{name}}},'
                       for name in result.rate_group_names)
    tasks = "\n".join(f'    {{"{result.task_name(qualified)}", &{cpp}, sizeof({cpp}), &{cpp}}},'
                      for qualified, cpp, _ in result.tasks)
    contexts = "\n".join(f"    {ns}::{name}.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));"
                         for name in result.rate_group_names)
    driver = next(instance for instance in deployment.own if instance.type == "Svc.RateGroupDriver")
    time = deployment.patterns.get("time")
    time_instance = deployment.instance(time) if time else None
    epoch = ""
    # OsTime counts from an epoch it is given: without one its time stays at
    # zero, and every event and channel carries the same time. The host's
    # clocks become OsTime (adapt.py), so theirs is set too.
    if time is not None and time_instance is not None and time_instance.type in ("Svc.OsTime", *HOST_CLOCKS):
        epoch = (f"    // Time starts at zero at boot\n    Os::RawTime now;\n    (void)now.now();\n"
                 f"    {deployment.cpp(time)}.set_epoch(Fw::Time(0, 0), now);\n")
    sequencers = "".join(f"    // The sequencer's buffer, from F´'s allocator (the template's size)\n"
                         f"    {cpp}.allocateBuffer(0, state.allocator, {size});\n"
                         for cpp, size in result.sequencers.items())
    parameter_files = "".join(
        f"    // F´'s FileHandling names its parameter file \"PrmDb.dat\" (its phase code), a name the kit's RAM\n"
        f"    // file system (MicroFs: /bin<b>/file<n>) has not: the database reads and saves the kit's instead\n"
        f"    {deployment.cpp(instance.qualified)}.configure(RamFs::parameterFile);\n"
        for instance in fixed_parameter_files(deployment))
    free_sequencers = "".join(f"    {cpp}.deallocateBuffer(state.allocator);\n" for cpp in result.sequencers)
    events = deployment.cpp(deployment.patterns.get("event", "events"))
    dispatcher = deployment.cpp(deployment.patterns.get("command", "cmdDisp"))
    return f"""// ======================================================================
// \\title  KitTopology.cpp
// \\brief  The {deployment.name} deployment's tables and setup, for the kit
//         (app/src/Deployment.hpp). Written by kit new-deployment from the
//         template's {deployment.name}Topology.cpp, whose host timer, driver
//         and clock the kit's tick, link and time replace.
// ======================================================================
#include "{deployment.include_root}/Top/KitTopology.hpp"
#include <Fw/Types/Assert.hpp>
#include <Os/RawTime.hpp>
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Subtopologies/GroundLink/GroundLink.hpp"
#include "app/src/RamFs.hpp"
#include "app/src/ServiceIds.hpp"

namespace Kit {{

// The one place the deployment's rates are declared: the rate group driver
// and the kit's timing probe both take them from here (the template's host
// timer interval times its divisors). Offsets keep the slower groups off
// the ticks where the faster ones start.
const RateGroupSpec RATE_GROUPS[RATE_GROUP_COUNT] = {{
{chr(10).join(specs)}
}};
{chr(10).join(checks)}
// F´'s rate group driver multiplies the divisors into its rollover count
static_assert({rollover} <=
                  static_cast<unsigned long long>(static_cast<FwSizeType>(-1)),
              "the rate groups' divisors overflow F´'s RateGroupDriver rollover (FwSizeType)");

const ActiveInstance ACTIVE_INSTANCES[ACTIVE_INSTANCE_COUNT] = {{
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
{groups}
#endif
{tasks}
    {{"load", &load, sizeof(load), &load}},
    {{"comQueue", &comQueue, sizeof(comQueue), &comQueue}},
}};

namespace {{

// Members per rate group: the ports of the rate group class the build chose
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
constexpr FwIndexType RATE_GROUP_PORTS = PassiveRateGroupOutputPorts;
#else
constexpr FwIndexType RATE_GROUP_PORTS = Svc::ActiveRateGroup::CONNECTION_COUNT_MAX;
#endif

void configureTopology(const TopologyState& state) {{
    Svc::RateGroupDriver::DividerSet dividers;
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {{
        dividers.dividers[i] = {{RATE_GROUPS[i].divisor, RATE_GROUPS[i].offset}};
    }}
    {deployment.cpp(driver.qualified)}.configure(dividers);
    timing.configure(RATE_GROUPS, RATE_GROUP_COUNT, TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);

    // Contexts are unused by the members; a rate group wants one per port
    U32 contexts[RATE_GROUP_PORTS] = {{}};
{contexts}

{epoch}{parameter_files}{sequencers}
    GroundLink::configure(state.allocator, {"true" if result.file_uplink else "false"}, {events});
}}

}}  // namespace

FwOpcodeType noOpOpcode() {{
    return {dispatcher}.getIdBase() + CmdDispIds::NO_OP;
}}

void setupTopology(const TopologyState& state) {{
    // The kit breaks the fastest group's dispatch into stages: its queue and
    // task know themselves by lying inside it
    Stages::watch(&{ns}::{fastest}, sizeof({ns}::{fastest}));
    {ns}::initComponents(state);
    {ns}::setBaseIds();
    {ns}::connectComponents();
    {ns}::regCommands();
    {ns}::configComponents(state);
    configureTopology(state);
    {ns}::loadParameters();
    {ns}::startTasks(state);
}}

void teardownTopology(const TopologyState& state) {{
    {ns}::stopTasks(state);
    {ns}::freeThreads(state);
{free_sequencers}    {ns}::tearDownComponents(state);
    GroundLink::cleanup();
}}

}}  // namespace Kit
"""


def fixed_parameter_files(deployment: Deployment) -> list[fpp.Instance]:
    """The parameter databases of F´'s FileHandling subtopology, whose phase
    code names their file "PrmDb.dat": the kit configures them again, after
    that phase and before the parameters load, with Kit.RamFs.parameterFile.
    A deployment's own databases are configured by its own code."""
    return [instance for instance in deployment.subtopologies.get("FileHandling", []) if instance.type == "Svc.PrmDb"]
