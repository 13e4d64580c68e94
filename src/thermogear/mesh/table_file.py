"""A user's mesh period from a table file: the case key ``dynamics.mesh_table``.

The file is a CSV table over one mesh period, one row per interval, with the units in the column names:

    phase [-], stiffness [N/m], damping [N*s/m], deviation [um]
    0.0,       2.6e8,           1500,            0.0
    0.6,       1.6e8,           1500,            0.0

``phase`` τ_i is the start of each interval as a fraction of the mesh period (0 first, strictly increasing, below 1;
the last interval ends at 1) and the values hold on [τ_i, τ_{i+1}). ``stiffness`` (required, > 0) is the total mesh
stiffness k(τ); ``damping`` c(τ) (>= 0) and ``deviation`` e(τ) (the unloaded deviation, positive where material
is missing) are optional. Units accepted: stiffness N/m, N/mm, N/um; damping N*s/m (also N·s/m, Ns/m); deviation
m, mm, um (also µm). The table is read and checked when the case is loaded (sorted phases, finite numbers, positive
stiffness, one period covered), so ``check``, ``run`` and ``sweep`` refuse a bad table alike.

With the key set, every mesh period the case's models hand to the dynamics (``run``, ``sweep``, the drivetrain) is
this table at the operating point's speed and load: the period T_m = 60/(z1·n1), the static load, the equivalent
mass and the backlash stay the case's; without a damping column c(τ) is the model's own friction damping at the
same phase (it then follows speed and load as the model's does), with one it is the table's at every speed and
load. The table is one pair slot carrying the whole mesh (Kv is then the total mesh force over the static load).
The Python route is :func:`~thermogear.mesh.state.mesh_state_from_arrays`.
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from thermogear.case import cached_per_case
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState, mesh_state_from_arrays
from thermogear.text_files import is_existing_file, read_user_text

__all__ = ["KEY", "MeshTable", "check_mesh_table", "mesh_table_of", "read_mesh_table"]

KEY = "dynamics.mesh_table"

#: column → {unit as written: factor to SI}
_UNITS: dict[str, dict[str, float]] = {
    "phase": {"-": 1.0, "1": 1.0},
    "stiffness": {"N/m": 1.0, "N/mm": 1e3, "N/um": 1e6, "N/µm": 1e6},
    "damping": {"N*s/m": 1.0, "N·s/m": 1.0, "Ns/m": 1.0, "N s/m": 1.0},
    "deviation": {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6},
}
_HEADER = re.compile(r"^\s*([A-Za-z_]+)\s*\[\s*([^\]]*?)\s*\]\s*$")


@dataclass(frozen=True, eq=False)
class MeshTable:
    """A checked mesh table: ``phase`` (N,) [-], ``stiffness`` (N,) [N/m], ``damping`` (N,) [N·s/m] or None,
    ``deviation`` (N,) [m] or None; ``source`` the file as named in the case."""

    phase: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray | None
    deviation: np.ndarray | None
    source: str

    def state_like(self, state: MeshState) -> MeshState:
        """This table at the operating point of a model's ``state`` (its period, load, mass, backlash, face width
        and speed; its c(τ) at the table's phases where the table has no damping column)."""
        damping = self.damping
        if damping is None:
            middle = 0.5 * (self.phase + np.append(self.phase[1:], 1.0)) * state.period
            index = np.clip(np.searchsorted(state.grid.nodes, middle, side="right") - 1, 0,
                            state.mesh_damping.size - 1)
            damping = state.mesh_damping[index]
        return mesh_state_from_arrays(self.phase, self.stiffness, speed_rpm=state.speed_rpm,
                                      normal_load=state.normal_load, mass=state.mass, damping=damping,
                                      deviation=self.deviation, period=state.period, backlash=state.backlash,
                                      face_width=state.face_width, model=state.model)


