# SPDX-License-Identifier: Apache-2.0
"""The little of FPP that `kit new-deployment` reads: instance
declarations, a topology's imports and its connections. Line based, as F´'s
templates and F´'s subtopologies write them; anything else is left as it is."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

_INSTANCE = re.compile(r"^\s*instance\s+(?P<name>\$?\w+)\s*:\s*(?P<type>[\w.]+)\s+base\s+id\s+(?P<base>.+?)\s*$")
_QUEUE = re.compile(r"\bqueue\s+size\s+(?P<value>[^\\\n]+?)\s*(?=\\|\bstack\b|\bpriority\b|$)")
_STACK = re.compile(r"\bstack\s+size\s+(?P<value>[^\\\n]+?)\s*(?=\\|\bpriority\b|\bqueue\b|$)")
_PRIORITY = re.compile(r"\bpriority\s+(?P<value>[^\\\n{]+?)\s*(?=\\|\{|$)")
_MODULE = re.compile(r"^\s*module\s+(?P<name>\w+)\s*\{")
#: One connection: `source.port[index] -> target.port[index]`
CONNECTION = re.compile(r"^(?P<indent>\s*)(?P<source>[\w.$]+(?:\[[^\]]*\])?)\s*->\s*(?P<target>[\w.$]+(?:\[[^\]]*\])?)"
                        r"\s*(?P<comment>#.*)?$")


@dataclass(frozen=True)
class Instance:
    """One `instance` declaration of an FPP file."""

    name: str
    type: str
    base: str
    module: str  #: the module it is declared in (its C++ namespace)
    queue: str | None
    stack: str | None
    priority: str | None
    first: int  #: its first line (0-based) in its file
    last: int  #: its last line, the end of its continuation or its body

    @property
    def active(self) -> bool:
        """An active instance: F´ gives it a task, with a stack and a priority."""
        return self.stack is not None

    @property
    def queued(self) -> bool:
        return self.queue is not None

    @property
    def qualified(self) -> str:
        return f"{self.module}.{self.name}" if self.module else self.name


def _body_end(lines: list[str], start: int) -> int:
    """The last line of a declaration that starts at `start`: its `\\`
    continuations, then a `{ ... }` body if one opens."""
    end = start
    while lines[end].rstrip().endswith("\\") and end + 1 < len(lines):
        end += 1
    opened = "".join(lines[start:end + 1]).count("{")
    if not opened and end + 1 < len(lines) and lines[end + 1].strip().startswith("{"):
        end += 1
        opened = lines[end].count("{")
    depth = opened - "".join(lines[start:end + 1]).count("}")
    while depth > 0 and end + 1 < len(lines):
        end += 1
        depth += lines[end].count("{") - lines[end].count("}")
    return end


def instances(text: str) -> list[Instance]:
    """Every instance declared in an FPP file, with its module."""
    lines = text.splitlines()
    found: list[Instance] = []
    modules: list[tuple[str, int]] = []  # (name, brace depth when it opened)
    depth = 0
    index = 0
    while index < len(lines):
        line = lines[index].split("#", 1)[0]
        module = _MODULE.match(line)
        if module:
            modules.append((module.group("name"), depth))
        declared = _INSTANCE.match(line.rstrip("\\ \t"))
        if declared:
            last = _body_end(lines, index)
            head = " ".join(part.split("#", 1)[0].rstrip().rstrip("\\") for part in lines[index:last + 1])
            head = head.split("{", 1)[0]
            queue, stack, priority = (_QUEUE.search(head), _STACK.search(head), _PRIORITY.search(head))
            base = re.split(r"\s+(?:queue|stack|priority)\b|\\", declared.group("base"))[0].strip()
            found.append(Instance(
                name=declared.group("name"), type=declared.group("type"), base=base,
                module=".".join(name for name, _ in modules),
                queue=queue.group("value").strip() if queue else None,
                stack=stack.group("value").strip() if stack else None,
                priority=priority.group("value").strip() if priority else None,
                first=index, last=last))
            for body_line in lines[index:last + 1]:
                depth += body_line.count("{") - body_line.count("}")
            index = last + 1
            continue
        depth += line.count("{") - line.count("}")
        while modules and depth <= modules[-1][1]:
            modules.pop()
        index += 1
    return found


def instances_in(folder: Path) -> list[Instance]:
    """The instances of every FPP file under a folder, in file order."""
    found: list[Instance] = []
    for path in sorted(folder.rglob("*.fpp")):
        found.extend(instances(path.read_text()))
    return found


def endpoint_instance(endpoint: str) -> str:
    """`CdhCore.cmdDisp.seqCmdBuff[0]` -> `CdhCore.cmdDisp`."""
    return endpoint.split("[", 1)[0].rsplit(".", 1)[0]


def endpoint_port(endpoint: str) -> str:
    """`CdhCore.cmdDisp.seqCmdBuff[0]` -> `CdhCore.cmdDisp.seqCmdBuff`."""
    return endpoint.split("[", 1)[0]


def endpoint_index(endpoint: str) -> str | None:
    """`rg.RateGroupMemberOut[3]` -> `3`; None without an index."""
    match = re.search(r"\[([^\]]*)\]", endpoint)
    return match.group(1).strip() if match else None


def imports(text: str) -> list[str]:
    """The subtopologies a topology file imports, as written."""
    return re.findall(r"^\s*import\s+([\w.]+)", text, flags=re.MULTILINE)


def constants(text: str, module: str) -> dict[str, str]:
    """The constants of a module of an F´ config file (`module StackSizes {
    constant cmdDisp = 64 * 1024 }`), by name, with their expressions."""
    block = re.search(r"\bmodule\s+" + re.escape(module) + r"\s*\{(?P<body>[^}]*)\}", text)
    if not block:
        return {}
    return {match.group(1): match.group(2).strip()
            for match in re.finditer(r"^\s*constant\s+(\$?\w+)\s*=\s*([^#\n]+)", block.group("body"), re.MULTILINE)}


def set_constants(text: str, module: str, values: dict[str, str]) -> str:
    """`text` with the named constants of `module` set to `values`."""
    block = re.search(r"\bmodule\s+" + re.escape(module) + r"\s*\{(?P<body>[^}]*)\}", text)
    if not block:
        return text
    body = block.group("body")
    for name, value in values.items():
        body = re.sub(r"^(\s*constant\s+" + re.escape(name) + r"\s*=\s*)[^#\n]+?(\s*(#.*)?)$",
                      lambda match, value=value: f"{match.group(1)}{value}{match.group(2)}", body,
                      flags=re.MULTILINE)
    return text[:block.start("body")] + body + text[block.end("body"):]
