# SPDX-License-Identifier: Apache-2.0
import json
import os

import pytest

from kittools.model import Results
from kittools.suite import counts, determinism, host, platforms, results, twister, verdict
from kittools.workspace import KitError


def test_twister_tally_counts_failures_errors_and_blocks(tmp_path):
    report = tmp_path / "twister.json"
    report.write_text(json.dumps({"testsuites": [
        {"status": "passed"}, {"status": "passed"}, {"status": "failed"},
        {"status": "error"}, {"status": "filtered"}, {"status": "skipped"}, {"status": "blocked"},
    ]}))
    tally = counts.twister_tally(report)
    assert (tally.passed, tally.failed) == (2, 3)


def test_a_real_boards_build_counts_once_passed_if_built_and_failed_if_not(tmp_path):
    report = tmp_path / "twister.json"
    report.write_text(json.dumps({"testsuites": [
        {"name": "tests/boards/board.baremetal", "status": "not run",
         "testcases": [{"status": "not run"}, {"status": "not run"}]},
        {"name": "tests/boards/board.rtos", "status": "error", "testcases": [{"status": "error"}]},
        {"name": "tests/deployment/kit.rtos", "status": "not run", "testcases": [{"status": "not run"}]},
    ]}))
    tally = counts.twister_tally(report)
    # a suite build not run (it should have run) counts neither way
    assert (tally.passed, tally.failed) == (1, 1)


def test_the_real_boards_build_every_variant_and_run_nothing():
    import yaml

    suite = yaml.safe_load(platforms.BUILD_ONLY_SUITE.read_text())
    assert suite["common"]["build_only"] is True
    # every variant, and the small part's build (board.small.<variant>: the deployment suite's profile.small.*)
    deployment = yaml.safe_load(platforms.SUITE.read_text())["tests"]
    assert sorted(name.removeprefix(results.BUILD_ONLY_PREFIX) for name in suite["tests"]) == sorted(
        [name.removeprefix("kit.") for name in deployment if name.startswith("kit.")]
        + [name.removeprefix(results.PROFILE_PREFIX) for name in deployment if name.startswith("profile.small.")])
    assert not set(platforms.suite_boards(platforms.BUILD_ONLY_SUITE)) & set(platforms.suite_boards())


def test_missing_twister_report_is_an_error(tmp_path):
    with pytest.raises(KitError, match="no report"):
        counts.twister_tally(tmp_path / "twister.json")


def test_gtest_tally(tmp_path):
    report = tmp_path / "ut.json"
    report.write_text(json.dumps({"tests": 12, "failures": 2, "errors": 0}))
    tally = counts.gtest_tally(report)
    assert (tally.passed, tally.failed) == (10, 2)


def test_junit_tally_handles_testsuites_root(tmp_path):
    report = tmp_path / "pytest.xml"
    report.write_text('<testsuites><testsuite tests="5" failures="1" errors="1" skipped="1"/></testsuites>')
    tally = counts.junit_tally(report)
    assert (tally.passed, tally.failed) == (2, 2)


def test_junit_failures_name_each_failure_with_its_reason(tmp_path):
    report = tmp_path / "pytest.xml"
    report.write_text(
        '<testsuites><testsuite tests="3" failures="1" errors="1">'
        '<testcase name="test_ok"/>'
        '<testcase name="test_bad"><failure message="AssertionError: 3 != 4&#10;assert 3 == 4">trace</failure>'
        '</testcase><testcase name="test_broken"><error>fixture gone</error></testcase>'
        '</testsuite></testsuites>')
    assert counts.junit_failures(report) == ["test_bad (AssertionError: 3 != 4)", "test_broken (fixture gone)"]


def _suite_build(twister_out, platform, name, logs):
    """A twister build of the suite, as the pytest harness leaves it: its
    ELF and each played scenario's console in kit-runs/."""
    build = twister_out / platform.replace("/", "_") / "tests" / "deployment" / name
    (build / "zephyr").mkdir(parents=True)
    (build / "zephyr" / "zephyr.elf").write_bytes(b"")
    (build / "kit-runs").mkdir()
    for scenario, text in logs.items():
        (build / "kit-runs" / f"{scenario}.log").write_text(text)
    return build


