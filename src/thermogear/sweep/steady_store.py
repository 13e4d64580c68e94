"""The zarr store of a gearbox's steady sweep (`thermogear gearbox CASE --speeds … --torques … --out X.zarr`).

The grid of :func:`thermogear.gearbox.sweep.steady_sweep` as an xarray Dataset, written the way the studies write
theirs (:func:`thermogear.sweep.branches.write_branch_store`: the ownership marker, a hidden sibling folder renamed
into place, ``--overwrite`` only of thermogear's own store holding nothing else, consolidated metadata):

* coordinates ``speed_rpm`` [rpm] and ``torque_nm`` [N·m] (pinion);
* per point: the node temperatures ``temperature_pinion`` … ``temperature_housing`` [°C], the losses by source
  [W] (``injection_loss`` only with an oil jet) and their sum, the efficiency [–], the normal backlash [m];
* ``runaway`` (1 where the network has no steady state: thermal runaway) and ``valid`` (its complement); every other
  variable is NaN there, and NaN is never a value: read the flags;
* attributes: the case (name, source, document as JSON), the ambient temperature, thermogear's version, and
  ``row_dimensions`` (``thermogear export`` writes one row per speed × torque).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from thermogear.errors import CaseError
from thermogear.gearbox.losses import NODES
from thermogear.ownership import is_owned, require_no_foreign_entries, resolve_output

__all__ = ["STORE_KIND", "check_steady_store_target", "steady_dataset", "write_steady_store"]

#: The ownership kind of the store (the studies' own: ``thermogear export`` and ``--overwrite`` treat it alike).
STORE_KIND = "sweep-store"


def check_steady_store_target(path: str | Path, overwrite: bool) -> Path:
    """Before any work: an existing ``--out`` is refused unless ``overwrite``, and then only when it is a store
    thermogear wrote that holds nothing else (CaseError naming the path; nothing is touched)."""
    target = resolve_output(path)
    if not (target.exists() or target.is_symlink()):
        return target
    if not overwrite:
        raise CaseError("--out", str(target), "a path that does not exist yet (or --overwrite)",
                        "the result store exists; overwrite it explicitly")
    if not is_owned(target, STORE_KIND):
        what = "a file" if target.is_file() else "a folder" if target.is_dir() else "a path"
        raise CaseError("--out", str(target), "a sweep-store folder written by thermogear",
                        f"{what} that thermogear did not write is never overwritten; nothing was changed")
    require_no_foreign_entries(target)
    return target


def steady_dataset(result, case_name: str, case_source: str, case_document: dict):
    """The :class:`~thermogear.gearbox.sweep.SteadySweep` ``result`` of a case (its name, source and document as
    loaded) as an xarray Dataset (dims
    ``speed_rpm`` × ``torque_nm``), NaN where ``runaway`` is 1."""
    import xarray as xr  # noqa: PLC0415

    from thermogear import __version__  # noqa: PLC0415

    dims = ("speed_rpm", "torque_nm")

    def filled(values) -> np.ndarray:
        return np.ma.filled(np.ma.asarray(values, dtype=np.float64), np.nan)

    variables = {f"temperature_{name}": (filled(result.node(name)), "degC", f"steady temperature of the {name}")
                 for name in NODES}
    sources = {"mesh_loss": (result.mesh_loss, "tooth friction loss of the mesh"),
               "bearing_loss": (result.bearing_loss, "bearing loss"),
               "seal_loss": (result.seal_loss, "seal loss"),
               "churning_loss": (result.churning_loss, "churning loss of the dipped gears")}
    if result.injection_loss is not None:
        sources["injection_loss"] = (result.injection_loss, "impulse loss of the oil jet")
    sources["total_loss"] = (result.total_loss, "sum of the losses")
    variables.update({name: (filled(values), "W", text) for name, (values, text) in sources.items()})
    variables["efficiency"] = (filled(result.efficiency), "1", "efficiency of the gearbox")
    variables["backlash"] = (filled(result.backlash), "m", "normal backlash at the steady temperatures")
    runaway = np.asarray(result.runaway, dtype=np.int8)
    data_vars = {name: (dims, values, {"units": units, "long_name": text})
                 for name, (values, units, text) in variables.items()}
    data_vars["runaway"] = (dims, runaway, {"units": "1", "long_name": "1 where the network has no steady state "
                                                                        "(thermal runaway); the values there are NaN"})
    data_vars["valid"] = (dims, np.asarray(result.valid, dtype=np.int8),
                          {"units": "1", "long_name": "1 where the point has a stable steady state with every gear "
                                                      "within the material data (thermogear.temperature_limits)"})
    from thermogear.temperature_limits import FLAG_MEANINGS  # noqa: PLC0415

    for flag, meaning in FLAG_MEANINGS.items():
        data_vars[f"flag_{flag}"] = (dims, np.asarray(result.flagged(flag), dtype=np.int8),
                                     {"units": "1", "long_name": f"1 where the steady state has {meaning}"})
    coords = {"speed_rpm": ("speed_rpm", np.asarray(result.speeds_rpm, dtype=float),
                            {"units": "rpm", "long_name": "pinion speed"}),
              "torque_nm": ("torque_nm", np.asarray(result.torques, dtype=float),
                            {"units": "N m", "long_name": "pinion torque"})}
    attrs = {"title": "thermogear steady gearbox sweep", "thermogear_version": __version__,
             "case_name": case_name, "case_source": str(case_source),
             "case_json": json.dumps(case_document, sort_keys=True, default=str),
             "ambient_c": float(result.ambient_c), "load": "constant torque",
             "row_dimensions": ",".join(dims)}  # `thermogear export`: one row per point
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def write_steady_store(result, case_name: str, case_source: str, case_document: dict, path: str | Path,
                       overwrite: bool = False) -> Path:
    """Write the steady sweep ``result`` of a case (name, source, document) to the zarr store ``path`` (see the
    module docstring)."""
    from thermogear.sweep.branches import write_branch_store  # noqa: PLC0415

    return write_branch_store(steady_dataset(result, case_name, case_source, case_document), path,
                              overwrite=overwrite)
