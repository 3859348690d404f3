# SPDX-License-Identifier: Apache-2.0
import re

import pytest

from kittools.sizes import ablation
from kittools.workspace import KIT_ROOT, KitError


def test_knobs_are_the_switches_two_profiles_differ_in_and_every_other_assert_level():
    kit = {"CONFIG_FPRIME": "y", "CONFIG_FPRIME_ASSERT_RELATIVE_PATH": "y", "CONFIG_FPRIME_COM_BUFFER_MAX_SIZE": "128",
           "CONFIG_FPRIME_CMD_STRING_MAX_SIZE": "40"}
    default = {"CONFIG_FPRIME": "y", "CONFIG_FPRIME_ASSERT_FILE_NAME": "y", "CONFIG_FPRIME_OBJECT_NAMES": "y",
               "CONFIG_FPRIME_COM_BUFFER_MAX_SIZE": "512", "CONFIG_FPRIME_CMD_STRING_MAX_SIZE": "40"}
    found = ablation.knobs(kit, default, "rtos")
    compilers = [k.name for k in ablation.COMPILER_KNOBS]  # no build given: every one
    assert [k.name for k in found] == [
        "profile", "asserts: none", "asserts: file_id", "asserts: file_name",
        "com_buffer_max_size: 128 -> 512", "object_names: n -> y", *compilers]
    assert [k.name for k in ablation.knobs(kit, default, "baremetal")[-2 - len(compilers):-len(compilers)]] == [
        "telemetry store: TlmChan -> TlmLinearChan", "command dispatcher: CommandDispatcher -> PassiveCmdDispatcher"]
    # A policy that selects a service's other form already (baremetal_passive's dispatcher) has no knob for it
    passive = {"CONFIG_KIT_MODEL_BAREMETAL": "y", "CONFIG_KIT_CMD_DISPATCHER_PASSIVE": "y"}
    assert [k.name for k in ablation.knobs(kit, default, "baremetal", passive)
            if k not in ablation.COMPILER_KNOBS][-1:] == ["telemetry store: TlmChan -> TlmLinearChan"]
    assert found[1].settings == ("CONFIG_FPRIME_ASSERT_NONE=y",)
    assert found[5].settings == ("CONFIG_FPRIME_OBJECT_NAMES=y",)


def test_a_knob_that_takes_heap_grows_the_profile_builds_arena():
    """TlmLinearChan's table comes out of the heap: its build's arena is the
    profile build's (a board sizes it to what its runs use) plus the table's."""
    built = {"CONFIG_KIT_MODEL_BAREMETAL": "y", "CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE": "16512"}
    linear = next(k for k in ablation.knobs({}, {}, "baremetal", built) if "TlmLinearChan" in k.name)
    assert linear.settings == ("CONFIG_KIT_TELEMETRY_LINEAR=y",
                               f"CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE={16512 + linear.heap_bytes}")
    # No build to read: the knob as it is
    assert next(k for k in ablation.knobs({}, {}, "baremetal") if "TlmLinearChan" in k.name).settings == (
        "CONFIG_KIT_TELEMETRY_LINEAR=y",)


def test_the_compiler_knobs_move_what_the_kit_sets():
    """Each compiler knob moves an option off the model's own choice: LTO is on
    in the baremetal model (baremetal/Kconfig.model), so its knob there turns it
    off; rtos has none, so its knob turns it on; the optimization knobs leave -Os."""
    model = (KIT_ROOT / "baremetal" / "Kconfig.model").read_text()
    assert all(re.search(rf"config {name}\n\tdefault y", model) for name in ("LTO", "ISR_TABLES_LOCAL_DECLARATION"))
    assert 'config COMPILER_OPT\n\tdefault "-fconserve-stack"' in model
    kit = {"CONFIG_FPRIME_ASSERT_RELATIVE_PATH": "y"}
    baremetal = {"CONFIG_LTO": "y", "CONFIG_ISR_TABLES_LOCAL_DECLARATION": "y",
                 "CONFIG_COMPILER_OPT": "-fconserve-stack"}
    names = [k.name for k in ablation.knobs(kit, kit, "baremetal", baremetal)]
    assert "link-time optimization: on -> off" in names and "link-time optimization: off -> on" not in names
    rtos = {"CONFIG_COMPILER_OPT": ""}
    names = [k.name for k in ablation.knobs(kit, kit, "rtos", rtos)]
    assert "link-time optimization: off -> on" in names and "link-time optimization: on -> off" not in names
    assert "-fconserve-stack: on -> off" not in names


