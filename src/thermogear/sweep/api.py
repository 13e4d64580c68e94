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

from thermogear.case.pieces import call_with_pieces
from thermogear.dynamics.problems.continuation_directions import study_directions
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError
from thermogear.sweep.schedulers import PROCESSES
from thermogear.sweep.schedulers import scheduler as scheduler_named
from thermogear.sweep.evaluation_methods import is_batched

__all__ = ["STUDY_KINDS", "StudyKind", "StudySubject", "register_study_kind", "study", "study_kind", "study_kinds"]


@dataclass(frozen=True)
class StudySubject:
    """What picks a case's kind of study, resolved once from the case (:meth:`of` its sections): whether it has a
    ``[drivetrain]``, whether its mesh has the backlash dead zone, whether it has a ``[gearbox]``."""

    drivetrain: bool
    backlash: bool
    gearbox: bool

    @classmethod
    def of(cls, drivetrain, dynamics, gearbox) -> "StudySubject":
        """The subject of a case with these sections (``call_with_pieces(StudySubject.of, case)``)."""
        return cls(drivetrain is not None, mesh_law(dynamics.mesh).backlash, gearbox is not None)


@dataclass(frozen=True)
class StudyKind:
    """A kind of study: ``name``, ``accepts(subject, method)`` (a :class:`StudySubject`), ``run(study, out, options)`` → Dataset,
    ``by_case`` (picked from the case when no kind is named; False: only when named, e.g. the warm-ups of a gearbox
    case, whose case also has a steady study), ``needs`` (what ``accepts`` asks of the case, for the refusal) and
    ``default_model`` (the gear model when none is given)."""

    name: str
    accepts: Callable[[Any, str], bool]
    run: Callable[[Any, Path, dict], Any]
    by_case: bool = True
    needs: str = ""
    default_model: str = "both"


def _run_drivetrain(study, out, options: dict):
    from thermogear.sweep.drivetrain_run import run_drivetrain_study

    _refuse(options, "drivetrain", method="batch", multistart=0, warmup=None)
    direction = options["direction"]
    directions = study_directions(direction)
    scheduler = scheduler_named(options["scheduler"], default=PROCESSES)
    return run_drivetrain_study(study, out, directions, scheduler, options["workers"], options["resume"],
                                options["overwrite"], options["chunk_points"]).dataset


def _run_branches(study, out, options: dict):
    from thermogear.sweep.branches import branch_study

    _refuse(options, "branch", chunk_points=None, warmup=None)
    return branch_study(study, options["direction"] or "both", workers=options["workers"],
                        multistart=options["multistart"], scheduler=options["scheduler"], out=out,
                        resume=options["resume"], overwrite=options["overwrite"])


def _run_grid(study, out, options: dict):
    from thermogear.sweep.engine import run_study

    _refuse(options, "linear-mesh grid", direction=None, multistart=0, warmup=None)
    return run_study(study, out, scheduler=options["scheduler"], resume=options["resume"],
                     overwrite=options["overwrite"], workers=options["workers"], method=options["method"]).dataset


def _run_warmups(study, out, options: dict):
    from dataclasses import replace

    from thermogear.sweep.warmup_study import WarmupSettings, run_warmup_study

    _refuse(options, "warm-up", direction=None, multistart=0, method="batch")
    scheduler = scheduler_named(options["scheduler"], default=PROCESSES)
    return run_warmup_study(replace(study, chunk_points=options["chunk_points"] or 1), out,
                            options["warmup"] or WarmupSettings(), scheduler, options["workers"], options["resume"],
                            options["overwrite"], options.get("progress"))


def _refuse(options: dict, kind: str, **defaults) -> None:
    """Refuse an option the study kind cannot act on (never silently ignored)."""
    for name, default in defaults.items():
        if options[name] != default:
            raise CaseError(name, options[name], f"{default!r} for a {kind} study",
                            f"a {kind} study has no use for it")


#: The kinds of study, tried in order (those picked by the case), or named.
STUDY_KINDS: tuple[StudyKind, ...] = (
    StudyKind("drivetrain", lambda subject, method: subject.drivetrain, _run_drivetrain),
    StudyKind("branches", lambda subject, method: subject.backlash and is_batched(method), _run_branches),
    StudyKind("grid", lambda subject, method: True, _run_grid),
    StudyKind("warmup", lambda subject, method: subject.gearbox, _run_warmups, by_case=False,
              needs="a case with a [gearbox] (the thermal network the warm-up integrates)", default_model="thermal"),
)


