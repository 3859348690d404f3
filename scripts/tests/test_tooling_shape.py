# SPDX-License-Identifier: Apache-2.0
"""The tooling's shape, as issue 31 left it, held: no module over 400 lines,
progress only through the kit's logger, and what a build folder holds named
only by kittools.build.folder."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import kittools

PACKAGE = Path(kittools.__file__).parent
MODULES = sorted(PACKAGE.rglob("*.py"))
MOST_LINES = 400
#: The files of a build folder (their names as kittools.build.folder spells them)
BUILD_FILES = ("zephyr.elf", ".config", "CMakeCache.txt", "compile_commands.json", "TopologyDictionary.json",
               "FppConstantsAc.hpp", "handler.log")
_BUILD_FILE = re.compile("|".join(rf"{re.escape(name)}(?!\w)" for name in BUILD_FILES))


def _strings(tree: ast.AST) -> list[ast.Constant]:
    """The string constants of a module but its docstrings."""
    docstrings = {id(node.body[0].value) for node in ast.walk(tree)
                  if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
                  and node.body and isinstance(node.body[0], ast.Expr)
                  and isinstance(node.body[0].value, ast.Constant)}
    return [node for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings]


def test_no_module_is_over_400_lines():
    long = {str(p.relative_to(PACKAGE)): n for p in MODULES if (n := len(p.read_text().splitlines())) > MOST_LINES}
    assert long == {}


def test_progress_goes_through_the_logger():
    printed = [f"{p.relative_to(PACKAGE)}:{node.lineno}" for p in MODULES for node in ast.walk(ast.parse(p.read_text()))
               if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "print"
               and any(isinstance(c, ast.Constant) and str(c.value).startswith("[kit]")
                       for arg in node.args[:1] for c in ast.walk(arg))]
    assert printed == [], "say it with kittools.log.say (the logger adds [kit])"


def test_only_the_build_folder_names_its_files():
    owner = PACKAGE / "build" / "folder.py"
    named = [f"{p.relative_to(PACKAGE)}:{node.lineno} {node.value!r}" for p in MODULES if p != owner
             for node in _strings(ast.parse(p.read_text())) if _BUILD_FILE.search(node.value)]
    assert named == [], "ask kittools.build.folder.BuildFolder"
