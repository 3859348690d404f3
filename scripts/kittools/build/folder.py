# SPDX-License-Identifier: Apache-2.0
"""A build folder and everything the kit reads from it: the one place that
knows where a build (west build -d, or one of twister's) keeps its ELF, its
Kconfig values (.config), its CMake cache, its compile commands, F´'s
dictionary and constants, and twister's console log; and how to read them.

Every other module asks a `BuildFolder`, so that a file that moves (a Zephyr
or F´ upgrade) is followed here once.
"""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path

from kittools.workspace import KIT_ROOT, KitError

#: The image Zephyr links, relative to the build folder
ELF = "zephyr/zephyr.elf"
#: The Kconfig values Zephyr resolved
CONFIG = "zephyr/.config"
#: CMake's cache: the variables the build was configured with
CMAKE_CACHE = "CMakeCache.txt"
#: Every compilation's command line (CMAKE_EXPORT_COMPILE_COMMANDS)
COMPILE_COMMANDS = "compile_commands.json"
#: F´'s dictionary of the topology (its fpp-to-json output)
DICTIONARIES = "build-artifacts/**/dict/*TopologyDictionary.json"
#: F´'s constants of the kit's configuration (app/config), as autocoded
FPP_CONSTANTS = "F-Prime/default/config/FppConstantsAc.hpp"
#: FPP's C++ header of each topology and subtopology the build generated
TOPOLOGY_HEADERS = "**/*TopologyAc.hpp"
#: Where twister's QEMU handler keeps a build's console
CONSOLE_LOG = "handler.log"
#: Where twister keeps a build's output (the compiler's and the linker's)
BUILD_LOG = "build.log"

#: The kit's Kconfig files: the models', the deployment's, the boards' defaults, the modules'
KIT_KCONFIG_FILES = ("app/**/Kconfig*", "*/Kconfig.model", "boards/**/Kconfig*", "modules/**/Kconfig*")
#: Beside a build the kit configures itself: the digest of the Kconfig files it was configured from
KCONFIG_STAMP = "kit-kconfig.sha256"


def kit_kconfig_digest(root: Path = KIT_ROOT) -> str:
    """The kit's Kconfig files, as one digest. Ninja configures a build
    again when one changes, but Zephyr then takes the build's last .config
    as input, which keeps every prompted symbol's old value: a changed
    default reaches a build only configured from its fragments again."""
    digest = hashlib.sha256()
    for kconfig in sorted({path for pattern in KIT_KCONFIG_FILES for path in root.glob(pattern) if path.is_file()}):
        digest.update(f"{kconfig.relative_to(root)}\0".encode() + kconfig.read_bytes() + b"\0")
    return digest.hexdigest()


#: The F´ switches of modules/fprime/Kconfig start with this
FPRIME_SWITCH = "CONFIG_FPRIME_"
# F´ settings passed as compile definitions (app/kit.cmake)
_FW_DEFINE = re.compile(r"-D(FW_[A-Z_]+)=(\S+)")
#: F´ constants from the kit's configuration (app/config)
FPP_CONSTANT_NAMES = ("FW_COM_BUFFER_MAX_SIZE", "FW_LOG_STRING_MAX_SIZE", "FW_TLM_BUFFER_MAX_SIZE",
                      "FW_FIXED_LENGTH_STRING_SIZE", "FW_ASSERT_COUNT_MAX")


def parse_kconfig(text: str) -> dict[str, str]:
    """A .config's text as symbol -> value (quotes stripped)."""
    values: dict[str, str] = {}
    for line in text.splitlines():
        if line.startswith("CONFIG_") and "=" in line:
            key, value = line.split("=", 1)
            values[key] = value.strip('"')
    return values