def test_recorded_hashes_read_each_played_scenario_log(tmp_path):
    rtos = _suite_build(tmp_path, "mps2/an385", "kit.rtos", {
        "nominal": "KIT SELECT scenarios=nominal\nKIT RG name=rg1kHz\nKIT HASH samples=10 fnv=0xdeadbeef\n",
        "assert": "KIT HALT reason=kernel_panic\n"})
    bare = _suite_build(tmp_path, "qemu_cortex_m3/ti_lm3s6965", "kit.baremetal", {
        "faults": "KIT HASH samples=10 fnv=0x00c0ffee\n"})
    (tmp_path / "twister.json").write_text(json.dumps({"testsuites": [
        {"name": "tests/deployment/kit.rtos", "platform": "mps2/an385", "status": "passed"},
        {"name": "tests/deployment/kit.baremetal", "platform": "qemu_cortex_m3/ti_lm3s6965", "status": "failed"},
        {"name": "tests/deployment/kit.rtos", "platform": "qemu_cortex_m3/ti_lm3s6965", "status": "filtered"},
    ]}))
    assert determinism.recorded_hashes(tmp_path) == {("mps2/an385", rtos, "nominal"): "0xdeadbeef",
                                                 ("qemu_cortex_m3/ti_lm3s6965", bare, "faults"): "0x00c0ffee"}


def test_twister_tally_counts_a_pytest_configuration_per_scenario(tmp_path):
    report = tmp_path / "twister.json"
    report.write_text(json.dumps({"testsuites": [
        {"status": "failed", "testcases": [{"status": "passed"}, {"status": "failed"}, {"status": "passed"}]},
        {"status": "error", "testcases": [{"status": "blocked"}, {"status": "blocked"}]},
    ]}))
    tally = counts.twister_tally(report)
    assert (tally.passed, tally.failed) == (2, 3)


def test_the_suite_boards_are_its_platform_allow_list(tmp_path):
    suite = tmp_path / "suite.yaml"
    suite.write_text("common:\n  platform_allow:\n    - qemu_cortex_m3\n    - mps2/an385\ntests: {}\n")
    assert platforms.suite_boards(suite) == ["qemu_cortex_m3", "mps2/an385"]
    bad = tmp_path / "testcase.yaml"
    bad.write_text("tests: {}\n")
    with pytest.raises(KitError, match="names no platforms"):
        platforms.suite_boards(bad)


def test_a_baseline_holds_metrics_and_load_breaking_points_not_the_runs_records(tmp_path):
    """The committed baseline keeps the metrics and the load sweep's records
    (the breaking points the budget holds, read back from the file as CI
    reads it), not the rest of the console, nor the serial axes' (host-paced:
    they do not repeat)."""
    from kittools import console, metrics
    from kittools.sizes.memory import Footprint
    from kittools.suite import budget, results

    from sample_console import console_log

    def point(axis: str, level: int, slips: int) -> list[console.Record]:
        lines = [f"KIT SWEEP axis={axis} point=0 level={level} unit=us burst=0 rg=rg1kHz hz=1000 cycles=1000 "
                 f"expected=1000 slips={slips} late_starts=0 latency_p99=700 latency_max=900 jitter_p99=1 "
                 "jitter_max=2",
                 f"KIT SERIAL axis=noise point=0 level={level} repeat=0 offered=48 delivered={48 - slips} "
                 f"lost={slips} bytes_sent=1 uart_received=1 ring_drops=0 uart_errors=0"]
        return [r for r in map(console.parse_line, lines) if r is not None]

    def made(slips_at_50: int) -> Results:
        runs = []
        for v in ("baremetal", "rtos"):
            run = console.parse(console_log(v))
            run.records += point("slice", 50, slips_at_50) + point("slice", 75, 3) + point("noise", 50, slips_at_50)
            runs.append(metrics.VariantData(v, Footprint(1000, 500, 262144, 65536), run))
        return metrics.results(runs)

    data = made(0)
    path = tmp_path / "baselines" / "board.json"
    verdict.write_baseline(data, path)
    written = json.loads(path.read_text())
    for variant in written["variants"].values():
        assert {(r["kind"], r["axis"]) for r in variant["records"]} == {("SWEEP", "slice")}
    baseline = results.load(path)
    assert baseline.conditions == data.conditions
    assert {n: v.metrics for n, v in baseline.variants.items()} == {n: v.metrics for n, v in data.variants.items()}
    assert budget.check(data, baseline).passed
    # A run whose 1 kHz group breaks earlier on a load axis fails its budget;
    # the serial axes' breaking points are shown, not held
    violations = budget.check(made(2), baseline).violations
    assert any("slice load, rg1kHz: 50, earlier than the baseline (broke at 75)" in v for v in violations)
    assert not any("noise" in v for v in violations)


