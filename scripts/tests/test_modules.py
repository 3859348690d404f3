# SPDX-License-Identifier: Apache-2.0
from kittools.sizes import by_layer, instances

# The reference's instances as FPP's topology headers declare them (app/Top's, app/Subtopologies')
KIT_TOPOLOGY_HEADER = """
namespace Kit {
  //! comQueue
  extern Svc::ComQueue comQueue;
}
namespace Kit {
  extern Zephyr::ZephyrUartDriver linkUart;
}
namespace Kit {
  extern Kit::LinkHealth linkHealth;
}
namespace Kit { extern Svc::Health health; }
namespace Kit { extern Svc::Version version; }
namespace Kit { extern Svc::PrmDb prmDb; }
namespace Kit { extern Svc::CmdSequencer cmdSeq; }
namespace Kit { extern Kit::Timing timing; }
namespace Kit { extern Kit::PingProbe eventsPing; }
namespace Kit { extern Kit::Controller controller; }
namespace Kit { extern Svc::TlmChan tlmSend; }
"""
KIT = by_layer.Deployment.of((), instances.of_header(KIT_TOPOLOGY_HEADER))


def _tree():
    return {"total_size": 100, "symbols": {"name": "Root", "children": [
        {"name": "ZEPHYR_BASE", "children": [{"name": "kernel", "children": [
            {"name": "sched.c", "identifier": "kernel/sched.c/z_thread_halt", "size": 10}]}]},
        {"name": "OUTPUT_DIR", "children": [
            {"name": "x", "identifier": "F-Prime/Svc/CmdDispatcher/CommandDispatcherComponentAc.cpp/f", "size": 20},
            {"name": "y", "identifier": "F-Prime/Fw/Types/SerializableAc.cpp/g", "size": 5},
            {"name": "z", "identifier": "app/Components/Monitor/MonitorComponentAc.cpp/h", "size": 7}]},
        {"name": "WORKSPACE", "children": [
            {"name": "a", "size": 3,
             "identifier": "deps/fprime-baremetal/fprime-baremetal/Os/TaskRunner/TaskRunner.cpp/r"},
            {"name": "b", "identifier": "rtos/Os/PriorityTask.cpp/s", "size": 2},
            {"name": "c", "identifier": "newlib/libc/tinystdio/vfprintf.c/vfprintf", "size": 30}]},
        {"name": "/", "children": [
            {"name": "d", "identifier": "/src/libstdc++-v3/libsupc++/eh_throw.cc", "size": 8},
            {"name": "e", "identifier": "/libgcc/libgcc2.c/__udivmoddi4", "size": 4}]},
        {"name": "(no paths)", "children": [
            {"name": "f", "identifier": ":/_GLOBAL__sub_I__ZN3Kit7cmdDispE", "size": 6},
            {"name": "g", "identifier": ":/CSWTCH.16", "size": 5}]},
    ]}}


def test_every_layer_is_recognised():
    sizes = by_layer.breakdown(_tree())
    assert sizes["Zephyr kernel, arch, drivers"] == 10
    assert sizes["F´ services"] == 20
    assert sizes["F´ framework"] == 5
    assert sizes["kit deployment and components"] == 7 + 6  # path, then namespace of a path-less symbol
    assert sizes["OS layer (fprime-baremetal / fprime-zephyr / kit)"] == 5
    assert sizes["libc (picolibc, libgcc)"] == 34
    assert sizes["libstdc++"] == 8
    assert sizes["unattributed"] == 5


def test_breakdown_accounts_for_every_byte():
    assert sum(by_layer.breakdown(_tree()).values()) == 100


