# SPDX-License-Identifier: Apache-2.0
"""The kit imported by another repository's west.yml, as a team uses it
(docs/your-deployment.md): the team's repository is the manifest
repository and its own F´ project, the kit a project of its manifest whose
upstreams land in the kit's deps/ (`path: .`, `import: path-prefix:`), and
`west kit ...` runs in that workspace.

CI makes one in a scratch folder outside the clone (SCRATCH): the kit is
this clone (a link to it: west update finds every pin checked out and
fetches nothing), the team's repository a copy of an F´ project of tests/."""

from __future__ import annotations

import contextlib
import fcntl
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

from kittools.log import LOG
from kittools.suite.counts import Tally, run_logged
from kittools.workspace import KIT_ROOT, KitError

#: The kit's folder in the importing workspace, beside the team's repository
KIT_FOLDER = "kit"
#: The team's repository (the manifest repository) in that workspace
TEAM_FOLDER = "team"
#: west's own branch in each project of a workspace: the revision its manifest pins
MANIFEST_REV = "refs/heads/manifest-rev"


def manifest(url: str, revision: str, kit_folder: str = KIT_FOLDER, team_folder: str = TEAM_FOLDER) -> str:
    """A team's west.yml importing the kit: the kit at `kit_folder` and, with
    the same prefix, its upstreams in `kit_folder`/deps (where the kit reads
    them, as in its own workspace)."""
    return (
        'manifest:\n  version: "1.2"\n'
        f"  self:\n    path: {team_folder}\n"
        "  projects:\n"
        "    - name: fprime-zephyr-kit\n"
        f"      url: {url}\n"
        f"      revision: {revision}\n"
        "      path: .\n"
        "      import:\n"
        f"        path-prefix: {kit_folder}\n"
    )


def _run_west(args: list[str], cwd: Path, log: Path) -> int:
    """west in the importing workspace, found from `cwd` as a user's west
    finds it: without the ZEPHYR_BASE the kit's own runs set, which would
    point west at the clone's own workspace instead."""
    return run_logged([sys.executable, "-m", "west", *args], log, cwd=cwd, unset=("ZEPHYR_BASE",))


def _west(args: list[str], cwd: Path, log: Path) -> None:
    if _run_west(args, cwd, log) != 0:
        raise KitError(f"west {' '.join(args)} failed in the importing workspace; see {log}")


def _git(args: list[str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["git", "-C", str(KIT_ROOT), *args], capture_output=True, text=True, check=False)


#: The scratch workspace's folder, the same for every clone on a machine: its
#: path is on the deployment's compile lines, and ccache, which keys on them,
#: then serves the next clone's run what this one compiled (a fresh folder
#: each time cost the second deployment about 40 s of CI's run)
SCRATCH = Path(tempfile.gettempdir()) / "kit-import"


@contextlib.contextmanager
def scratch(folder: Path) -> Iterator[Path]:
    """A scratch folder of the machine's (SCRATCH, ...), emptied, for one run
    at a time on this machine (the kernel's lock, which goes with the process
    however it ends), removed after."""
    lock_path = folder.with_name(folder.name + ".lock")
    with lock_path.open("a+") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # another clone's run: wait for it
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        try:
            yield folder
        finally:
            shutil.rmtree(folder, ignore_errors=True)


@contextlib.contextmanager
def importing_workspace(project: Path, log_dir: Path) -> Iterator[Path]:
    """A west workspace outside the clone whose manifest repository, a copy
    of the F´ project `project`, imports this clone; yields that copy, and
    removes the workspace after. The clone keeps no trace of it: west's
    manifest-rev branch, which its update adds to the kit, is taken off,
    and the clone's branch, which it leaves for the pin, put back."""
    head = _git(["rev-parse", "HEAD"])
    if head.returncode != 0:
        raise KitError(f"the kit at {KIT_ROOT} is not a git clone: a west manifest cannot import it")
    had_manifest_rev = _git(["rev-parse", "--verify", "--quiet", MANIFEST_REV]).returncode == 0
    branch = _git(["symbolic-ref", "-q", "HEAD"]).stdout.strip()
    with scratch(SCRATCH) as top:
        team = top / TEAM_FOLDER
        shutil.copytree(project, team)
        (top / KIT_FOLDER).symlink_to(KIT_ROOT, target_is_directory=True)
        (team / "west.yml").write_text(manifest(KIT_ROOT.as_uri(), head.stdout.strip()))
        try:
            _west(["init", "-l", str(team)], top, log_dir / "import-west-init.log")
            _west(["update"], team, log_dir / "import-west-update.log")
            LOG.info(f"  importing workspace: {top} ({TEAM_FOLDER}/west.yml imports the kit at {KIT_FOLDER}/)")
            yield team
        finally:
            if not had_manifest_rev:
                _git(["update-ref", "-d", MANIFEST_REV])
            # west update checks the kit's pin out detached (the same commit):
            # the clone gets its branch back, its tree untouched
            if branch and _git(["rev-parse", "HEAD"]).stdout == head.stdout:
                _git(["symbolic-ref", "HEAD", branch])


def west_kit(team: Path, args: list[str], log: Path, expect: str) -> Tally:
    """`west kit <args>` from the team's repository: one check, passed when
    west finds the kit's extension command through the import and the
    command's output says `expect`."""
    code = _run_west(["kit", *args], team, log)
    text = log.read_text(errors="replace") if log.is_file() else ""
    if code == 0 and expect in text:
        LOG.info(f"  west kit {' '.join(args[:1])} from the importing repository: PASS")
        return Tally(1, 0)
    LOG.error(f"  west kit {' '.join(args)} from the importing repository failed (exit {code}); see {log}")
    return Tally(0, 1)