def test_lint_passes_on_the_tooling_and_counts_each_tool(tmp_path):
    tally = host.run_lint(tmp_path)
    assert (tally.passed, tally.failed) == (2, 0), [p.read_text() for p in tmp_path.glob("*.log")]
    assert {p.name for p in tmp_path.glob("*.log")} == {"ruff.log", "mypy.log"}


def test_a_lint_failure_is_one_failure(tmp_path, monkeypatch):
    monkeypatch.setattr(host, "LINTERS", (("ruff", ["check", "--select", "E", "--line-length", "20", "."]),))
    assert (host.run_lint(tmp_path).failed, host.run_lint(tmp_path).passed) == (1, 0)


# Twister 4.0's output with -v (twisterlib/runner.py), colors included
TWISTER_OUTPUT = [
    "INFO    - Using Ninja..",
    "INFO    - JOBS: 2",
    "INFO    - 16 test scenarios (40 configurations) selected, 16 configurations filtered (16 by static filter, "
    "0 at runtime).",
    "INFO    - \x1b[1;32mBuilding\x1b[0m ...",
    "INFO    -  3/24 qemu_cortex_m3/ti_lm3s6965 kit.deployment.rtos                                "
    "\x1b[32mPASSED\x1b[39m (qemu 2.341s)",
    "INFO    - 24/24 mps2/an385                 tests/deployment/kit.faults.baremetal              "
    "\x1b[31mFAILED\x1b[39m Timeout (qemu 60.012s)",
    "INFO    - 12/24 mps2/an385                 kit.load.rtos                                      "
    "\x1b[33mNOT RUN\x1b[39m (build)",
]


def test_twister_progress_says_one_line_per_finished_configuration():
    progress = twister.TwisterProgress()
    said = [s for s in (progress.line(line) for line in TWISTER_OUTPUT) if s is not None]
    assert said[:3] == [
        "  twister: 24 configurations to build and run, 2 at a time",
        "  3/24 qemu_cortex_m3/ti_lm3s6965 kit.deployment.rtos PASSED 2.3 s (21 left)",
        "  24/24 mps2/an385 kit.faults.baremetal FAILED Timeout 60.0 s (0 left)",
    ]  # the logger adds "[kit] " (kittools.log)
    assert said[3] == "  12/24 mps2/an385 kit.load.rtos NOT RUN build (12 left)"


def test_twister_progress_without_the_announcement_uses_the_line_total():
    progress = twister.TwisterProgress()
    assert progress.line("INFO    - 1/2 qemu_cortex_m3 kit.soak.rtos PASSED (qemu 610.2s)") == \
        "  1/2 qemu_cortex_m3 kit.soak.rtos PASSED 610.2 s (1 left)"
    assert progress.line("INFO    - Total complete:    1/   2  50%  built (not run):    0, filtered:    0\r") is None


