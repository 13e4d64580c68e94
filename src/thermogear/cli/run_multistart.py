"""`thermogear run CASE --multistart N`: every stable orbit of the backlash drivetrain that N starts settle on, with
its basin share (issue 36), as a table or in the JSON.

The search is :func:`~thermogear.drivetrain.backlash_orbits.case_stable_orbits` (the start from rest, the linear
periodic state and a grid over the mesh coordinate and its rate, each run in over the case's
``dynamics.transient_periods`` and shot, solved as ``run`` solves its orbit). It applies where a start can reach
more than one orbit: a case with a ``[drivetrain]`` of one mesh, the nonlinear (backlash) mesh and the periodic
method. Elsewhere the option is refused before any work, with the reason.
"""

from __future__ import annotations

from typing import Any

from thermogear.errors import CaseError

__all__ = ["check_multistart", "multistart_json", "print_multistart"]


def check_multistart(drivetrain, dynamics, starts: int, method: str, out) -> None:
    """Refuse ``--multistart`` (CaseError naming the option, its value, what it needs and why) where it does not
    apply (module docstring) for a case's ``[drivetrain]`` and ``[dynamics]`` sections; nothing where ``starts`` is
    0 (the option not given)."""
    if not starts:
        return
    from thermogear.dynamics.problems.mesh_laws import mesh_law
    from thermogear.dynamics.problems.solution_methods import solution_method

    if drivetrain is None:
        raise CaseError("--multistart", starts, "a case with a [drivetrain]",
                        "the search runs on the drivetrain's backlash orbit; the 1-DOF pair's orbits are searched "
                        "point by point by `thermogear sweep --multistart`")
    if not mesh_law(dynamics.mesh).backlash:
        raise CaseError("--multistart", starts, 'dynamics.mesh = "nonlinear" (the backlash mesh)',
                        f"with the {dynamics.mesh} mesh the drivetrain is a linear periodic system: it has one "
                        "periodic orbit, which every start reaches")
    if solution_method(method).from_rest:
        raise CaseError("--multistart", starts, "--method periodic",
                        "the search lists periodic orbits; --method transient follows one motion from rest")
    if drivetrain.stages:
        raise CaseError("--multistart", starts, "a drivetrain of one mesh (no [[drivetrain.stages]])",
                        "the backlash orbit, and so its search, is solved for a single mesh")
    if out is not None:
        raise CaseError("--multistart", starts, "without --out",
                        "the report does not show the search: run it on the terminal or with --json")


def multistart_json(built, models: tuple[str, ...], starts: int, progress=None) -> dict[str, Any]:
    """Per model the search's summary (:func:`~thermogear.drivetrain.backlash_orbits.census_summary`: each stable
    orbit's Kv, DTE, contact loss, largest Floquet multiplier, basin share and whether the start from rest reaches
    it; the unresolved and unbounded shares). ``built``: the :class:`~thermogear.drivetrain.case_model.
    CaseDrivetrain` the run's results came from; ``progress(model)`` before each model's search."""
    from thermogear.drivetrain.backlash_orbits import case_stable_orbits, census_summary
    from thermogear.serialization import json_ready

    found = {}
    for model in models:
        if progress is not None:
            progress(model)
        found[model] = census_summary(case_stable_orbits(built, model, int(starts)))
    return json_ready(found, non_finite="null")


def _shown(value, pattern: str) -> str:
    return "—" if value is None else pattern.format(value)


def print_multistart(summaries: dict[str, Any], console) -> None:
    """One table of every stable orbit found, per model, largest basin share first, and the shares of the starts
    that settled on none."""
    from rich.table import Table

    starts = next(iter(summaries.values()))["starts"]
    table = Table(title=f"drivetrain: stable orbits of a multi-start search ({starts} starts: rest, the linear "
                        "solution and a grid of the mesh coordinate and its rate)", header_style="bold")
    for column in ("model", "orbit", "basin share", "starts", "from rest", "Kv", "DTE RMS [μm]",
                   "DTE p-p [μm]", "contact loss", "back flanks", "largest |μ|"):
        table.add_column(column, justify="left" if column == "model" else "right")
    for model, summary in summaries.items():
        for number, orbit in enumerate(summary["orbits"], start=1):
            table.add_row(model, str(number), f"{orbit['basin_share']:.3f}", str(orbit["start_count"]),
                          "yes" if orbit["reached_from_rest"] else "no", _shown(orbit["kv"], "{:.4f}"),
                          _shown(orbit["dte_rms_um"], "{:.3f}"), _shown(orbit["dte_peak_to_peak_um"], "{:.3f}"),
                          f"{orbit['contact_loss_fraction']:.3f}", f"{orbit['back_contact_fraction']:.3f}",
                          _shown(orbit["largest_floquet_multiplier_abs"], "{:.4f}"))
    console.print(table)
    for model, summary in summaries.items():
        count = len(summary["orbits"])
        console.print(f"{model}: {count} stable one-period orbit{'s' if count != 1 else ''} found; starts that "
                      f"settled on none {summary['unresolved_share']:.3f}, grew without bound "
                      f"{summary['unbounded_share']:.3f} (no finite search proves an orbit absent; orbits over "
                      "several mesh periods are not searched)", highlight=False)