def _columns(header: list[str], name: str) -> dict[str, tuple[int, float]]:
    """column name → (index, factor to SI) from a header row; CaseError for an unknown name or unit."""
    found = {}
    for index, text in enumerate(header):
        match = _HEADER.match(text)
        if match is None or match.group(1).lower() not in _UNITS:
            raise CaseError(KEY, name, "a header of 'name [unit]' columns: " + ", ".join(
                f"{column} [{' | '.join(units)}]" for column, units in _UNITS.items()),
                f"column {index + 1} is {text.strip()[:40]!r}: the units must be named in the header")
        column, unit = match.group(1).lower(), match.group(2)
        if unit not in _UNITS[column]:
            raise CaseError(KEY, name, f"{column} in {' | '.join(_UNITS[column])}",
                            f"column {index + 1} gives {column} in [{unit}]")
        if column in found:
            raise CaseError(KEY, name, "each column once", f"{column} appears twice in the header")
        found[column] = (index, _UNITS[column][unit])
    for column in ("phase", "stiffness"):
        if column not in found:
            raise CaseError(KEY, name, "columns phase [-] and stiffness [N/m] at least",
                            f"the header names no {column} column")
    return found


def read_mesh_table(name: str, directory: Path | None = None) -> MeshTable:
    """Read and check a mesh table file (module docstring); relative paths from the case file's folder."""
    path = Path(name)
    if not path.is_absolute() and directory is not None:
        path = directory / path
    if not is_existing_file(path):
        raise CaseError(KEY, name, "an existing CSV file (relative to the case file)", "no such file")
    text = read_user_text(path, KEY, name, "CSV")
    lines = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    rows = list(csv.reader(lines))
    if len(rows) < 2:
        raise CaseError(KEY, name, "a header row and one row per interval", "the table has no data rows")
    columns = _columns(rows[0], name)
    values = {column: [] for column in columns}
    for number, row in enumerate(rows[1:], start=2):
        if len(row) != len(rows[0]):
            raise CaseError(KEY, name, f"{len(rows[0])} values per row", f"row {number} has {len(row)}")
        for column, (index, factor) in columns.items():
            try:
                value = float(row[index]) * factor
            except ValueError:
                raise CaseError(KEY, name, f"numbers in the {column} column",
                                f"row {number} has {row[index].strip()[:20]!r}") from None
            if not np.isfinite(value):
                raise CaseError(KEY, name, f"finite numbers in the {column} column",
                                f"row {number} has {row[index].strip()[:20]}")
            values[column].append(value)
    arrays = {column: np.array(entries) for column, entries in values.items()}
    phase = arrays["phase"]
    steps = np.diff(phase)
    if phase[0] != 0.0 or np.any(steps <= 0.0) or phase[-1] >= 1.0:
        bad = int(np.flatnonzero(steps <= 0.0)[0]) + 3 if np.any(steps <= 0.0) else None
        where = (f"row {bad} does not increase" if bad is not None else
                 f"the first phase is {phase[0]:g}" if phase[0] != 0.0 else f"the last phase is {phase[-1]:g}")
        raise CaseError(KEY, name, "phase from 0, strictly increasing, below 1 (one mesh period)",
                        f"{where}: the rows must cover one period in order, each the start of an interval")
    stiffness = arrays["stiffness"]
    if np.any(stiffness <= 0.0):
        row = int(np.argmin(stiffness)) + 2
        raise CaseError(KEY, name, "stiffness > 0 N/m on every row",
                        f"row {row} has {stiffness[row - 2]:g} N/m: a mesh in contact has positive stiffness")
    damping = arrays.get("damping")
    if damping is not None and np.any(damping < 0.0):
        row = int(np.argmin(damping)) + 2
        raise CaseError(KEY, name, "damping >= 0 N·s/m", f"row {row} has {damping[row - 2]:g}: a damper must not "
                        "inject energy")
    return MeshTable(phase, stiffness, damping, arrays.get("deviation"), name)


@cached_per_case
def mesh_table_of(dynamics, directory) -> MeshTable | None:
    """The case's mesh table (read once per case: called with the case, ``mesh_table_of(case)``,
    :func:`thermogear.case.cached_per_case`), None where its ``[dynamics] mesh_table`` is not set; a relative path
    is read from the case file's ``directory``.

    It is also the load-time check of that table (:data:`thermogear.composition.CASE_CHECKS`: every command runs
    it, check = run): reading the file is what checks it, and the table read then is the one the mesh model uses."""
    name = getattr(dynamics, "mesh_table", None)
    return None if name is None else read_mesh_table(name, directory)


#: The load-time check of the case's mesh table: the resolver itself (reading the table checks it).
check_mesh_table = mesh_table_of