def test_streamed_output_is_logged_whole_and_said_line_by_line(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(twister, "environment", lambda: dict(os.environ))
    heard: list[str] = []

    def progress(line: str) -> str | None:
        heard.append(line)
        return f"said {line}" if line.startswith("b") else None

    code = twister._run_streamed(["sh", "-c", "printf 'a\\nb1\\rb2\\n'; exit 3"], tmp_path / "t.log", progress)
    assert code == 3
    assert (tmp_path / "t.log").read_bytes() == b"a\nb1\rb2\n"
    assert heard == ["a", "b1", "b2"]
    assert capsys.readouterr().out == "[kit] said b1\n[kit] said b2\n"  # said through the kit's logger


def _fake_twister(monkeypatch, commands, status="passed", code=0):
    """twister.play's twister: records its command, writes its report."""
    def run(command, log, say):
        commands.append(command)
        out_dir = command[command.index("--outdir") + 1]
        with open(os.path.join(out_dir, "twister.json"), "w") as report:
            json.dump({"testsuites": [{"name": "tests/deployment/kit.rtos", "status": status}]}, report)
        return code

    monkeypatch.setattr(twister, "_run_streamed", run)


def test_twister_configures_again_unless_the_last_clean_run_was_configured_from_the_same(tmp_path, monkeypatch):
    suite = tmp_path / "tests" / "deployment" / "testcase.yaml"
    suite.parent.mkdir(parents=True)
    suite.write_text("tests: {kit.rtos: {}}\n")
    monkeypatch.setattr(twister, "KIT_ROOT", tmp_path)
    monkeypatch.setattr(twister, "environment", lambda: {"ZEPHYR_TOOLCHAIN_VARIANT": "gnuarmemb"})
    monkeypatch.setattr(twister, "commit_label", lambda root: "0123456789ab")
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    commands: list[list[str]] = []

    def play():
        twister.play(["west", "twister"], tmp_path / "t.log", out_dir)
        return "--aggressive-no-clean" in commands[-1], "-n" in commands[-1]

    _fake_twister(monkeypatch, commands)
    assert play() == (False, True)  # nothing configured yet: twister configures
    assert play() == (True, False)  # as configured then: ninja's own checks suffice
    suite.write_text("tests: {kit.rtos: {extra_args: SNIPPET=fprime-small}}\n")
    assert play() == (False, True)  # twister hands extra_args to CMake only when it configures
    monkeypatch.setattr(twister, "environment", lambda: {"ZEPHYR_TOOLCHAIN_VARIANT": "zephyr"})
    assert play() == (False, True)  # another toolchain
    _fake_twister(monkeypatch, commands, status="error")
    assert play() == (True, False)
    _fake_twister(monkeypatch, commands)
    assert play() == (False, True)  # after a failed run: configure again (a configure may have failed)
    assert play() == (True, False)
    kconfig = tmp_path / "app" / "Kconfig"
    kconfig.parent.mkdir()
    kconfig.write_text("config KIT_X\n\tint\n\tdefault 1\n")
    assert play() == (False, True)  # a Kconfig default changed: Zephyr would keep the old value
    assert play() == (True, False)
    monkeypatch.setattr(twister, "commit_label", lambda root: "0123456789ab-dirty")
    assert play() == (False, True)  # another commit string in the image: its code moves


def test_an_earlier_suites_kconfig_file_goes_with_its_cmake_cache(tmp_path, monkeypatch):
    monkeypatch.setattr(twister, "KIT_ROOT", tmp_path)
    monkeypatch.setattr(twister, "environment", lambda: {})
    out_dir = tmp_path / "out"
    build = out_dir / "qemu_cortex_m3_ti_lm3s6965" / "deployment" / "kit.rtos"
    (build / "twister").mkdir(parents=True)
    (build / "twister" / "testsuite_extra.conf").write_text("CONFIG_KIT_MODEL_RTOS=y")
    (build / "CMakeCache.txt").write_text("OVERLAY_CONFIG:UNINITIALIZED=twister/testsuite_extra.conf\n")
    other = out_dir / "mps2_an385" / "deployment" / "kit.rtos"
    other.mkdir(parents=True)
    (other / "CMakeCache.txt").write_text("\n")
    _fake_twister(monkeypatch, [])
    twister.play(["west", "twister"], tmp_path / "t.log", out_dir)
    assert not (build / "twister" / "testsuite_extra.conf").exists()
    assert not (build / "CMakeCache.txt").exists()  # configured from scratch
    assert (other / "CMakeCache.txt").exists()


def test_a_build_configured_again_loses_its_last_kconfig(tmp_path, monkeypatch):
    """Zephyr configures a build from its last .config when its fragments
    did not change, which keeps the old value of a default the kit changed;
    a run that configures again removes it."""
    monkeypatch.setattr(twister, "KIT_ROOT", tmp_path)
    monkeypatch.setattr(twister, "environment", lambda: {})
    out_dir = tmp_path / "out"
    dotconfig = out_dir / "qemu_cortex_m3_ti_lm3s6965" / "deployment" / "kit.rtos" / "zephyr" / ".config"
    dotconfig.parent.mkdir(parents=True)
    (dotconfig.parent.parent / "CMakeCache.txt").write_text("\n")
    dotconfig.write_text("CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE=14848\n")
    _fake_twister(monkeypatch, [])
    twister.play(["west", "twister"], tmp_path / "t.log", out_dir)
    assert not dotconfig.exists()
    dotconfig.write_text("CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE=16128\n")
    twister.play(["west", "twister"], tmp_path / "t.log", out_dir)
    assert dotconfig.exists()  # as configured then: kept
