# SPDX-License-Identifier: Apache-2.0
"""The commands docs/your-deployment.md gives are the tools' own: each
`scripts/kit` line parses with the kit's CLI and names a deployment the seam
takes, each `west build` line sets only options the kit has, and the whole
run the page promises is the one CI makes (kit test's second deployment)."""

from __future__ import annotations

import re
import shlex

import pytest

from kittools import cli, deployment
from kittools.commands import test as test_command
from kittools.workspace import KIT_ROOT

PAGE = KIT_ROOT / "docs" / "your-deployment.md"
#: What the page's placeholders stand for: the deployment CI measures (a deployment in
#: a team's own F´ project, tests/team), and one of its builds
PLACEHOLDERS = {"<folder>": "tests/team/Thermal", "<project>/MyDeployment": "tests/team/Thermal",
                "<a build folder of it>": "build/compare-Thermal"}
FENCE = re.compile(r"^```[a-z]*\n(.*?)^```", re.MULTILINE | re.DOTALL)


#: The walk from fprime-util's template (its own test below): a deployment CI makes in a scratch project
WALK = "fprime-util new --deployment"


def _commands(prefix: str) -> list[list[str]]:
    found = []
    for block in FENCE.findall(PAGE.read_text()):
        if WALK in block:
            continue
        for line in block.splitlines():
            for placeholder, value in PLACEHOLDERS.items():
                line = line.replace(placeholder, value)
            if line.startswith(prefix):
                found.append(shlex.split(line))
    return found


KIT_COMMANDS = _commands("scripts/kit ")
WEST_BUILDS = _commands("west build -b ")
#: west kit, in the workspace of a repository that imports the kit: run from
#: that repository, which holds the deployment (tests/team in CI)
WEST_KIT_COMMANDS = _commands("west kit ")


def test_the_page_gives_commands():
    assert len(KIT_COMMANDS) >= 5 and WEST_BUILDS and len(WEST_KIT_COMMANDS) >= 2


@pytest.mark.parametrize("words", KIT_COMMANDS, ids=lambda words: " ".join(words[1:3]))
def test_each_kit_command_parses_and_its_deployment_passes_the_seam(words: list[str]):
    args = cli.parser().parse_args(words[1:])
    if getattr(args, "deployment", None):
        assert deployment.resolve(KIT_ROOT / args.deployment).name == args.deployment


def _kconfig_symbols() -> set[str]:
    files = [*KIT_ROOT.glob("app/Kconfig*"), *KIT_ROOT.glob("*/Kconfig.model"), *KIT_ROOT.glob("app/scenarios/Kconfig")]
    return {m.group(1) for f in files for m in re.finditer(r"^\s*(?:menu)?config\s+(\w+)", f.read_text(), re.MULTILINE)}


@pytest.mark.parametrize("words", WEST_BUILDS, ids=lambda words: " ".join(words[2:4]))
def test_each_west_build_sets_only_options_the_kit_has(words: list[str]):
    cache = (KIT_ROOT / "app" / "kit.cmake").read_text()
    for word in words[words.index("--") + 1:]:
        name, _, value = word.removeprefix("-D").partition("=")
        if name.startswith("CONFIG_"):
            assert name.removeprefix("CONFIG_") in _kconfig_symbols(), name
        else:
            assert f"set({name} " in cache and "CACHE" in cache, name
            deployment.resolve(KIT_ROOT / value)


def test_the_whole_run_the_page_promises_is_the_one_ci_makes():
    """kit test's second deployment is `kit test --deployment tests/team/Thermal`."""
    runs = [words for words in KIT_COMMANDS if words[1] == "test" and "--deployment" in words]
    assert runs, "the page gives no kit test --deployment"
    assert KIT_ROOT / PLACEHOLDERS["<folder>"] == test_command.SECOND_DEPLOYMENT


@pytest.mark.parametrize("words", WEST_KIT_COMMANDS, ids=lambda words: " ".join(words[2:4]))
def test_each_west_kit_command_parses_and_names_a_deployment_of_the_importing_repository(words: list[str]):
    args = cli.parser().parse_args(words[2:])
    if getattr(args, "deployment", None):
        # The page's MyDeployment is tests/team's Thermal
        deployment.resolve(KIT_ROOT / "tests" / "team" / args.deployment.replace("MyDeployment", "Thermal"))


def test_the_importing_manifest_on_the_page_is_the_one_ci_makes():
    """The page's west.yml imports the kit as kittools.suite.imported does."""
    import yaml

    from kittools.suite import imported

    page = next(block for block in re.findall(r"^```yaml\n(.*?)^```", PAGE.read_text(), re.MULTILINE | re.DOTALL))
    shown = yaml.safe_load(page)["manifest"]
    made = yaml.safe_load(imported.manifest("url", "revision"))["manifest"]
    assert shown["self"] == made["self"]
    (kit,) = shown["projects"]
    keys = ("name", "path", "import")
    assert {k: kit[k] for k in keys} == {k: made["projects"][0][k] for k in keys}


def test_the_walk_from_fprime_utils_template_is_the_one_ci_runs():
    """The page's walk: fprime-util's wizard, then the kit's commands CI's
    new-deployment step runs (kittools.suite.template_deployment)."""
    from kittools.suite import template_deployment

    (block,) = [block for block in FENCE.findall(PAGE.read_text()) if WALK in block]
    lines = [shlex.split(line.split("#", 1)[0]) for line in block.splitlines() if line.strip()]
    assert lines[0] == WALK.split()
    assert all(words[0] == "scripts/kit" for words in lines[1:])
    assert [words[1:] for words in lines[1:]] == list(template_deployment.walk(template_deployment.DEPLOYMENT).values())
    for words in lines[1:]:
        cli.parser().parse_args(words[1:])
