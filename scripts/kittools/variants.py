# SPDX-License-Identifier: Apache-2.0
"""The kit's variants, from their one table (app/variants.yaml).

A data file rather than a Python table: the suite's pytest harness
(tests/deployment/pytest, run by twister outside this package) and anyone
reading app/ beside the twister suites find it there, and it is the same
list of Kconfig settings the suites hold, in the same form.
"""

from __future__ import annotations

import argparse
import functools
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kittools.workspace import KIT_ROOT, VARIANTS, KitError

VARIANTS_FILE = KIT_ROOT / "app" / "variants.yaml"
#: The setting that picks a variant's execution model: CONFIG_KIT_MODEL_<MODEL>=y
MODEL_SETTING = "CONFIG_KIT_MODEL_"


@dataclass(frozen=True)
class Variant:
    name: str
    description: str
    kconfig: tuple[str, ...]  # CONFIG_X=value

    @property
    def model(self) -> str:
        """The execution model (its folder): what a knob or port that is
        one model's applies to, whatever the policy."""
        return next(s.removeprefix(MODEL_SETTING).split("=", 1)[0].lower()
                    for s in self.kconfig if s.startswith(MODEL_SETTING))

    def cmake_args(self) -> list[str]:
        """The settings as `west build ... --` takes them."""
        return [f"-D{setting}" for setting in self.kconfig]


def _variant(name: str, entry: Any, path: Path) -> Variant:
    if not isinstance(entry, dict) or not isinstance(entry.get("kconfig"), list):
        raise KitError(f"{path}: variant {name} has no kconfig list")
    kconfig = tuple(str(s) for s in entry["kconfig"])
    if any(not s.startswith("CONFIG_") or "=" not in s for s in kconfig):
        raise KitError(f"{path}: variant {name}: every setting is CONFIG_X=value, got {list(kconfig)}")
    models = [s for s in kconfig if s.startswith(MODEL_SETTING)]
    if len(models) != 1 or not models[0].endswith("=y"):
        raise KitError(f"{path}: variant {name} picks {len(models)} models ({models}): it needs one "
                       f"{MODEL_SETTING}<MODEL>=y")
    found = Variant(name, str(entry.get("description", "")), kconfig)
    if found.model not in VARIANTS:
        raise KitError(f"{path}: variant {name}: no model {found.model} (the models: {', '.join(VARIANTS)})")
    return found


@functools.cache
def table(path: Path = VARIANTS_FILE) -> dict[str, Variant]:
    """Every variant by name, in the file's order."""
    import yaml

    try:
        entries = yaml.safe_load(path.read_text())["variants"]
    except (OSError, KeyError, TypeError, yaml.YAMLError) as error:
        raise KitError(f"{path} lists no variants: {error}") from error
    if not isinstance(entries, dict) or not entries:
        raise KitError(f"{path} lists no variants")
    return {str(name): _variant(str(name), entry, path) for name, entry in entries.items()}


def names() -> tuple[str, ...]:
    return tuple(table())


def get(name: str) -> Variant:
    try:
        return table()[name]
    except KeyError:
        raise KitError(f"unknown variant '{name}'; the variants are: {', '.join(names())} "
                       f"({VARIANTS_FILE.relative_to(KIT_ROOT)})") from None


def add_model_option(parser: argparse.ArgumentParser, usage: str, default: str | None = None,
                     repeatable: bool = False) -> None:
    """--model, as every command that builds or picks a variant takes it:
    the table's names, described from the table; `usage` says what this
    command does with it and its default."""
    # argparse formats help with %: a description's own is escaped
    described = "; ".join(f"{v.name}: {v.description}" for v in table().values()).replace("%", "%%")
    parser.add_argument("--model", default=default, choices=names(), action="append" if repeatable else "store",
                        help=f"the variant ({VARIANTS_FILE.relative_to(KIT_ROOT)}: {described}); {usage}")
