# SPDX-License-Identifier: Apache-2.0
"""The HTML report as a reviewer sees it: Debian's headless Chromium renders
it, screenshots it, and the test checks tables, plots and the console."""

import re
import shutil
import subprocess

from PIL import Image

from kittools.report import writer

from test_report import _results

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--hide-scrollbars", "--enable-logging=stderr", "--v=0"]


def _chromium(tmp_path, *args: str) -> subprocess.CompletedProcess:
    binary = shutil.which("chromium")
    assert binary, "Debian's chromium is needed for this test (scripts/setup.sh installs it)"
    return subprocess.run([binary, *CHROMIUM_FLAGS, f"--user-data-dir={tmp_path / 'profile'}", *args],
                          capture_output=True, text=True, timeout=120)


def test_report_renders_tables_and_plots_without_console_errors(tmp_path):
    writer.write(_results(), tmp_path)
    page = (tmp_path / "report.html").as_uri()

    dom = _chromium(tmp_path, "--dump-dom", page)
    assert dom.returncode == 0, dom.stderr[-2000:]
    assert len(re.findall(r"<table>", dom.stdout)) >= 4
    assert len(re.findall(r'<img alt="[^"]+" src="data:image/png;base64,', dom.stdout)) >= 2
    assert not re.search(r"CONSOLE\(\d+\)|Uncaught|Failed to load resource", dom.stderr)

    shot = tmp_path / "report.png"
    run = _chromium(tmp_path, "--window-size=1280,2400", f"--screenshot={shot}", page)
    assert run.returncode == 0 and shot.is_file(), run.stderr[-2000:]
    image = Image.open(shot).convert("L")
    assert image.size == (1280, 2400)
    # A rendered page, not a blank one: plenty of dark (text, lines) and mid-grey (plot) pixels
    histogram = image.histogram()
    assert sum(histogram[:128]) > 10000