def test_the_ground_link_is_its_own_layer():
    link = by_layer.GROUND_LINK
    # its components' code, by folder, generated or not
    assert by_layer.classify("F-Prime/Svc/ComQueue/ComQueueComponentAc.cpp/f", "OUTPUT_DIR") == link
    assert by_layer.classify("deps/fprime/Svc/FrameAccumulator/FrameAccumulator.cpp/f", "WORKSPACE") == link
    assert by_layer.classify("deps/fprime-zephyr/fprime-zephyr/Drv/ZephyrUartDriver/ZephyrUartDriver.cpp/f",
                            "WORKSPACE") == link
    # path-less: its vtables and its instances' objects (static RAM)
    assert by_layer.classify(":/_ZTVN3Svc8ComQueueE") == link
    assert by_layer.classify(":/_ZN3Kit8linkUartE", deployment=KIT) == link
    # ... not the kit's counters of it, an instrument like their code
    assert by_layer.classify(":/_ZN3Kit10linkHealthE", deployment=KIT) == by_layer.INSTRUMENTS
    # not the link: another instance, another service
    assert by_layer.classify(":/_ZN3Kit10controllerE", deployment=KIT) == by_layer.KIT
    dispatcher = "deps/fprime/Svc/CmdDispatcher/CommandDispatcherImpl.cpp/f"
    assert by_layer.classify(dispatcher, "WORKSPACE") == by_layer.SERVICES
    # The kit's telemetry store is F´'s service in another form, as TlmChan
    assert by_layer.classify("app/Components/TlmTable/TlmTable.cpp/f", "WORKSPACE") == by_layer.SERVICES
    assert by_layer.classify("app/Components/TlmTable/TlmTableComponentAc.cpp/f", "OUTPUT_DIR") == by_layer.SERVICES
    assert by_layer.instance_layer("Kit", "Kit::TlmTable") == by_layer.SERVICES
    assert by_layer.instance_layer("Kit", "Svc::TlmChan") == by_layer.SERVICES


def test_each_subtopology_and_the_instruments_are_layers_of_their_own():
    # CdhCore's health and version: code, vtables, instances
    health = by_layer.HEALTH_VERSION
    assert by_layer.classify("F-Prime/Svc/Health/HealthComponentAc.cpp/f", "OUTPUT_DIR") == health
    assert by_layer.classify(":/_ZTVN3Svc7VersionE") == health
    assert by_layer.classify(":/_ZN3Kit6healthE", deployment=KIT) == health
    # ... not the kit's LinkHealth, whose mangled name holds "Health"
    assert by_layer.classify(":/_ZN3Svc10LinkHealthC2Ev") != health
    # FileHandling: the parameter database, MicroFs and the kit's mount
    files = by_layer.FILE_HANDLING
    assert by_layer.classify("deps/fprime/Svc/PrmDb/PrmDbImpl.cpp/f", "WORKSPACE") == files
    assert by_layer.classify(":/_ZN3Kit5prmDbE", deployment=KIT) == files
    micro_fs = "deps/fprime-baremetal/fprime-baremetal/Os/Baremetal/MicroFs/MicroFs.cpp/f"
    assert by_layer.classify(micro_fs, "WORKSPACE") == files
    assert by_layer.classify("deps/fprime-baremetal/fprime-baremetal/Os/Baremetal/File.cpp/f", "WORKSPACE") == files
    assert by_layer.classify("app/src/RamFs.cpp/s_region", "WORKSPACE") == files
    # the command sequencer: its code and its instance
    assert by_layer.classify("deps/fprime/Svc/CmdSequencer/CmdSequencerImpl.cpp/f", "WORKSPACE") == by_layer.SEQUENCER
    assert by_layer.classify(":/_ZN3Kit6cmdSeqE", deployment=KIT) == by_layer.SEQUENCER
    # ... not fprime-baremetal's task
    task = "deps/fprime-baremetal/fprime-baremetal/Os/Baremetal/Task.cpp/f"
    assert by_layer.classify(task, "WORKSPACE") == by_layer.OS_LAYER
    # the kit's instruments: their code, their instances, the record
    instruments = by_layer.INSTRUMENTS
    assert by_layer.classify(":/_ZN3Kit6timingE", deployment=KIT) == instruments
    assert by_layer.classify(":/_ZN3Kit10eventsPingE", deployment=KIT) == instruments
    assert by_layer.classify("app/Components/Load/Load.cpp/f", "WORKSPACE") == instruments
    assert by_layer.classify("app/src/Report.cpp/f", "WORKSPACE") == instruments
    assert by_layer.classify("app/Components/Controller/Controller.cpp/f", "WORKSPACE") == by_layer.KIT


