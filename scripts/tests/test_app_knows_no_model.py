# SPDX-License-Identifier: Apache-2.0
"""app/ knows no execution model: the deployment is shared by every model,
so no file under app/ includes a model's header or tests a model's Kconfig
symbol. A model's checks and OS code live in its own folder (baremetal/,
rtos/); what both OS layers share, in modules/kit-os/. app/ tests the
capabilities a model selects (CONFIG_KIT_RATE_GROUPS_PASSIVE, ...), which
app/Kconfig declares.

Code is what is checked: C and C++ sources, CMake, Kconfig fragments
(.conf), with their comments left out, since a comment that names a model
("the baremetal TaskRunner ...") explains and decides nothing. The variant
table (app/variants.yaml, app/sample.yaml) and the model choice in
app/Kconfig are the places that list the models by design."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

KIT_ROOT = Path(__file__).resolve().parents[2]
APP = KIT_ROOT / "app"

#: Every execution model: a top-level folder with a Kconfig.model
MODELS = tuple(sorted(path.parent.name for path in KIT_ROOT.glob("*/Kconfig.model")))

#: The OS layers the models take from their upstreams (west.yml): a header of
#: theirs is a model's header too. (fprime-baremetal's components, such as
#: Svc/PassiveCmdDispatcher, are capabilities: app/Kconfig offers them; so is
#: its MicroFs, the RAM file system every model uses: app/src/RamFs.cpp.)
UPSTREAM_MODEL_HEADERS = ("fprime-baremetal/Os/", "fprime-zephyr/Os/")
SHARED_UPSTREAM_HEADERS = ("fprime-baremetal/Os/Baremetal/MicroFs/",)

_C_SUFFIXES = {".c", ".h", ".cpp", ".hpp"}
_HASH_COMMENT_SUFFIXES = {".cmake", ".conf"}


def _code_files(root: Path) -> list[Path]:
    return sorted(path for path in root.rglob("*") if path.is_file() and (
        path.suffix in _C_SUFFIXES | _HASH_COMMENT_SUFFIXES or path.name == "CMakeLists.txt"))


# A string literal, or a comment: strings are kept (an #include names its
# header in one), comments dropped
_C_TOKENS = re.compile(r'"(?:\\.|[^"\\\n])*"|//[^\n]*|/\*.*?\*/', re.DOTALL)
_HASH_TOKENS = re.compile(r'"(?:\\.|[^"\\])*"|#[^\n]*')


def _without_comments(path: Path) -> str:
    text = path.read_text(errors="replace")
    if path.suffix in _C_SUFFIXES:
        # Keep a comment's newlines so that line numbers stay right
        return _C_TOKENS.sub(lambda m: m.group(0) if m.group(0).startswith('"') else
                             "\n" * m.group(0).count("\n"), text)
    return _HASH_TOKENS.sub(lambda m: m.group(0) if m.group(0).startswith('"') else "", text)


def _app_declared_symbols() -> set[str]:
    """What app/Kconfig declares: the interface a model fills in (its name,
    the capabilities it selects), not the model."""
    text = "\n".join(path.read_text() for path in APP.rglob("Kconfig*"))
    return set(re.findall(r"^\s*(?:menu)?config\s+(\w+)", text, re.MULTILINE))


def _model_symbols() -> set[str]:
    """Every symbol a model's Kconfig.model defines (config or choice)."""
    found: set[str] = set()
    for model in MODELS:
        text = (KIT_ROOT / model / "Kconfig.model").read_text()
        found |= set(re.findall(r"^\s*(?:menu)?(?:config|choice)\s+(\w+)", text, re.MULTILINE))
    return found


def model_symbol_pattern() -> re.Pattern[str]:
    """CONFIG_KIT_MODEL_<MODEL>, CONFIG_KIT_<MODEL>_*, and every other symbol
    of a model's Kconfig.model that app/Kconfig does not declare."""
    names = [m.upper() for m in MODELS]
    own = sorted(_model_symbols() - _app_declared_symbols())
    alternatives = [rf"KIT_MODEL_(?:{'|'.join(names)})\b", rf"KIT_(?:{'|'.join(names)})_\w+",
                    *(rf"{re.escape(symbol)}\b" for symbol in own)]
    return re.compile(rf"\bCONFIG_(?:{'|'.join(alternatives)})")


