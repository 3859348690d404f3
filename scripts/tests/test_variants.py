# SPDX-License-Identifier: Apache-2.0
"""Every list of the variants agrees with their one table (app/variants.yaml):
the twister suites hold each variant once with the table's Kconfig settings,
Kconfig derives the table's names, the scenario suite has expectations for
each; and every command that takes a variant takes all of them. A drift
would otherwise show minutes into a twister run, or not at all (a variant
left out of a suite is never tested)."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest
import yaml

from kittools import cli, variants
from kittools.workspace import KIT_ROOT, VARIANTS, KitError

#: Each suite and the prefix of its one entry per variant (<prefix><variant>);
#: its other entries (a scenario, a footprint profile) name their variant as
#: one of their dot-separated parts
SUITES = {KIT_ROOT / "app" / "sample.yaml": "kit.",
          KIT_ROOT / "tests" / "deployment" / "testcase.yaml": "kit.",
          KIT_ROOT / "tests" / "boards" / "testcase.yaml": "board."}
SCENARIO_SUITE = KIT_ROOT / "tests" / "deployment" / "pytest" / "test_scenarios.py"


def _settings(test: dict) -> list[str]:
    """A suite entry's Kconfig settings: its extra_configs, and its extra_args
    that are CMake's -DCONFIG_... (without the -D)."""
    args = test.get("extra_args", [])
    args = args.split() if isinstance(args, str) else args
    return list(test.get("extra_configs", [])) + [a for a in args if a.startswith("CONFIG_")]


def _symbol(setting: str) -> str:
    return setting.split("=", 1)[0]


def drift(suite: dict, prefix: str, table: dict[str, variants.Variant]) -> list[str]:
    """What a suite's entries say against the table: [] when they agree."""
    # The symbols that make a variant: an entry's settings of these are its variant's
    variant_symbols = {_symbol(s) for v in table.values() for s in v.kconfig}
    problems = []
    own = {name.removeprefix(prefix) for name in suite["tests"] if name.startswith(prefix) and name.count(".") == 1}
    problems += [f"no entry {prefix}{name}" for name in sorted(set(table) - own)]
    for name, test in suite["tests"].items():
        named = [part for part in name.split(".") if part in table]
        if len(named) != 1:
            problems.append(f"{name}: names {len(named)} variants of the table ({', '.join(named)}), not one")
            continue
        made_by = sorted(s for s in _settings(test) + _settings(suite.get("common", {}))
                         if _symbol(s) in variant_symbols)
        if made_by != sorted(table[named[0]].kconfig):
            problems.append(f"{name}: {made_by}, the table's {named[0]}: {sorted(table[named[0]].kconfig)}")
    return problems


@pytest.mark.parametrize("path", SUITES, ids=lambda p: str(p.relative_to(KIT_ROOT)))
def test_every_suite_holds_the_tables_variants_with_its_settings(path: Path):
    assert drift(yaml.safe_load(path.read_text()), SUITES[path], variants.table()) == []


def test_a_drift_is_found():
    table = variants.table()
    good = {"tests": {f"kit.{name}": {"extra_args": list(v.kconfig)} for name, v in table.items()}}
    assert drift(good, "kit.", table) == []
    missing = {"tests": {k: v for k, v in good["tests"].items() if k != "kit.rtos"}}
    assert drift(missing, "kit.", table) == ["no entry kit.rtos"]
    extra = {"tests": {**good["tests"], "kit.superloop": {"extra_args": ["CONFIG_KIT_MODEL_SUPERLOOP=y"]}}}
    assert drift(extra, "kit.", table) == ["kit.superloop: names 0 variants of the table (), not one"]
    other = {"tests": {**good["tests"], "kit.baremetal_passive.load": {"extra_args": [
        "CONFIG_KIT_MODEL_BAREMETAL=y", "CONFIG_KIT_BAREMETAL_POLICY_BUDGETED=y", "CONFIG_KIT_SCENARIO_LOAD=y"]}}}
    assert len(drift(other, "kit.", table)) == 1


