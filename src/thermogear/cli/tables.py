"""Any JSON summary as readable tables: units from the key names, numbers to 5 significant digits.

Case files and JSON summaries carry the unit in the key (``flank_temperature_c``, ``stiffness_drop_percent``,
``thermal_stiffness_n_per_mm_um``). :func:`dict_tables` turns a nested summary dict into one table of rows
``quantity | value | unit`` and, for a dict of dicts with the same keys (values at the path points A–E, elastic
and thermal minimum/mean/maximum), a matrix table with one column per outer key. New keys need no code here.
"""

from __future__ import annotations

import math
from typing import Any

from rich.table import Table
from rich.text import Text

__all__ = ["DIMENSIONLESS", "PROPER_NAMES", "UNIT_SUFFIXES", "dict_tables", "format_value", "split_unit"]

#: Key suffix → unit, longest first (a key ending in ``_n_per_mm_um`` is not read as ``_um``).
UNIT_SUFFIXES: tuple[tuple[str, str], ...] = (
    ("_n_per_mm_um", "N/(mm·μm)"), ("_n_s_per_m", "N·s/m"), ("_n_per_mm", "N/mm"), ("_n_per_m", "N/m"),
    ("_gpa", "GPa"),
    ("_mm2_s", "mm²/s"), ("_mpa_s", "mPa·s"), ("_kg_m3", "kg/m³"), ("_per_k", "1/K"), ("_percent", "%"),
    ("_deg", "°"), ("_rpm", "rpm"), ("_kw", "kW"), ("_nm", "N·m"), ("_hz", "Hz"), ("_um", "μm"), ("_mm", "mm"),
    ("_c", "°C"), ("_k", "K"), ("_s", "s"), ("_m", "m"), ("_n", "N"), ("_w", "W"), ("_pa", "Pa"),
)


#: Words of key names as a reader writes them (whole words only, applied in order).
PROPER_NAMES: tuple[tuple[str, str], ...] = (
    ("youngs modulus", "Young's modulus"), ("x te", "X_te"), ("backlash normal", "normal backlash"),
    ("peak to peak", "peak-to-peak"), ("gamma", "Γ"), ("single tooth", "single-tooth"),
)

#: Unit column of a number whose key names no unit: a ratio, a factor, a count.
DIMENSIONLESS = "–"

#: Number lists longer than this are summarised (count, smallest and largest) instead of listed in a cell.
LIST_ITEMS_SHOWN = 4


def _proper(label: str) -> str:
    text = f" {label} "
    for words, name in PROPER_NAMES:
        text = text.replace(f" {words} ", f" {name} ")
    return text.strip()


def split_unit(key: str) -> tuple[str, str | None]:
    """(label in words, unit) of a key: ``"flank_temperature_c"`` → ``("flank temperature", "°C")``; a unit of
    three letters or more also inside the key: ``"stiffness_drop_percent_range"`` → ``("stiffness drop range",
    "%")``; words named as a reader writes them (``"youngs_modulus_gpa"`` → ``("Young's modulus", "GPa")``)."""
    for suffix, unit in UNIT_SUFFIXES:
        if key.endswith(suffix) and len(key) > len(suffix):
            return _proper(key[: -len(suffix)].replace("_", " ")), unit
    for suffix, unit in UNIT_SUFFIXES:
        if len(suffix) >= 4 and f"{suffix}_" in key[1:]:
            return _proper(key.replace(f"{suffix}_", "_", 1).replace("_", " ")), unit
    return _proper(key.replace("_", " ")), None


def format_value(value: Any) -> str:
    """A value for a table cell: 5 significant digits, yes/no, — for None, lists joined."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:.5g}" if math.isfinite(value) else str(value)
    if isinstance(value, (list, tuple)):
        if not value:
            return "none"
        numbers = [item for item in value if isinstance(item, (int, float)) and not isinstance(item, bool)]
        if len(value) > LIST_ITEMS_SHOWN and len(numbers) == len(value):
            return f"{len(value)} values, {format_value(min(numbers))} to {format_value(max(numbers))}"
        return ", ".join(format_value(item) for item in value)
    try:  # NumPy scalars
        return format_value(value.item())
    except AttributeError:
        return str(value)


def _is_matrix(value: dict) -> bool:
    """A dict of at least two dicts with the same keys and scalar values."""
    inner = list(value.values())
    return (len(inner) >= 2 and all(isinstance(item, dict) and item for item in inner)
            and all(list(item) == list(inner[0]) for item in inner)
            and not any(isinstance(leaf, dict) for item in inner for leaf in item.values()))


def _join(prefix: str, label: str) -> str:
    return f"{prefix}, {label}" if prefix else label


def dict_tables(title: str, data: dict) -> list[Table | Text]:
    """Renderables of a nested summary dict: a table of its numbers, one matrix table per dict of like dicts,
    then its texts as ``label: text`` lines (a sentence in a value column would widen the whole table)."""
    main = Table(title=title)
    main.add_column("quantity")
    main.add_column("value", justify="right")
    main.add_column("unit")
    matrices: list[Table] = []
    notes: list[Text] = []

    def walk(prefix: str, unit: str | None, value: Any) -> None:
        if isinstance(value, dict) and value and _is_matrix(value):
            matrices.append(_matrix(prefix, unit, value))
        elif isinstance(value, dict):
            for key, item in value.items():
                label, own_unit = split_unit(str(key))
                walk(_join(prefix, label), own_unit or unit, item)
        elif isinstance(value, str) and len(value) > 24:
            notes.append(Text(f"{prefix}: {value}"))
        elif isinstance(value, (list, tuple)) and any(isinstance(item, str) for item in value):
            notes.extend(Text(f"{prefix}: {item}") for item in value)  # sentences: one line each, not a cell
        else:
            main.add_row(prefix, format_value(value), unit or _unit_of_unnamed(value))

    walk("", None, data)
    return ([main] if main.row_count else []) + matrices + notes


def _unit_of_unnamed(value: Any) -> str:
    """The unit cell of a value whose key names no unit: – for a number, nothing for text or yes/no."""
    numbers = value if isinstance(value, (list, tuple)) else [value]
    if numbers and all(isinstance(item, (int, float)) and not isinstance(item, bool) for item in numbers):
        return DIMENSIONLESS
    return ""


def _matrix(label: str, unit: str | None, value: dict) -> Table:
    table = Table(title=f"{title_case(label)}" + (f" [{unit}]" if unit else ""))
    table.add_column("quantity")
    for column in value:
        table.add_column(str(column), justify="right")
    table.add_column("unit")
    for key in next(iter(value.values())):
        row_label, row_unit = split_unit(str(key))
        cells = [item[key] for item in value.values()]
        table.add_row(row_label, *(format_value(cell) for cell in cells),
                      row_unit or unit or (DIMENSIONLESS if any(_unit_of_unnamed(cell) for cell in cells) else ""))
    return table


def title_case(label: str) -> str:
    return label[:1].upper() + label[1:]