def test_the_table_says_what_each_knob_cost_and_broke(tmp_path):
    base = ablation.Row("profile", [], built=True, passed=True, rom=1000, ram=500,
                        rom_layers={"F´ framework": 600}, ram_layers={"F´ framework": 300})
    names = ablation.Row("object_names: n -> y", ["CONFIG_FPRIME_OBJECT_NAMES=y"], built=True, passed=False,
                         rom=1400, ram=900, rom_layers={"F´ framework": 1000}, ram_layers={"F´ framework": 700},
                         note="HEAP failures=3")
    broken = ablation.Row("com_buffer_max_size: 128 -> 512", [], built=False, note="build failed")
    found = ablation.table([base, names, broken], "qemu_cortex_m3", "rtos", "fprime-kit", "fprime-default")
    assert found.rows[1] == ["object_names: n -> y", 1400, "+400", 900, "+400", "", "",
                             "ROM F´ framework +400; RAM F´ framework +400", "FAIL: HEAP failures=3"]
    assert found.rows[2][-2:] == ["", "build failed: build failed"]
    ablation.write_report([found], tmp_path)
    assert "| object_names: n -> y | 1,400 | +400 |" in (tmp_path / "report.md").read_text()


def test_a_nominal_run_gives_its_verdict_and_the_fastest_rate_groups_latency():
    passed = ("KIT RG name=rg10Hz hz=10 latency_p50=900 latency_max=950\n"
              "KIT RG name=rg1kHz hz=1000 latency_min=107 latency_p50=111 latency_p99=2047 latency_max=2819\n"
              "KIT END variant=rtos result=PASS uptime_ms=2009\n")
    assert ablation.nominal_outcome(passed) == (True, "", {"p50": 111, "max": 2819})
    # Any deployment's fastest group, by its rate (tests/team/Thermal's 50 Hz)
    thermal = ("KIT RG name=rg1Hz hz=1 latency_p50=30 latency_max=40\n"
               "KIT RG name=rg50Hz hz=50 latency_p50=20 latency_max=25\n"
               "KIT END variant=rtos result=PASS uptime_ms=2009\n")
    assert ablation.nominal_outcome(thermal) == (True, "", {"p50": 20, "max": 25})
    halted = "KIT HALT reason=stack_overflow code=2 context=main expected=no\nPROJECT EXECUTION FAILED\n"
    assert ablation.nominal_outcome(halted) == (
        False, "HALT reason=stack_overflow code=2 context=main expected=no", {})
    assert ablation.nominal_outcome("") == (False, "no END PASS", {})


def test_a_knob_filter_keeps_the_profile_and_the_knobs_it_names():
    plan = [ablation.Knob("profile"), ablation.Knob("asserts: none"), *ablation.COMPILER_KNOBS]
    assert ablation.chosen(plan, []) == plan
    assert [k.name for k in ablation.chosen(plan, ["OPTIMIZATION"])] == [
        "profile", "link-time optimization: on -> off", "link-time optimization: off -> on",
        "optimization: -Os -> -O2", "optimization: -Os -> -Og"]
    assert [k.name for k in ablation.chosen(plan, ["stack"])] == ["profile", "-fconserve-stack: on -> off"]
    with pytest.raises(KitError, match="no knob matches 'nothing'; the knobs are: asserts: none; link-time"):
        ablation.chosen(plan, ["nothing"])


def test_a_knob_kconfig_did_not_take_is_named_with_what_it_got():
    # Kconfig keeps a value a symbol's dependencies or another default force,
    # and only warns: such a build is the profile again, not the knob
    config = {"CONFIG_LTO": "y", "CONFIG_COMPILER_OPT": "", "CONFIG_SPEED_OPTIMIZATIONS": "y"}
    assert ablation.not_taken(("CONFIG_LTO=n", "CONFIG_ISR_TABLES_LOCAL_DECLARATION=n"), config) == [
        "CONFIG_LTO=n (got y)"]
    assert ablation.not_taken(('CONFIG_COMPILER_OPT=""', "CONFIG_SPEED_OPTIMIZATIONS=y"), config) == []
    assert ablation.not_taken(('CONFIG_COMPILER_OPT="-fconserve-stack"',), config) == [
        'CONFIG_COMPILER_OPT="-fconserve-stack" (got )']
