# SPDX-License-Identifier: Apache-2.0
"""Static ROM and RAM of a Zephyr build, from its ELF and its .config.

ROM is how far the allocated sections loaded into flash extend (code,
read-only data, the initial values of .data); RAM how far those placed in
SRAM extend (.data, .bss, .noinit, stacks, heap arena), alignment gaps
included. That is the linker's "Memory region" accounting, recomputed so it
is available after any build, not only after a link.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from elftools.elf.constants import SH_FLAGS
from elftools.elf.elffile import ELFFile

from kittools.build.folder import BuildFolder


@dataclass(frozen=True)
class Region:
    """A memory region of the board: where it starts, how many bytes."""
    base: int
    size: int

    def holds(self, address: int) -> bool:
        return self.base <= address < self.base + self.size


def flash(folder: BuildFolder) -> Region:
    config = folder.kconfig()
    return Region(int(config["CONFIG_FLASH_BASE_ADDRESS"], 0), int(config["CONFIG_FLASH_SIZE"]) * 1024)


def sram(folder: BuildFolder) -> Region:
    config = folder.kconfig()
    return Region(int(config["CONFIG_SRAM_BASE_ADDRESS"], 0), int(config["CONFIG_SRAM_SIZE"]) * 1024)


@dataclass(frozen=True)
class Footprint:
    rom: int
    ram: int
    rom_size: int
    ram_size: int


def measure(build_dir: Path) -> Footprint:
    """Footprint of the Zephyr build in `build_dir`."""
    folder = BuildFolder(build_dir)
    for path in (folder.elf, folder.config):
        if not path.is_file():
            raise FileNotFoundError(f"{path} is missing: is {build_dir} a finished Zephyr build?")
    rom, ram = flash(folder), sram(folder)
    rom_end, ram_end = rom.base, ram.base
    with folder.elf.open("rb") as stream:
        elf = ELFFile(stream)
        # Load addresses come from the program headers: a section's LMA is its
        # VMA shifted by the offset of the segment that holds it.
        segments = [s for s in elf.iter_segments() if s["p_type"] == "PT_LOAD"]
        for section in elf.iter_sections():
            if not section["sh_flags"] & SH_FLAGS.SHF_ALLOC or section["sh_size"] == 0:
                continue
            vma, size = section["sh_addr"], section["sh_size"]
            lma = vma
            for seg in segments:
                if seg["p_vaddr"] <= vma < seg["p_vaddr"] + seg["p_memsz"]:
                    lma = seg["p_paddr"] + (vma - seg["p_vaddr"])
                    break
            if ram.holds(vma):
                ram_end = max(ram_end, vma + size)
            if rom.holds(lma) and section["sh_type"] != "SHT_NOBITS":
                rom_end = max(rom_end, lma + size)
    return Footprint(rom=rom_end - rom.base, ram=ram_end - ram.base, rom_size=rom.size, ram_size=ram.size)