def model_include_pattern() -> re.Pattern[str]:
    folders = "|".join(re.escape(f"{model}/") for model in MODELS)
    upstream = "|".join(re.escape(prefix) for prefix in UPSTREAM_MODEL_HEADERS)
    shared = "|".join(re.escape(prefix) for prefix in SHARED_UPSTREAM_HEADERS)
    return re.compile(rf'^[ \t]*#[ \t]*include[ \t]*[<"](?!{shared})(?:{folders}|{upstream})', re.MULTILINE)


def findings(root: Path, base: Path = KIT_ROOT) -> list[str]:
    """Where a file under `root` includes a model's header or uses a model's
    Kconfig symbol: "<path relative to base>:<line>: <what>"."""
    symbol, include = model_symbol_pattern(), model_include_pattern()
    found = []
    for path in _code_files(root):
        code = _without_comments(path)
        for pattern in (include, symbol):
            for match in pattern.finditer(code):
                line = code.count("\n", 0, match.start()) + 1
                found.append(f"{path.relative_to(base)}:{line}: {match.group(0).strip()}")
    return found


def test_the_models_are_found():
    assert MODELS == ("baremetal", "rtos")
    symbols = model_symbol_pattern()
    assert symbols.search("#if defined(CONFIG_KIT_MODEL_RTOS)")
    assert symbols.search("IS_ENABLED(CONFIG_KIT_BAREMETAL_POLICY_BUDGETED)")
    assert symbols.search("CONFIG_KIT_BUDGET_CRITICAL_PRIORITY")  # baremetal/Kconfig.model's own
    # app/Kconfig's: the model's name and the capabilities a model selects
    assert not symbols.search("CONFIG_KIT_MODEL_NAME")
    assert not symbols.search("IS_ENABLED(CONFIG_KIT_MODEL_SHEDS_LOAD)")
    assert not symbols.search("#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)")


def test_app_includes_no_models_header_and_tests_no_models_symbol():
    assert findings(APP) == []


@pytest.mark.parametrize("name,text,expected", [
    ("Checks.cpp", '#include "rtos/Os/PriorityMap.hpp"\n', 'Checks.cpp:1: #include "rtos/'),
    ("Checks.cpp", "int a;\n#include <fprime-baremetal/Os/TaskRunner/TaskRunner.hpp>\n",
     "Checks.cpp:2: #include <fprime-baremetal/Os/"),
    ("Checks.cpp", "/* a\n * comment */\n#if defined(CONFIG_KIT_MODEL_BAREMETAL)\n#endif\n",
     "Checks.cpp:3: CONFIG_KIT_MODEL_BAREMETAL"),
    ("CMakeLists.txt", '# "x\nif(CONFIG_KIT_BAREMETAL_POLICY_BUDGETED)\nendif()\n',
     "CMakeLists.txt:2: CONFIG_KIT_BAREMETAL_POLICY_BUDGETED"),
    ("extra.conf", "CONFIG_KIT_MODEL_RTOS=y\n", "extra.conf:1: CONFIG_KIT_MODEL_RTOS"),
])
def test_a_file_that_knows_a_model_is_found(tmp_path, name, text, expected):
    # The check above can fail: the same scan finds each kind of knowledge
    (tmp_path / name).write_text(text)
    assert findings(tmp_path, tmp_path) == [expected]


@pytest.mark.parametrize("text", [
    "#include <fprime-baremetal/Os/Baremetal/MicroFs/MicroFs.hpp>\n",  # every model's file system
    "// the baremetal TaskRunner, CONFIG_KIT_MODEL_BAREMETAL\n",
    "/* #include \"rtos/Os/PriorityMap.hpp\" */\n",
    "#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)\n#endif\n",
])
def test_comments_and_capabilities_are_not_findings(tmp_path, text):
    (tmp_path / "Note.cpp").write_text(text)
    assert findings(tmp_path, tmp_path) == []
