# SPDX-License-Identifier: Apache-2.0
"""The kit's YAML files edited as text, their comments and layout kept: a
new board joins the twister files' platform lists (suite_files: a QEMU board
the suites that run, a real board the boards built and not run), and a real
board's HAL joins west.yml's allow-list (allow_module)."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

from kittools.boards.zephyr import ZephyrBoard
from kittools.workspace import KitError

# Twister files whose platform lists name the kit's boards, relative to the kit
# The suite's, the kernel floor's (tests/floor/<app>/) and the samples'
TWISTER_GLOBS = ("tests/*/testcase.yaml", "tests/*/*/testcase.yaml", "app/sample.yaml")
TWISTER_LIST_KEYS = ("platform_allow", "integration_platforms")

#: Real boards: built for every model, not run (no emulator)
BUILD_ONLY_SUITE = "tests/boards/testcase.yaml"


def _item_name(item: str) -> str:
    """A list item as a name: no comment, no quotes."""
    return item.split(" #", 1)[0].strip().strip("'\"")


def _add_inline(rest: str, identifier: str) -> str:
    """A list written on the key's line: `[a, b]` or twister's `a b`; the
    spacing around it and its comment stay as they were."""
    value, hash_sign, comment = rest.partition(" #")
    lead, core, trail = re.fullmatch(r"(\s*)(.*?)(\s*)", value).groups()  # type: ignore[union-attr]
    if core.startswith("["):
        if not core.endswith("]"):
            return rest  # a flow list over several lines: left alone rather than mangled
        inner = core[1:-1].rstrip()
        if identifier in [_item_name(n) for n in inner.split(",")]:
            return rest
        core = f"[{inner}{', ' if inner.strip() else ''}{identifier}]"
    elif identifier in [_item_name(n) for n in core.split()]:
        return rest
    else:
        core = f"{core} {identifier}"
    return f"{lead}{core}{trail}{hash_sign}{comment}"


def add_to_twister_lists(text: str, identifier: str, keys: tuple[str, ...] = TWISTER_LIST_KEYS) -> str:
    """`identifier` added once to every list of `keys` (platform_allow and
    integration_platforms) of a twister file, editing the text so its
    comments and layout stay: a `- identifier` line after the list's last
    item, at its indentation."""
    key = re.compile(rf"^(?P<indent>[ \t]*)(?:{'|'.join(keys)}):(?P<rest>.*?)(?P<eol>\r?\n?)$")
    lines = text.splitlines(keepends=True)
    out: list[str] = []
    index = 0
    while index < len(lines):
        match = key.match(lines[index])
        index += 1
        if match is None:
            out.append(lines[index - 1])
            continue
        rest = match.group("rest")
        if rest.split(" #", 1)[0].strip():
            out.append(lines[index - 1][:match.start("rest")] + _add_inline(rest, identifier) + match.group("eol"))
            continue
        out.append(lines[index - 1])
        # The block list: its items, and the comments and blank lines between them
        item_indent: str | None = None
        block: list[str] = []
        last_item = -1
        while index < len(lines):
            line = lines[index]
            item = re.match(r"^([ \t]*)-(?:[ \t]+(.*))?$", line.rstrip("\r\n"))
            if item and len(item.group(1)) >= len(match.group("indent")) and item_indent in (None, item.group(1)):
                item_indent = item.group(1)
                last_item = len(block)
            elif line.strip() and not line.lstrip().startswith("#"):
                break
            block.append(line)
            index += 1
        names = [_item_name(re.sub(r"^\s*-", "", line)) for line in block
                 if re.match(r"^\s*-", line) and not line.lstrip().startswith("#")]
        if last_item >= 0 and identifier not in names:
            ending = "\r\n" if block[last_item].endswith("\r\n") else "\n"
            if not block[last_item].endswith("\n"):
                block[last_item] += ending  # the list ended the file
            block.insert(last_item + 1, f"{item_indent}- {identifier}{ending}")
        out.extend(block)
    return "".join(out)


def twister_files(root: Path) -> list[Path]:
    """The twister files whose platform lists name the kit's boards."""
    return [path for pattern in TWISTER_GLOBS for path in sorted(root.glob(pattern)) if path.is_file()]



def suite_files(root: Path, emulated: bool) -> list[Path]:
    """The twister files a new board joins: the one rule for both kinds. A
    QEMU board joins every suite that runs (the deployment's, the kernel
    floor's, the samples'); a real board only the boards built and not run
    (BUILD_ONLY_SUITE), which is how `kit compare` and `kit test` tell it is
    one (cli.is_real_board): a QEMU board listed there would be refused."""
    build_only = root / BUILD_ONLY_SUITE
    if not emulated:
        return [build_only]
    return [path for path in twister_files(root) if path != build_only]


