"""``thermogear.sweep(case, vary={...}, out=..., scheduler=...)``: any study of a case from Python, returning the
store's xarray Dataset.

The kind of study follows from the case, resolved once from :data:`STUDY_KINDS` (the first whose test accepts
the case): a case with a ``[drivetrain]`` runs the drivetrain study (linear mesh: each speed's response; backlash
mesh: the branches up and down in speed), a nonlinear-mesh pair the branch study (with ``multistart`` the orbit
search), any other the grid of independent points on the fast path. All run on the one executor and write the one
kind of store, resumable; see docs/sweeps.md.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from thermogear.errors import CaseError
from thermogear.dynamics.mesh_laws import mesh_law

__all__ = ["STUDY_KINDS", "StudyKind", "study"]


@dataclass(frozen=True)
class StudyKind:
    """A kind of study: ``name``, ``accepts(case, method)`` and ``run(study, out, options)`` → Dataset."""

    name: str
    accepts: Callable[[Any, str], bool]
    run: Callable[[Any, Path, dict], Any]


def _run_drivetrain(study, out, options: dict):
    from thermogear.sweep.drivetrain_run import run_drivetrain_study

    _refuse(options, "drivetrain", method="batch", multistart=0)
    direction = options["direction"]
    directions = ("up", "down") if direction in (None, "both") else (direction,)
    scheduler = options["scheduler"] if options["scheduler"] not in (None, "", "local") else "processes"
    return run_drivetrain_study(study, out, directions, scheduler, options["workers"], options["resume"],
                                options["overwrite"], options["chunk_points"]).dataset


def _run_branches(study, out, options: dict):
    from thermogear.sweep.branches import branch_study

    _refuse(options, "branch", chunk_points=None)
    return branch_study(study, options["direction"] or "both", workers=options["workers"],
                        multistart=options["multistart"], scheduler=options["scheduler"], out=out,
                        resume=options["resume"], overwrite=options["overwrite"])


def _run_grid(study, out, options: dict):
    from thermogear.sweep.engine import run_study

    _refuse(options, "linear-mesh grid", direction=None, multistart=0)
    return run_study(study, out, scheduler=options["scheduler"], resume=options["resume"],
                     overwrite=options["overwrite"], workers=options["workers"], method=options["method"]).dataset


def _refuse(options: dict, kind: str, **defaults) -> None:
    """Refuse an option the study kind cannot act on (never silently ignored)."""
    for name, default in defaults.items():
        if options[name] != default:
            raise CaseError(name, options[name], f"{default!r} for a {kind} study",
                            f"a {kind} study has no use for it")


#: The kinds of study, tried in order.
STUDY_KINDS: tuple[StudyKind, ...] = (
    StudyKind("drivetrain", lambda case, method: case.drivetrain is not None, _run_drivetrain),
    StudyKind("branches", lambda case, method: mesh_law(case.dynamics.mesh).backlash and method == "batch",
              _run_branches),
    StudyKind("grid", lambda case, method: True, _run_grid),
)


def study(case, vary: dict[str, Any] | list[str], out: str | Path, scheduler: str | None = None,
          model: str = "both", hold: str = "torque", direction: str | None = None, workers: int | None = None,
          resume: bool = False, overwrite: bool = False, chunk_points: int | None = None, method: str = "batch",
          multistart: int = 0):
    """Run the study of ``case`` (a :class:`~thermogear.case.Case`, a built-in name or a case file) over ``vary``
    (``{"speed_rpm": "1000:3000:21", "oil_temperature_c": [50, 70]}``) into the zarr store ``out`` and return the
    store's xarray Dataset. ``scheduler``: None (the local default), ``"serial"``, ``"threads"``, ``"processes"``
    or a ``dask.distributed`` scheduler address; ``hold``: the load a speed sweep keeps (``"torque"`` |
    ``"power"``); ``direction``: the branches of a nonlinear mesh (``"up"`` | ``"down"`` | ``"both"``); ``resume``
    continues an interrupted study in ``out``; the rest as the command line's options (docs/sweeps.md). An option
    the study's kind cannot act on is refused with a CaseError."""
    from thermogear.sweep.study import Study, load_study_case

    if isinstance(case, (str, Path)):
        case, _ = load_study_case(case)
    defined = Study.define(case, vary, model=model, chunk_points=chunk_points, hold=hold)
    options = {"scheduler": scheduler, "workers": workers, "resume": resume, "overwrite": overwrite,
               "chunk_points": chunk_points, "method": method, "direction": direction, "multistart": multistart}
    kind = next(kind for kind in STUDY_KINDS if kind.accepts(case, method))
    return kind.run(defined, Path(out), options)