def test_a_size_report_is_made_again_only_for_another_image(tmp_path, monkeypatch):
    """Staleness is by the image's content: a relink into the same bytes (a
    configure's) keeps the reports, different bytes remake both, in one run
    of the size report (both kinds) with a fixed hash seed."""
    import json
    import os
    import subprocess

    elf = tmp_path / "zephyr" / "zephyr.elf"
    elf.parent.mkdir()
    elf.write_bytes(b"image 1")
    made = []

    def size_report(command, **kwargs):
        made.append((command[2], kwargs["env"]["PYTHONHASHSEED"]))
        for kind in ("rom", "ram"):
            (tmp_path / f"{kind}-symbols.json").write_text(json.dumps(_tree()))
        return subprocess.CompletedProcess(command, 0, "", "")

    monkeypatch.setattr(by_layer.subprocess, "run", size_report)
    assert by_layer.report(tmp_path, "rom")["total_size"] == 100
    by_layer.report(tmp_path, "ram")
    assert made == [("kittools.sizes.size_report", "0")]
    later = elf.stat().st_mtime + 60
    os.utime(elf, (later, later))  # relinked, same bytes
    by_layer.report(tmp_path, "rom")
    assert made == [("kittools.sizes.size_report", "0")]
    elf.write_bytes(b"image 2")
    by_layer.report(tmp_path, "ram")
    assert made == [("kittools.sizes.size_report", "0")] * 2


def test_the_size_report_places_a_path_in_zephyrs_groups():
    """The groups and identifiers of Zephyr's size_report tree: Zephyr's
    base before the build folder before the workspace, anything else by
    its absolute path, a symbol without a source file under "(no paths)"."""
    from pathlib import Path

    from kittools.sizes import size_report

    build = size_report.KIT_ROOT / "twister-out" / "b"
    groups = size_report._groups(build)
    assert size_report._place(size_report.DEPS / "zephyr" / "kernel" / "sched.c" / "f", groups) == (
        "ZEPHYR_BASE", "kernel/sched.c/f")
    assert size_report._place(build / "F-Prime" / "x.cpp" / "f", groups) == ("OUTPUT_DIR", "F-Prime/x.cpp/f")
    assert size_report._place(size_report.KIT_ROOT / "app" / "a.cpp" / "f", groups) == ("WORKSPACE", "app/a.cpp/f")
    assert size_report._place(Path("/usr/lib/gcc/x.c/f"), groups) == ("/", "/usr/lib/gcc/x.c/f")
    assert size_report._place(Path(":", "_ZTVN3Kit1AE"), groups) == ("(no paths)", ":/_ZTVN3Kit1AE")
    assert by_layer.classify(":/_ZTVN3Kit1AE", "(no paths)") == by_layer.KIT


def test_a_deployments_own_namespace_is_its_layer(tmp_path):
    """tests/team/Thermal's instances and components (namespace Thermal) are
    the deployment's, as the reference's (namespace Kit) are; the namespaces
    come from the build's dictionary, the kit's own module left out."""
    import json

    instance, component = "_ZN7Thermal6rg50HzE", "_ZTVN7Thermal13HeaterControlE"
    assert by_layer.classify(instance) == by_layer.UNATTRIBUTED
    assert by_layer.classify(instance, deployment=by_layer.Deployment(("Thermal",))) == by_layer.KIT
    assert by_layer.classify(component, deployment=by_layer.Deployment(("Thermal",))) == by_layer.KIT
    assert by_layer.classify("_ZN8Thermals1xE", deployment=by_layer.Deployment(("Thermal",))) == by_layer.UNATTRIBUTED
    dictionary = tmp_path / "build-artifacts" / "x" / "dict" / "ThermalTopologyDictionary.json"
    dictionary.parent.mkdir(parents=True)
    dictionary.write_text(json.dumps({
        "commands": [{"name": "Thermal.cmdDisp.CMD_NO_OP", "opcode": 1}, {"name": "Kit.load.SET_SLICE", "opcode": 2}],
        "telemetryChannels": [{"name": "Thermal.heaters.Duty"}], "events": []}))
    assert by_layer.deployment_of(tmp_path).namespaces == ("Thermal",)
    assert by_layer.deployment_of(tmp_path / "none") == by_layer.NO_DEPLOYMENT


