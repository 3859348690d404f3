# SPDX-License-Identifier: Apache-2.0
"""The repository's layout agrees with itself: every execution model and
scenario the Kconfig choices offer has its files, and the twister files ask
only for scenarios that exist (a mismatch would otherwise show as a Kconfig
error in one twister configuration, minutes into a run; their variants are
checked in test_variants.py)."""

from __future__ import annotations

import re

import yaml

from kittools.workspace import KIT_ROOT, VARIANTS

MODEL_FILES = ("Kconfig.model", "model.cmake", "Variant.cpp")


def _choice_entries(kconfig: str, prefix: str) -> set[str]:
    return {m.lower() for m in re.findall(rf"^config {prefix}(\w+)$", kconfig, re.MULTILINE)}


def test_every_model_folder_has_its_files_and_its_choice_entry():
    assert VARIANTS == ("baremetal", "rtos")
    for model in VARIANTS:
        folder = KIT_ROOT / model
        for name in MODEL_FILES:
            assert (folder / name).is_file(), f"{model}/{name} is missing"
        kconfig = (folder / "Kconfig.model").read_text()
        assert f"config KIT_MODEL_{model.upper()}\n" in kconfig
        assert f'default "{model}"' in kconfig  # KIT_MODEL_NAME: the folder the build includes


SCENARIOS_DIR = KIT_ROOT / "app" / "scenarios"
#: The file of app/scenarios/ that lists and chooses the others
CHOOSER = "Scenarios"


def _scenario_sources() -> set[str]:
    return {p.stem for p in SCENARIOS_DIR.glob("*.cpp")} - {CHOOSER}


def test_every_scenario_choice_has_its_source_and_back():
    kconfig = (SCENARIOS_DIR / "Kconfig").read_text()
    choices = _choice_entries(kconfig, "KIT_SCENARIO_") - {"at_boot"}
    sources = _scenario_sources()
    assert choices == sources
    for name in sources:
        assert f'default "{name}" if KIT_SCENARIO_{name.upper()}' in kconfig


def test_the_boot_choice_lists_every_scenario_and_the_suite_plays_them():
    table = set(re.findall(r'\{"(\w+)", play\w+\}', (SCENARIOS_DIR / f"{CHOOSER}.cpp").read_text()))
    assert table == _scenario_sources()
    suite = (KIT_ROOT / "tests" / "deployment" / "pytest" / "test_scenarios.py").read_text()
    played = set(re.findall(r'"(\w+)"', re.search(r"^SCENARIOS = \((.*)\)$", suite, re.MULTILINE).group(1)))
    # Every scenario but the ground link's, which `kit test` plays with fprime-gds
    assert played == table - {"ground"}


def test_twister_files_choose_only_existing_scenarios():
    # Their variants are checked against the table: test_variants.py
    scenarios = _scenario_sources() | {"at_boot"}
    for path in (KIT_ROOT / "app" / "sample.yaml", KIT_ROOT / "tests" / "deployment" / "testcase.yaml",
                 KIT_ROOT / "tests" / "boards" / "testcase.yaml"):
        for name, test in yaml.safe_load(path.read_text())["tests"].items():
            # Kconfig settings as extra_configs, or as extra_args (CMake's -DCONFIG_...)
            args = test.get("extra_args", [])
            configs = test.get("extra_configs", []) + [
                a for a in (args.split() if isinstance(args, str) else args) if a.startswith("CONFIG_")]
            for config in configs:
                if config.startswith("CONFIG_KIT_SCENARIO_"):
                    scenario = config.removeprefix("CONFIG_KIT_SCENARIO_").removesuffix("=y").lower()
                    assert scenario in scenarios, f"{path.name} {name}: no scenario {scenario}"


def test_every_board_folder_has_what_the_build_checks():
    for board in (KIT_ROOT / "boards").iterdir():
        for name in ("kit.conf", "Kconfig.defconfig", "app.overlay"):  # Tables.fpp: an optional override
            assert (board / name).is_file(), f"boards/{board.name}/{name} is missing"


def test_board_fragments_hold_only_zephyrs_own_symbols():
    # boards/<board>/kit.conf is also the configuration of tests/floor, plain
    # Zephyr applications without the kit's Kconfig: a kit or F´ symbol there
    # would stop their configure
    for conf in (KIT_ROOT / "boards").glob("*/kit.conf"):
        kit_symbols = re.findall(r"^\s*(CONFIG_(?:KIT|FW|FPRIME)_\w+)", conf.read_text(), re.MULTILINE)
        assert not kit_symbols, f"{conf.relative_to(KIT_ROOT)} sets {kit_symbols}: put them in Kconfig.defconfig"


def test_the_floor_the_tick_and_the_suite_run_on_the_same_boards():
    def platforms(path):
        return yaml.safe_load(path.read_text())["common"]["platform_allow"]

    suite = platforms(KIT_ROOT / "tests" / "deployment" / "testcase.yaml")
    others = [*(KIT_ROOT / "tests" / "floor").glob("*/testcase.yaml"),
              *(KIT_ROOT / "tests" / "tick").glob("*/testcase.yaml")]
    assert others
    for other in others:
        assert platforms(other) == suite, f"{other.relative_to(KIT_ROOT)} runs on other boards than the suite"


def test_kit_compare_leaves_out_exactly_the_profile_builds():
    from kittools.commands import compare
    from kittools.suite import results

    suite = yaml.safe_load((KIT_ROOT / "tests" / "deployment" / "testcase.yaml").read_text())
    for name, test in suite["tests"].items():
        tagged = compare.PROFILE_TAG in str(test.get("tags", "")).split()
        assert tagged == name.startswith(results.PROFILE_PREFIX), name