def join_suite(root: Path, board: ZephyrBoard, say: Callable[[str], None]) -> None:
    """A board that takes the kit profile joins every platform list of its
    suites but the small builds' (SMALL_SCENARIOS), which exclude it: twister
    joins a scenario's list to the common one, and the fprime-small builds
    are for the small parts."""
    identifier = board.identifier
    for path in suite_files(root, board.emulated):
        if not path.is_file():
            raise KitError(f"{path.relative_to(root)} is missing: a real board joins its platform list")
        before = path.read_text()
        name = path.relative_to(root)
        prefix = SMALL_SCENARIOS.get(name.as_posix())
        if prefix is None:
            after = add_to_twister_lists(before, identifier)
        else:
            after = exclude_from_scenarios(before, prefix, identifier)
        if after != before:
            path.write_text(after)
            say(f"twister: added {identifier} to the platform lists of {name}"
                + (f" (excluded from its {prefix}* scenarios: the small parts' builds)" if prefix else ""))
        else:
            say(f"twister: {name} unchanged (its lists name {identifier} already, or it has none)")


#: A small board joins only the scenarios of the builds that fit it: these, per suite
SMALL_SCENARIOS = {"tests/deployment/testcase.yaml": "profile.small.", BUILD_ONLY_SUITE: "board.small."}


def _edit_scenarios(text: str, prefix: str, edit: Callable[[str, str], str],
                    outside: Callable[[str], str] = lambda rest: rest) -> str:
    """A twister file with `edit(body, indent)` applied to the body of every
    scenario whose name starts with `prefix` (indent: the name's), and
    `outside` to the text between."""
    scenario = re.compile(rf"^(?P<indent>[ \t]+){re.escape(prefix)}[\w.]*:[ \t]*$")
    lines = text.splitlines(keepends=True)
    out: list[str] = []
    between: list[str] = []
    index = 0
    while index < len(lines):
        match = scenario.match(lines[index].rstrip("\r\n"))
        between.append(lines[index])
        index += 1
        if match is None:
            continue
        out.append(outside("".join(between)))
        between = []
        body_start = index
        while index < len(lines) and (not lines[index].strip() or lines[index].lstrip().startswith("#")
                                      or len(lines[index]) - len(lines[index].lstrip()) > len(match["indent"])):
            index += 1
        out.append(edit("".join(lines[body_start:index]), match["indent"]))
    out.append(outside("".join(between)))
    return "".join(out)


def _with_list(body: str, indent: str, key: str, identifier: str, keys: tuple[str, ...]) -> str:
    """A scenario's body with `identifier` in its lists of `keys`, its `key`
    list made first in the body if it has none."""
    if f"{key}:" not in body:
        body = f"{indent}  {key}:\n{indent}    - {identifier}\n" + body
    return add_to_twister_lists(body, identifier, keys)


def add_to_scenario_lists(text: str, prefix: str, identifier: str) -> str:
    """`identifier` added to the platform lists of every scenario of a
    twister file whose name starts with `prefix` (the rest as it was); a
    scenario without a platform_allow list gets one."""
    return _edit_scenarios(text, prefix, lambda body, indent: _with_list(body, indent, "platform_allow", identifier,
                                                                             TWISTER_LIST_KEYS))


def exclude_from_scenarios(text: str, prefix: str, identifier: str) -> str:
    """`identifier` added to the platform_allow lists of a twister file but
    those of its scenarios whose name starts with `prefix`, which exclude it
    (platform_exclude, made where missing). Not to integration_platforms:
    twister joins the common list to each scenario's, and a platform a
    scenario excludes but lists for integration is an error to twister."""
    return _edit_scenarios(text, prefix,
                           lambda body, indent: _with_list(body, indent, "platform_exclude", identifier,
                                                           ("platform_exclude",)),
                           outside=lambda rest: add_to_twister_lists(rest, identifier, ("platform_allow",)))


def join_small_suite(root: Path, board: ZephyrBoard, say: Callable[[str], None]) -> None:
    """A small board joins the scenarios of the builds that fit it: for a QEMU
    board the suite's fprime-small scenarios, for a real board the fprime-small
    builds of tests/boards."""
    name = "tests/deployment/testcase.yaml" if board.emulated else BUILD_ONLY_SUITE
    path, prefix = root / name, SMALL_SCENARIOS[name]
    before = path.read_text() if path.is_file() else ""
    if not re.search(rf"^[ \t]+{re.escape(prefix)}", before, re.MULTILINE):
        raise KitError(f"{name} has no {prefix}* scenario for a small board to join")
    after = add_to_scenario_lists(before, prefix, board.identifier)
    if after != before:
        path.write_text(after)
    say(f"twister: {board.identifier} {'added to' if after != before else 'already in'} the platform lists of "
        f"{name}'s {prefix}* scenarios (the builds that fit it)")


def allow_module(west_yml: str, module: str) -> str:
    """west.yml with `module` in the zephyr import's name-allowlist (once),
    its comments and layout kept."""
    # The list's items: the lines at the first item's indentation
    match = re.search(r"^[ \t]*name-allowlist:[ \t]*\r?\n"
                      r"(?P<items>(?P<item_indent>[ \t]+)-[^\n]*\n(?:(?P=item_indent)-[^\n]*\n)*)",
                      west_yml, re.MULTILINE)
    if match is None:
        raise KitError("west.yml has no name-allowlist under the zephyr project: add the module by hand")
    items = match.group("items")
    if module in [_item_name(re.sub(r"^\s*-", "", line)) for line in items.splitlines()]:
        return west_yml
    return west_yml[:match.end("items")] + f"{match.group('item_indent')}- {module}\n" + west_yml[match.end("items"):]

