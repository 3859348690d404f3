# SPDX-License-Identifier: Apache-2.0
"""The instances of a build's topology and their component types, read from
the topology's generated C++ headers (FPP's `<Name>TopologyAc.hpp`, one per
topology and subtopology: `namespace CdhCore { extern Svc::Health health; }`).

An instance's object holds its component's static RAM, and it is defined in
the topology's code, so its source says nothing of its layer: its type does,
whatever the deployment named it (the kit's `Kit::health`, fprime-util's
template's `CdhCore::health`).
"""

from __future__ import annotations

import re
from pathlib import Path

from kittools.build.folder import BuildFolder

# The header's tokens that matter: a namespace opened, an instance declared, any other brace
_TOKENS = re.compile(r"\bnamespace\s+(?P<namespace>\w+)\s*\{|\bextern\s+(?P<type>[\w:]+)\s+(?P<name>\w+)\s*;"
                     r"|(?P<open>\{)|(?P<close>\})")


def mangled(scope: list[str], name: str) -> str:
    """The Itanium C++ ABI name of the object `name` in the namespaces `scope`."""
    return "_ZN" + "".join(f"{len(part)}{part}" for part in [*scope, name]) + "E"


def of_header(text: str) -> dict[str, tuple[str, str]]:
    """Each instance a topology header declares: its mangled name, with
    (its namespace, its component type)."""
    found: dict[str, tuple[str, str]] = {}
    scope: list[str | None] = []  # each open brace: the namespace it opened, or None
    for token in _TOKENS.finditer(text):
        if token["namespace"]:
            scope.append(token["namespace"])
        elif token["name"]:
            namespaces = [part for part in scope if part is not None]
            found[mangled(namespaces, token["name"])] = ("::".join(namespaces), token["type"])
        elif token["open"]:
            scope.append(None)
        elif scope:
            scope.pop()
    return found


def of_build(build_dir: Path) -> dict[str, tuple[str, str]]:
    """Every instance of the build's topology and its subtopologies, by
    mangled name; none where the build generated no topology."""
    found: dict[str, tuple[str, str]] = {}
    for header in BuildFolder(build_dir).topology_headers():
        found.update(of_header(header.read_text(errors="replace")))
    return found