class BuildFolder:
    """A build folder: the paths of what the kit reads in it, and readers."""

    def __init__(self, path: Path) -> None:
        self.path = Path(path)

    def __repr__(self) -> str:
        return f"BuildFolder({str(self.path)!r})"

    @staticmethod
    def built_under(root: Path, name: str = "*") -> list[BuildFolder]:
        """The build folders named `name` under `root` (at any depth) that
        hold a linked image."""
        return [BuildFolder(elf.parents[len(Path(ELF).parts) - 1]) for elf in root.glob(f"**/{name}/{ELF}")]

    @staticmethod
    def configured_under(root: Path) -> list[BuildFolder]:
        """The build folders under `root` (at any depth) that CMake
        configured, linked or not."""
        return [BuildFolder(cache.parent) for cache in root.glob(f"**/{CMAKE_CACHE}")]

    def take_kconfig_defaults(self, digest: str) -> None:
        """Before a build the kit configures itself: drop its .config when
        the kit's Kconfig files changed since (or it has no stamp), so that
        Zephyr configures it from its fragments and today's defaults
        (kit_kconfig_digest says why); mark_kconfig(digest) after it built."""
        stamp = self.path / KCONFIG_STAMP
        if not stamp.is_file() or stamp.read_text().strip() != digest:
            self.config.unlink(missing_ok=True)

    def mark_kconfig(self, digest: str) -> None:
        (self.path / KCONFIG_STAMP).write_text(digest + "\n")

    # --- Paths ----------------------------------------------------------

    @property
    def elf(self) -> Path:
        return self.path / ELF

    @property
    def config(self) -> Path:
        return self.path / CONFIG

    @property
    def cmake_cache(self) -> Path:
        return self.path / CMAKE_CACHE

    @property
    def compile_commands(self) -> Path:
        return self.path / COMPILE_COMMANDS

    @property
    def fpp_constants(self) -> Path:
        return self.path / FPP_CONSTANTS

    @property
    def console_log(self) -> Path:
        return self.path / CONSOLE_LOG

    @property
    def build_log(self) -> Path:
        return self.path / BUILD_LOG

    def configured(self) -> bool:
        """CMake configured the folder (it has a cache)."""
        return self.cmake_cache.is_file()

    # --- Readers --------------------------------------------------------

    def built_elf(self) -> Path:
        """The linked image; KitError when the build has none."""
        if not self.elf.is_file():
            raise KitError(f"{self.elf} is missing: build first")
        return self.elf

    def dictionary(self) -> Path:
        """The F´ dictionary the build made; KitError when it has none."""
        dictionaries = sorted(self.path.glob(DICTIONARIES))
        if not dictionaries:
            raise KitError(f"{self.path} has no F´ dictionary: build it first (west build -d {self.path})")
        return dictionaries[0]

    def topology_headers(self) -> list[Path]:
        """The C++ headers FPP generated for the build's topology and its
        subtopologies (none before a build)."""
        return sorted(self.path.glob(TOPOLOGY_HEADERS))

    def kconfig(self, missing_ok: bool = False) -> dict[str, str]:
        """The build's Kconfig values (its .config) as symbol -> value,
        quotes stripped. A folder never configured has no .config:
        FileNotFoundError, or {} when `missing_ok`."""
        if missing_ok and not self.config.is_file():
            return {}
        return parse_kconfig(self.config.read_text())

    def fprime_switches(self) -> dict[str, str]:
        """The F´ switches of the build (modules/fprime/Kconfig), as its
        .config has them."""
        return {k: v for k, v in self.kconfig().items() if k.startswith(FPRIME_SWITCH)}

    def cache_value(self, name: str) -> str | None:
        """A variable of the build's CMake cache, or None when it is not set;
        KitError when the folder was never configured."""
        if not self.configured():
            raise KitError(f"{self.path} is not a configured build (no {CMAKE_CACHE})")
        match = re.search(rf"^{name}:[A-Z]+=(.+)$", self.cmake_cache.read_text(), re.MULTILINE)
        return match.group(1) if match else None

    def fprime_settings(self) -> dict[str, str]:
        """The F´ settings the build was compiled with: the FW_ definitions
        of its compile commands (app/kit.cmake) and the F´ constants of the
        kit's configuration (FppConstantsAc.hpp); those it lacks are left out."""
        settings: dict[str, str] = {}
        if self.compile_commands.is_file():
            for entry in json.loads(self.compile_commands.read_text()):
                found = dict(_FW_DEFINE.findall(entry.get("command", "")))
                if found:
                    settings.update(found)
                    break
        if self.fpp_constants.is_file():
            text = self.fpp_constants.read_text()
            for name in FPP_CONSTANT_NAMES:
                match = re.search(rf"\b{name}\s*=\s*(\d+)", text)
                if match:
                    settings[name] = match.group(1)
        return settings
