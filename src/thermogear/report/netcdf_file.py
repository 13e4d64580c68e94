"""Write netCDF-4 groups straight with h5netcdf, without xarray.

The report's ``results.nc`` is a handful of arrays per group; building xarray Datasets for it imports xarray,
pandas and (through xarray's writer, which asks for a dask scheduler) dask and distributed: about a second of a
two-second results file. The parts are the same ``(dimensions, values, attributes)`` tuples an
``xarray.Dataset`` takes, and the file reads back with ``xarray.open_dataset(path, engine="h5netcdf", group=…)``
as before: dimension coordinates are variables named after their dimension, other coordinates are named in the
``coordinates`` attribute of the variables that share their dimensions (the CF convention xarray follows).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["DatasetParts", "write_groups"]

#: (data variables, coordinates, attributes): each variable ``name → (dims, values[, attrs])``.
DatasetParts = tuple[dict[str, tuple], dict[str, tuple], dict[str, Any]]


def _unpack(item: tuple) -> tuple[tuple[str, ...], np.ndarray, dict]:
    dims, values, *rest = item
    dims = (dims,) if isinstance(dims, str) else tuple(dims)
    return dims, np.asarray(values), dict(rest[0]) if rest else {}


def _write_group(group, parts: DatasetParts) -> None:
    data_vars, coords, attrs = parts
    variables = {name: _unpack(item) for name, item in {**coords, **data_vars}.items()}
    sizes: dict[str, int] = {}
    for name, (dims, values, _) in variables.items():
        if len(dims) != values.ndim:
            raise ValueError(f"{name}: {len(dims)} dimensions named for an array of {values.ndim}")
        for dim, size in zip(dims, values.shape):
            if sizes.setdefault(dim, size) != size:
                raise ValueError(f"{name}: dimension {dim} has size {size} here and {sizes[dim]} elsewhere")
    group.dimensions = sizes
    auxiliary = [name for name in coords if name not in sizes]  # coordinates that are not dimensions (roll)
    for name, (dims, values, own) in variables.items():
        if values.dtype == bool:
            values = values.astype(np.int8)
        if values.dtype.kind in "OU":  # names (e.g. bearings): HDF5 variable-length strings, which xarray reads back
            import h5py  # noqa: PLC0415

            variable = group.create_variable(name, dims, dtype=h5py.string_dtype(), data=values.astype(object))
        else:
            variable = group.create_variable(name, dims, data=values)
        labels = [other for other in auxiliary if other != name and set(variables[other][0]) <= set(dims)]
        if labels and name not in coords:
            own = {**own, "coordinates": " ".join(labels)}
        for key, value in own.items():
            variable.attrs[key] = value
    for key, value in attrs.items():
        group.attrs[key] = int(value) if isinstance(value, bool) else value


def write_groups(path: Path, root: DatasetParts, groups: dict[str, DatasetParts]) -> list[str]:
    """Write ``root`` into the root group of a new file ``path`` and each of ``groups`` into a group of that
    name; returns the group names."""
    import h5netcdf  # noqa: PLC0415

    with h5netcdf.File(path, "w") as file:
        _write_group(file, root)
        for name, parts in groups.items():
            _write_group(file.create_group(name), parts)
    return list(groups)