#: Kinds of study added at run time (:func:`register_study_kind`), tried before the built-in ones.
_REGISTERED: list[StudyKind] = []


def register_study_kind(kind: StudyKind) -> StudyKind:
    """Add a kind of study, named by ``sweep --kind`` and ``thermogear.sweep(kind=...)`` (``by_case=False``), or
    picked from the case before the built-in kinds wherever its ``accepts`` does (``by_case=True``). Its
    ``run(study, out, options)`` computes the study's points and writes them to ``out``; it returns the Dataset.
    Returns the kind; ValueError for a name already taken."""
    if kind.name in {known.name for known in (*_REGISTERED, *STUDY_KINDS)}:
        raise ValueError(f"a kind of study named {kind.name!r} exists already")
    _REGISTERED.append(kind)
    return kind


def study_kinds() -> tuple[StudyKind, ...]:
    """Every kind of study, in the order they are tried: the registered ones, then :data:`STUDY_KINDS`."""
    return (*_REGISTERED, *STUDY_KINDS)


def study_kind(subject: StudySubject, method: str = "batch", name: str | None = None) -> StudyKind:
    """The kind of study of a case (its ``subject``, :meth:`StudySubject.of`): the first of :func:`study_kinds`
    picked by the case that accepts it, or the kind ``name`` (refused where it does not accept the case, or where
    the case picks another kind of its own)."""
    every = study_kinds()
    automatic = next(kind for kind in every if kind.by_case and kind.accepts(subject, method))
    if name is None:
        return automatic
    kinds = {kind.name: kind for kind in every}
    if name not in kinds:
        raise CaseError("kind", name, " | ".join(kinds), "unknown kind of study")
    chosen = kinds[name]
    if chosen.by_case and chosen is not automatic:
        raise CaseError("kind", name, f"{automatic.name} (or a kind named only: "
                        f"{', '.join(kind.name for kind in every if not kind.by_case)})",
                        f"this case's study is the {automatic.name} study")
    if not chosen.accepts(subject, method):
        raise CaseError("kind", name, chosen.needs or "a case this kind accepts", f"the {name} study needs it")
    return chosen


def study(case, vary: dict[str, Any] | list[str], out: str | Path, scheduler: str | None = None,
          model: str | None = None, hold: str = "torque", direction: str | None = None, workers: int | None = None,
          resume: bool = False, overwrite: bool = False, chunk_points: int | None = None, method: str = "batch",
          multistart: int = 0, kind: str | None = None, warmup=None):
    """Run the study of ``case`` (a :class:`~thermogear.case.Case`, a built-in name or a case file) over ``vary``
    (``{"speed_rpm": "1000:3000:21", "oil_temperature_c": [50, 70]}``) into the zarr store ``out`` and return the
    store's xarray Dataset. ``scheduler``: None (the local default), ``"serial"``, ``"threads"``, ``"processes"``
    or a ``dask.distributed`` scheduler address; ``hold``: the load a speed sweep keeps (``"torque"`` |
    ``"power"``); ``direction``: the branches of a nonlinear mesh (``"up"`` | ``"down"`` | ``"both"``); ``resume``
    continues an interrupted study in ``out``; the rest as the command line's options (docs/sweeps.md). An option
    the study's kind cannot act on is refused with a CaseError. ``kind``: None (picked from the case) or a kind of
    :data:`STUDY_KINDS` by name, e.g. ``"warmup"``: the gearbox warm-up at every point
    (:mod:`thermogear.sweep.warmup_study`; ``warmup``: its :class:`~thermogear.sweep.warmup_study.WarmupSettings`).
    ``model``: None gives the kind's default (both models; the warm-up: thermal)."""
    from thermogear.sweep.study import Study, load_study_case

    if isinstance(case, (str, Path)):
        case, _ = load_study_case(case)
    chosen = study_kind(call_with_pieces(StudySubject.of, case), method, kind)
    defined = Study.define(case, vary, model=model or chosen.default_model, chunk_points=chunk_points, hold=hold)
    options = {"scheduler": scheduler, "workers": workers, "resume": resume, "overwrite": overwrite,
               "chunk_points": chunk_points, "method": method, "direction": direction, "multistart": multistart,
               "warmup": warmup}
    return chosen.run(defined, Path(out), options)
