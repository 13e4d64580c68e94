"""Results as CSV: one row per point of a sweep or per time sample of a response, units in the column names.

:func:`dataset_rows` turns an xarray Dataset (a sweep store, a group of a report's ``results.nc``, a response's
``to_xarray()``) into a header and rows along its row dimensions: a variable over the row dimensions is one
column; one with a further dimension (``model`` of a sweep, ``slot`` of the pair loads) gives one column per
label of it (``kv_elastic``, ``pair_load_0``). :func:`write_csv` writes such blocks with comment lines on top
(``# thermogear 0.1.0``, the case, the source) that ``pandas.read_csv(path, comment="#")`` skips.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, TextIO

import numpy as np

__all__ = ["CsvBlock", "dataset_rows", "default_row_dimensions", "write_csv"]


@dataclass(frozen=True)
class CsvBlock:
    """Columns and rows of one dataset, and what it left out (variables on other dimensions)."""

    columns: tuple[str, ...]
    rows: np.ndarray  # (rows, columns), object array of numbers or texts
    left_out: tuple[str, ...]


def _column(name: str, attrs: dict) -> str:
    units = str(attrs.get("units", "")).strip()
    return f"{name} [{units}]" if units and units != "1" else name


def default_row_dimensions(dataset) -> tuple[str, ...]:
    """The dimensions a table of ``dataset`` runs along: those of the variable with the most dimensions among the
    dimensions most variables share (a sweep store: every swept parameter, without ``model``; a response group:
    ``time``)."""
    counts: dict[str, int] = {}
    for variable in dataset.data_vars.values():
        for dimension in variable.dims:
            counts[dimension] = counts.get(dimension, 0) + 1
    if not counts:
        return ()
    if "model" in dataset.dims and "model" in counts:  # a sweep store: one row per point, the models in columns
        widest = max(dataset.data_vars.values(), key=lambda variable: len(variable.dims))
        grid = [name for name in widest.dims if name != "model"]
        if grid:
            return tuple(grid)
    best = max(counts, key=lambda name: (counts[name], dataset.sizes[name]))
    return (best,)


def dataset_rows(dataset, dimensions: Iterable[str] | None = None) -> CsvBlock:
    """The table of ``dataset`` along ``dimensions`` (default: :func:`default_row_dimensions`)."""
    dimensions = tuple(dimensions) if dimensions is not None else default_row_dimensions(dataset)
    shape = tuple(dataset.sizes[name] for name in dimensions)
    count = int(np.prod(shape)) if shape else 1
    columns: list[str] = []
    values: list[np.ndarray] = []
    for name in dimensions:  # the coordinates first, one value per row
        coordinate = dataset[name] if name in dataset.variables else None
        labels = np.asarray(coordinate.values) if coordinate is not None else np.arange(dataset.sizes[name])
        grid = np.broadcast_to(labels.reshape([-1 if d == name else 1 for d in dimensions]), shape)
        columns.append(_column(name, coordinate.attrs if coordinate is not None else {}))
        values.append(grid.reshape(count))
    left_out = []

    def flat(array) -> np.ndarray:  # a DataArray over some of the row dimensions, repeated over the others
        for name in dimensions:
            if name not in array.dims:
                array = array.expand_dims({name: dataset.sizes[name]})
        return np.asarray(array.transpose(*dimensions).values).reshape(count)

    others = [(name, coordinate) for name, coordinate in dataset.coords.items() if name not in dataset.dims
              and coordinate.dims and set(coordinate.dims) <= set(dimensions)]  # e.g. roll beside gamma
    for name, variable in [*others, *dataset.data_vars.items()]:
        extra = [d for d in variable.dims if d not in dimensions]
        if len(extra) > 1 or not set(variable.dims) & set(dimensions):
            left_out.append(name)
            continue
        if extra:
            labels = (dataset[extra[0]].values if extra[0] in dataset.variables
                      else np.arange(dataset.sizes[extra[0]]))
            for index, label in enumerate(labels):
                values.append(flat(variable.isel({extra[0]: index})))
                columns.append(_column(f"{name}_{_label(label)}", variable.attrs))
        else:
            values.append(flat(variable))
            columns.append(_column(name, variable.attrs))
    rows = np.empty((count, len(columns)), dtype=object)
    for index, column in enumerate(values):
        rows[:, index] = column
    return CsvBlock(tuple(columns), rows, tuple(left_out))


def _label(value: Any) -> str:
    text = value.decode() if isinstance(value, bytes) else str(value)
    try:
        number = float(text)
        return f"{number:g}"
    except ValueError:
        return text


def _text(value: Any) -> str:
    if isinstance(value, (float, np.floating)):
        return repr(float(value)) if math.isfinite(value) else ("nan" if math.isnan(value) else str(float(value)))
    if isinstance(value, (np.integer, int)) and not isinstance(value, bool):
        return str(int(value))
    if isinstance(value, bytes):
        return value.decode()
    return str(value)


def write_csv(target: Path | TextIO, header: list[str], blocks: list[tuple[dict[str, str], CsvBlock]]) -> int:
    """Write comment lines (``# …``) then one table: every block's rows under the union of their columns, each
    block's leading label columns (e.g. ``{"model": "elastic"}``) first. Returns the number of rows."""
    labels = list(dict.fromkeys(key for label, _ in blocks for key in label))
    columns = labels + list(dict.fromkeys(column for _, block in blocks for column in block.columns))
    if isinstance(target, Path):
        with target.open("w", newline="", encoding="utf-8") as stream:
            return write_csv(stream, header, blocks)
    for line in header:
        target.write(f"# {line}\n")
    writer = csv.writer(target, lineterminator="\n")
    writer.writerow(columns)
    written = 0
    for label, block in blocks:
        position = {column: index for index, column in enumerate(block.columns)}
        for row in block.rows:
            writer.writerow([label.get(column, "") if column in labels else
                             (_text(row[position[column]]) if column in position else "") for column in columns])
            written += 1
    return written
