# SPDX-License-Identifier: Apache-2.0
"""The C++ style check (kittools.suite.style) on a throwaway tree."""

import shutil
import sys
from pathlib import Path

import pytest

from kittools.suite import style
from kittools.workspace import KIT_ROOT, KitError

CLEAN = """\
// SPDX-License-Identifier: Apache-2.0
namespace Kit {

int twice(int value) {
    return 2 * value;
}

}  // namespace Kit
"""

UNCLEAN = """\
namespace Kit {
int  twice( int value ){ return 2*value; }
}
"""


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    shutil.copy(KIT_ROOT / ".clang-format", tmp_path / ".clang-format")
    return tmp_path


def write(root: Path, relative: str, text: str) -> Path:
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def test_reports_only_the_unformatted_file(tree: Path) -> None:
    write(tree, "app/Components/Clean/Clean.cpp", CLEAN)
    messy = write(tree, "rtos/Os/Messy.hpp", UNCLEAN)
    assert style.clang_format_check(tree) == [messy]
    assert messy.read_text() == UNCLEAN  # check mode: nothing is rewritten


def test_skips_generated_and_foreign_files(tree: Path) -> None:
    clean = write(tree, "baremetal/Os/Clean.cpp", CLEAN)
    write(tree, "app/build-artifacts/Kit/TimingComponentAc.cpp", UNCLEAN)  # a build folder
    write(tree, "app/Components/Timing/TimingComponentAc.hpp", UNCLEAN)  # FPP's output
    write(tree, "deps/fprime/Fw/Messy.cpp", UNCLEAN)  # upstream, not the kit's
    write(tree, "app/Components/Timing/notes.txt", UNCLEAN)  # not C++
    assert style.source_files(tree) == [clean]
    assert style.clang_format_check(tree) == []


def test_every_glob_is_checked(tree: Path) -> None:
    expected = [write(tree, pattern.replace("**", "Sub").replace("*", "Messy"), UNCLEAN)
                for pattern in style.SOURCE_GLOBS]
    assert style.clang_format_check(tree) == sorted(expected)


def test_missing_style_file_is_an_error(tmp_path: Path) -> None:
    write(tmp_path, "app/Clean.cpp", CLEAN)
    with pytest.raises(KitError, match=r"no \.clang-format"):
        style.clang_format_check(tmp_path)


def test_missing_formatter_is_a_clear_error(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    write(tree, "app/Clean.cpp", CLEAN)
    monkeypatch.setattr(sys, "executable", str(tree / "no-venv" / "python"))
    monkeypatch.setenv("PATH", str(tree / "empty"))
    with pytest.raises(KitError, match=rf"clang-format not found.*clang-format=={style.CLANG_FORMAT_VERSION}"):
        style.clang_format_check(tree)


def test_another_version_is_refused(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    fake = write(tree, "bin/clang-format", "#!/bin/sh\necho 'clang-format version 14.0.6'\n")
    fake.chmod(0o755)
    monkeypatch.setattr(sys, "executable", str(tree / "bin" / "python"))
    with pytest.raises(KitError, match=r"14\.0\.6.*not the pinned"):
        style.find_clang_format()


def test_run_style_check_counts_one_test(tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write(tree, "app/Clean.cpp", CLEAN)
    assert (style.run_style_check(tree).passed, style.run_style_check(tree).failed) == (1, 0)
    write(tree, "tests/host/Messy.cpp", UNCLEAN)
    tally = style.run_style_check(tree)
    assert (tally.passed, tally.failed) == (0, 1)
    assert "tests/host/Messy.cpp" in capsys.readouterr().out