def _variant_names_of_kconfig() -> tuple[dict[str, str], list[tuple[str, str]]]:
    """What Kconfig derives CONFIG_KIT_VARIANT_NAME from: each model's own
    name (its KIT_MODEL_NAME default), and the models' `default "<name>" if
    <SYMBOL>` of KIT_VARIANT_NAME, in the order Kconfig reads them (app/Kconfig
    sources the models' before its own default, the model's name)."""
    model_names: dict[str, str] = {}
    policies: list[tuple[str, str]] = []
    for model in VARIANTS:
        text = (KIT_ROOT / model / "Kconfig.model").read_text()
        model_names[model] = re.search(r'^config KIT_MODEL_NAME\n\tdefault "(\w+)"', text, re.MULTILINE).group(1)
        block = re.search(r"^config KIT_VARIANT_NAME\n((?:\t.*\n)+)", text, re.MULTILINE)
        if block:
            policies += re.findall(r'^\tdefault "(\w+)" if (\w+)$', block.group(1), re.MULTILINE)
    return model_names, policies


def test_the_tables_names_are_those_kconfig_derives():
    # The firmware prints CONFIG_KIT_VARIANT_NAME in its banner and results:
    # a table name Kconfig does not derive would never be found in a run
    model_names, policies = _variant_names_of_kconfig()
    for name, variant in variants.table().items():
        on = {_symbol(s).removeprefix("CONFIG_") for s in variant.kconfig if s.endswith("=y")}
        derived = next((policy for policy, symbol in policies if symbol in on), model_names[variant.model])
        assert derived == name, f"{name}: Kconfig names a build of {list(variant.kconfig)} {derived}"
    # and every name Kconfig can derive is a variant of the table
    assert set(model_names.values()) | {policy for policy, _ in policies} == set(variants.names())


def test_every_model_is_a_variant_and_every_variant_has_a_model():
    assert {v.model for v in variants.table().values()} == set(VARIANTS)
    assert set(VARIANTS) <= set(variants.names())


def test_the_scenario_suite_has_expectations_for_every_variant():
    tree = ast.parse(SCENARIO_SUITE.read_text())
    expected = next(node.value for node in tree.body if isinstance(node, ast.AnnAssign)
                    and isinstance(node.target, ast.Name) and node.target.id == "EXPECTED")
    assert isinstance(expected, ast.Dict)
    keys = {key.value for key in expected.keys if isinstance(key, ast.Constant)}
    assert keys == set(variants.names())


def test_a_bad_table_is_one_clear_error(tmp_path: Path):
    path = tmp_path / "variants.yaml"
    path.write_text("variants:\n  two:\n    kconfig: [CONFIG_KIT_MODEL_RTOS=y, CONFIG_KIT_MODEL_BAREMETAL=y]\n")
    with pytest.raises(KitError, match="picks 2 models"):
        variants.table(path)
    path.write_text("variants:\n  other:\n    kconfig: [CONFIG_KIT_MODEL_SUPERLOOP=y]\n")
    with pytest.raises(KitError, match="no model superloop"):
        variants.table(path)


def test_a_policy_variant_has_its_models_service_knobs():
    assert variants.get("baremetal_passive").model == "baremetal"
    assert variants.get("baremetal_budgeted").cmake_args() == [
        "-DCONFIG_KIT_MODEL_BAREMETAL=y", "-DCONFIG_KIT_BAREMETAL_POLICY_BUDGETED=y"]


@pytest.mark.parametrize("command", [["gds"], ["serial-sweep"], ["footprint"], ["test"], ["sizediff", "a", "b"]])
def test_every_command_takes_every_variant_under_one_option(command: list[str]):
    for name in variants.names():
        assert cli.parser().parse_args([*command, "--model", name]).model in (name, [name])
    option = next(a for a in _subparser(command[0])._actions if "--model" in a.option_strings)
    assert tuple(option.choices) == variants.names()
    assert all(v.description in option.help for v in variants.table().values())


def _subparser(name: str):
    top = cli.parser()
    sub = next(a for a in top._actions if a.dest == "command")
    return sub.choices[name]