def test_an_instance_is_its_subtopologys_wherever_it_is_defined():
    """An LTO build's instances get their source from the objects
    (kittools.sizes.definitions): the topology's code, which is not where
    their layer is."""
    topology = "app/Top/TopologyAc.cpp/"
    assert by_layer.classify(topology + "_ZN3Kit6cmdSeqE", "OUTPUT_DIR", KIT) == by_layer.SEQUENCER
    assert by_layer.classify(topology + "_ZN3Kit8linkUartE", "OUTPUT_DIR", KIT) == by_layer.GROUND_LINK
    assert by_layer.classify(topology + "_ZN3Kit10controllerE", "OUTPUT_DIR", KIT) == by_layer.KIT


def test_path_less_symbols_of_an_lto_build_are_placed_by_their_names():
    # LTO's one static constructor of every object: the instances'
    assert by_layer.classify(":/_sub_I_65535_0.0") == by_layer.KIT
    # a function's own statics
    assert by_layer.classify(":/_ZZN2Os9Baremetal10TaskRunner12getSingletonEvE6runner") == by_layer.OS_LAYER
    assert by_layer.classify(":/_ZZN2Os4Task12getSingletonEvE11s_singleton") == by_layer.FRAMEWORK
    # libgcc's helpers, which carry no DWARF
    assert by_layer.classify(":/__aeabi_dadd") == by_layer.LIBC
    assert by_layer.classify(":/__truncdfsf2") == by_layer.LIBC
    # Zephyr's C library heap
    assert by_layer.classify(":/malloc_arena") == by_layer.ZEPHYR


def test_an_instance_is_placed_by_its_component_type_whatever_its_name(tmp_path):
    """fprime-util's template names its instances in F´'s subtopologies'
    namespaces (CdhCore::health): their RAM is their subtopology's, as the
    reference's is, read from the build's topology headers."""
    header = tmp_path / "MyDeployment" / "Top" / "MyDeploymentTopologyAc.hpp"
    header.parent.mkdir(parents=True)
    header.write_text("""#ifndef X
namespace CdhCore {

  //! health
  extern Svc::Health health;

}

namespace CdhCore {
  extern Svc::CommandDispatcher cmdDisp;
}
struct Unrelated { int a; };
namespace FileHandling { extern Svc::PrmDb prmDb; }
namespace DataProducts { extern Svc::BufferManager dpBufferManager; }
namespace MyDeployment {
  namespace Inner {
    extern MyDeployment::Sensor sensor;
  }
  extern Svc::CmdSequencer cmdSeq;
}
#endif
""")
    deployment = by_layer.deployment_of(tmp_path)
    assert deployment.instances == {
        "_ZN7CdhCore6healthE": by_layer.HEALTH_VERSION,
        "_ZN7CdhCore7cmdDispE": by_layer.SERVICES,
        "_ZN12FileHandling5prmDbE": by_layer.FILE_HANDLING,
        "_ZN12DataProducts15dpBufferManagerE": by_layer.SERVICES,  # not the link's buffers
        "_ZN12MyDeployment5Inner6sensorE": by_layer.KIT,
        "_ZN12MyDeployment6cmdSeqE": by_layer.SEQUENCER,
    }
    assert by_layer.classify("MyDeployment/Top/TopAc.cpp/_ZN7CdhCore6healthE", "OUTPUT_DIR",
                             deployment) == by_layer.HEALTH_VERSION


def test_what_no_symbol_covers_is_a_layer_of_its_own():
    """size_report's "(hidden)": string literals, mostly (25 KB of
    fprime-util's template's rodata on mps2/an385), not a failure to place."""
    assert by_layer.classify("(hidden)", "(hidden)") == by_layer.NO_SYMBOL
    assert by_layer.classify(":/(hidden)", "(no paths)") == by_layer.UNATTRIBUTED


def test_fprime_baremetals_services_are_services_and_its_os_the_os_layer():
    dispatcher = "fprime-baremetal/Svc/PassiveCmdDispatcher/PassiveCmdDispatcherComponentAc.cpp/f"
    assert by_layer.classify(dispatcher, "OUTPUT_DIR") == by_layer.SERVICES
    source = "deps/fprime-baremetal/fprime-baremetal/Svc/PassiveCmdDispatcher/PassiveCmdDispatcher.cpp/f"
    assert by_layer.classify(source, "WORKSPACE") == by_layer.SERVICES
    task_runner = "deps/fprime-baremetal/fprime-baremetal/Os/TaskRunner/TaskRunner.cpp/r"
    assert by_layer.classify(task_runner, "WORKSPACE") == by_layer.OS_LAYER
