"""The zarr store of a gearbox's steady sweep (`thermogear gearbox CASE --speeds … --torques … --out X.zarr`):
the check of its target before any work. The grid is planned and written block by block by
:mod:`thermogear.sweep.gearbox_grid` into the studies' one store (:mod:`thermogear.sweep.task_store`: the ownership
marker, ``--overwrite`` only of thermogear's own store holding nothing else at any depth, ``--resume``):

* coordinates ``speed_rpm`` [rpm] and ``torque_nm`` [N·m] (pinion);
* per point: the node temperatures ``temperature_pinion`` … ``temperature_housing`` [°C], the losses by source
  [W] (``injection_loss`` only with an oil jet) and their sum, the efficiency [–], the normal backlash [m];
* ``runaway`` (1 where the network has no steady state: thermal runaway) and ``valid`` (its complement); every other
  variable is NaN there, and NaN is never a value: read the flags;
* attributes: the case (name, source, document as JSON), the ambient temperature, thermogear's version, and
  ``row_dimensions`` (``thermogear export`` writes one row per speed × torque).
"""

from __future__ import annotations

from pathlib import Path


from thermogear.errors import CaseError
from thermogear.ownership import is_owned, require_no_foreign_entries, resolve_output

__all__ = ["STORE_KIND", "check_steady_store_target"]

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
