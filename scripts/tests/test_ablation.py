# SPDX-License-Identifier: Apache-2.0
import re

from kittools.sizes import ablation
from kittools.workspace import KIT_ROOT


def test_knobs_are_the_switches_two_profiles_differ_in_and_every_other_assert_level():
    kit = {"CONFIG_FPRIME": "y", "CONFIG_FPRIME_ASSERT_RELATIVE_PATH": "y", "CONFIG_FPRIME_COM_BUFFER_MAX_SIZE": "128",
           "CONFIG_FPRIME_CMD_STRING_MAX_SIZE": "40"}
    default = {"CONFIG_FPRIME": "y", "CONFIG_FPRIME_ASSERT_FILE_NAME": "y", "CONFIG_FPRIME_OBJECT_NAMES": "y",
               "CONFIG_FPRIME_COM_BUFFER_MAX_SIZE": "512", "CONFIG_FPRIME_CMD_STRING_MAX_SIZE": "40"}
    found = ablation.knobs(kit, default, "rtos")
    assert [k.name for k in found] == [
        "profile", "asserts: none", "asserts: file_id", "asserts: file_name",
        "com_buffer_max_size: 128 -> 512", "object_names: n -> y"]
    assert [k.name for k in ablation.knobs(kit, default, "baremetal")[-2:]] == [
        "telemetry store: TlmChan -> TlmLinearChan", "command dispatcher: CommandDispatcher -> PassiveCmdDispatcher"]
    # A policy that selects a service's other form already (baremetal_passive's dispatcher) has no knob for it
    passive = {"CONFIG_KIT_MODEL_BAREMETAL": "y", "CONFIG_KIT_CMD_DISPATCHER_PASSIVE": "y"}
    assert [k.name for k in ablation.knobs(kit, default, "baremetal", passive)[-1:]] == [
        "telemetry store: TlmChan -> TlmLinearChan"]
    assert found[1].settings == ("CONFIG_FPRIME_ASSERT_NONE=y",)
    assert found[-1].settings == ("CONFIG_FPRIME_OBJECT_NAMES=y",)


def test_every_profile_sets_only_switches_of_modules_fprime():
    kconfig = (KIT_ROOT / "modules" / "fprime" / "Kconfig").read_text()
    symbols = set(re.findall(r"^config (FPRIME_\w+)$", kconfig, re.MULTILINE))
    assert {"fprime-default", "fprime-kit"} <= set(ablation.profiles())
    for profile in ablation.profiles():
        conf = ablation.SNIPPETS / profile / f"{profile}.conf"
        assigned = re.findall(r"^CONFIG_(\w+)=", conf.read_text(), re.MULTILINE)
        assert set(assigned) <= symbols, f"{conf}: {set(assigned) - symbols} are not modules/fprime switches"


def test_the_table_says_what_each_knob_cost_and_broke(tmp_path):
    base = ablation.Row("profile", [], built=True, passed=True, rom=1000, ram=500,
                        rom_layers={"F´ framework": 600}, ram_layers={"F´ framework": 300})
    names = ablation.Row("object_names: n -> y", ["CONFIG_FPRIME_OBJECT_NAMES=y"], built=True, passed=False,
                         rom=1400, ram=900, rom_layers={"F´ framework": 1000}, ram_layers={"F´ framework": 700},
                         note="HEAP failures=3")
    broken = ablation.Row("com_buffer_max_size: 128 -> 512", [], built=False, note="build failed")
    found = ablation.table([base, names, broken], "qemu_cortex_m3", "rtos", "fprime-kit", "fprime-default")
    assert found.rows[1] == ["object_names: n -> y", 1400, "+400", 900, "+400",
                             "ROM F´ framework +400; RAM F´ framework +400", "FAIL: HEAP failures=3"]
    assert found.rows[2][-2:] == ["", "build failed: build failed"]
    ablation.write_report([found], tmp_path)
    assert "| object_names: n -> y | 1,400 | +400 |" in (tmp_path / "report.md").read_text()
