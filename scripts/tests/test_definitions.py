# SPDX-License-Identifier: Apache-2.0
"""Sources of a build's symbols from its own objects, where an LTO image's
DWARF names none (kittools.sizes.definitions), and the RAM report limited to
SRAM (kittools.sizes.size_report)."""

import json
import shutil
import subprocess

import pytest

from kittools.sizes import definitions, memory, size_report

COMPILER = shutil.which("arm-none-eabi-gcc")


def test_a_clone_is_defined_where_its_function_is():
    sources = {"uart_init": "/z/drivers/uart.c", "main": "/kit/app/src/main.cpp"}
    assert definitions.defined_in("uart_init", sources) == "/z/drivers/uart.c"
    assert definitions.defined_in("uart_init.lto_priv.1", sources) == "/z/drivers/uart.c"
    # Zephyr's main thread entry holds main() inlined under LTO
    assert definitions.defined_in("bg_thread_main.lto_priv.0", sources) == "/kit/app/src/main.cpp"
    assert definitions.defined_in("z_static", sources) is None
    # ... not where the DWARF names its source: no LTO inlined main into it there
    assert definitions.defined_in("bg_thread_main", sources, inlined=False) is None


@pytest.mark.skipif(COMPILER is None, reason="needs the arm-none-eabi toolchain (scripts/setup.sh provisions it)")
def test_an_lto_builds_objects_name_each_symbols_source(tmp_path):
    build = tmp_path / "build"
    (build / "zephyr").mkdir(parents=True)
    (build / "CMakeCache.txt").write_text(f"CMAKE_C_COMPILER:FILEPATH={COMPILER}\n")
    sources = {"strong.c": "int shared(void) { return 1; }\nint buffer[4];\n",
               "weak.c": "__attribute__((weak)) int shared(void) { return 0; }\nint only_weak_file(void) {return 2;}\n"
                         "__attribute__((weak)) int inline_like(void) { return 3; }\n"
                         "__attribute__((weak)) int weak_once(void) { return 4; }\n",
               "other.c": "__attribute__((weak)) int inline_like(void) { return 3; }\n"}
    commands = []
    for name, text in sources.items():
        source = tmp_path / name
        source.write_text(text)
        output = f"CMakeFiles/app.dir/{name}.obj"
        (build / output).parent.mkdir(parents=True, exist_ok=True)
        subprocess.run([str(COMPILER), "-flto", "-fno-common", "-c", str(source), "-o", str(build / output)],
                       check=True)
        commands.append({"directory": str(build), "file": str(source), "output": output, "command": "cc"})
    (build / "compile_commands.json").write_text(json.dumps(commands))
    found = definitions.defining_sources(build)
    assert found["shared"] == str(tmp_path / "strong.c")  # the strong definition, not the weak one
    assert found["buffer"] == str(tmp_path / "strong.c")
    assert found["only_weak_file"] == str(tmp_path / "weak.c")
    assert found["weak_once"] == str(tmp_path / "weak.c")  # weak, made in one source only
    assert "inline_like" not in found  # weak in two sources (a header's inline function): neither is its home


class _Section(dict):
    pass


class _Elf:
    def __init__(self, sizes):
        self.sizes = sizes

    def get_section_by_name(self, name):
        return _Section(sh_size=self.sizes[name])


def test_the_ram_report_counts_only_what_sram_holds():
    """LTO leaves rodata writable in flash: size_report counted it as RAM."""
    ranges = {"ram": [{"start": 0x21980, "end": 0x21980 + 0x58c7, "name": "rodata"},
                      {"start": 0x20000000, "end": 0x20000054, "name": "datas"}],
              "ram_total_size": 0x58c8 + 0x55, "rom": [], "rom_total_size": 0}
    kept = size_report._in_sram(ranges, memory.Region(0x20000000, 64 * 1024), _Elf({"rodata": 0x58c8, "datas": 0x55}))
    assert [bound["name"] for bound in kept["ram"]] == ["datas"]
    assert kept["ram_total_size"] == 0x55


def test_a_region_holds_its_addresses_only():
    sram = memory.Region(0x20000000, 0x10000)
    assert sram.holds(0x20000000) and sram.holds(0x2000FFFF)
    assert not sram.holds(0x20010000) and not sram.holds(0x1FFFFFFF)


class _Attribute:
    def __init__(self, value):
        self.value = value


class _Entry:
    def __init__(self, tag, parent=None, specification=None, **attributes):
        self.tag = tag
        self.parent = parent
        self.specification = specification
        self.attributes = {f"DW_AT_{key}": _Attribute(value) for key, value in attributes.items()}
        if specification is not None:
            self.attributes["DW_AT_specification"] = _Attribute(0)

    def iter_children(self):
        return iter(self.children)

    def get_parent(self):
        return self.parent

    def get_DIE_from_attribute(self, name):
        assert name == "DW_AT_specification"
        return self.specification


class _Unit:
    def __init__(self, name, comp_dir, *children):
        self.top = _Entry("DW_TAG_compile_unit", name=name, comp_dir=comp_dir)
        self.top.children = list(children)

    def get_top_DIE(self):
        return self.top


class _Dwarf:
    def __init__(self, *units):
        self.units = units

    def iter_CUs(self):
        return iter(self.units)


def test_an_lto_images_early_debug_names_the_source_of_a_c_static():
    """LTO's own unit names no source; each source's early unit names what
    it defines, a declaration elsewhere does not count, and a name two
    sources define (a static in each) names neither."""
    dwarf = _Dwarf(
        _Unit(b"<artificial>", b"/b", _Entry("DW_TAG_variable", name=b"crc_tab32")),
        _Unit(b"../deps/fprime/Utils/Hash/libcrc/lib_crc.c", b"/ws/build",
              _Entry("DW_TAG_variable", name=b"crc_tab32"), _Entry("DW_TAG_subprogram", name=b"elapsed")),
        _Unit(b"../deps/zephyr/kernel/timeout.c", b"/ws/build", _Entry("DW_TAG_subprogram", name=b"elapsed"),
              _Entry("DW_TAG_variable", name=b"crc_tab32", declaration=True)),
    )
    assert definitions.early_debug_sources(dwarf) == {"crc_tab32": "/ws/deps/fprime/Utils/Hash/libcrc/lib_crc.c"}


def test_a_cpp_variable_in_namespaces_is_named_by_its_declarations_scope():
    """Kit::RamFs's anonymous s_region: its definition at the unit's top
    level points at its declaration inside the namespaces."""
    kit = _Entry("DW_TAG_namespace", name=b"Kit")
    ram_fs = _Entry("DW_TAG_namespace", parent=kit, name=b"RamFs")
    anonymous = _Entry("DW_TAG_namespace", parent=ram_fs)
    declaration = _Entry("DW_TAG_variable", parent=anonymous, name=b"s_region", declaration=True)
    definition = _Entry("DW_TAG_variable", specification=declaration)
    function = _Entry("DW_TAG_subprogram", specification=declaration)
    dwarf = _Dwarf(_Unit(b"../app/src/RamFs.cpp", b"/ws/build", kit, definition, function))
    assert definitions.early_debug_sources(dwarf) == {
        "_ZN3Kit5RamFs12_GLOBAL__N_18s_regionE": "/ws/app/src/RamFs.cpp"}
