"""The summary of a backlash drivetrain study (counts, largest Kv per direction, where the branches differ and
jump) and the figure writer of the drivetrain studies (:mod:`thermogear.cli.sweep_drivetrain`)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from thermogear.errors import CaseError

__all__ = ["drivetrain_branch_summary", "print_branch_summary", "save_figure"]


def drivetrain_branch_summary(dataset) -> dict:
    """Per "model/direction" (over every point of the study): the counts of valid, unstable, missing (not
    computed), run-in, contact-loss and back-flank points; the largest Kv and where it is."""
    counts: dict = {name: {} for name in ("valid_points", "unstable_points", "missing_points", "run_in_points",
                                          "contact_loss_points", "back_side_contact_points")}
    largest: dict = {}
    for model in dataset["model"].values:
        for direction in dataset["direction"].values:
            key = f"{model}/{direction}"
            part = dataset.sel(model=model, direction=direction)
            status = np.asarray(part["status"].values).astype(str)
            counts["valid_points"][key] = int(part["valid"].values.sum())
            counts["unstable_points"][key] = int((status == "unstable").sum())
            counts["missing_points"][key] = int(np.char.startswith(status, "not computed").sum())
            counts["run_in_points"][key] = int(part["run_in"].values.sum())
            counts["contact_loss_points"][key] = int((np.nan_to_num(part["contact_loss_fraction"].values) > 0).sum())
            counts["back_side_contact_points"][key] = int((np.nan_to_num(part["back_side_contact"].values) == 1).sum())
            kv = np.where(part["valid"].values, part["kv"].values, np.nan)
            if not np.isfinite(kv).any():
                largest[key] = None
                continue
            index = np.unravel_index(int(np.nanargmax(kv)), kv.shape)
            where = {name: float(part[name].values[i]) for name, i in zip(part["kv"].dims, index)}
            largest[key] = {"kv": float(kv[index]), **where}
    return {**counts, "kv_max": largest}


def print_branch_summary(summary: dict, hysteresis: dict, console) -> None:
    """The table lines of a backlash drivetrain study: per model and direction the counts and the largest Kv, per
    combination of the other parameters and model where the branches differ and where each sweep jumps (a jump is
    always beside a speed where the branches differ; as steep a change where they coincide is said apart)."""
    for key, largest in summary["kv_max"].items():
        where = "no valid point" if largest is None else (f"max Kv {largest['kv']:.4g} at " + ", ".join(
            f"{name} {value:g}" for name, value in largest.items() if name != "kv"))
        console.print(f"  {key}: {where}; {summary['valid_points'][key]} valid, {summary['unstable_points'][key]} "
                      f"unstable, {summary['missing_points'][key]} not computed (in the store with the reason), "
                      f"{summary['run_in_points'][key]} run in after losing the branch; teeth separating at "
                      f"{summary['contact_loss_points'][key]}, back flanks struck at "
                      f"{summary['back_side_contact_points'][key]} of the points", highlight=False)
    for label, models in hysteresis.items():
        prefix = "" if label == "all" else f"{label}, "
        for model, band in models.items():
            steep = "; ".join(f"{way} sweep changes as steeply as a jump near " + ", ".join(
                f"{item['speed_rpm']:.0f}" for item in items) + " rpm" for way in ("up", "down")
                if (items := band.get(f"{way}_sweep_steep_changes")))
            steep_text = (f"; where they coincide, {steep} (both branches alike: a steep slope between grid "
                          "speeds, refine the grid there)") if steep else ""
            if not band.get("differ"):
                console.print(f"  {prefix}{model}: up and down branches coincide (no hysteresis, no jump)"
                              f"{steep_text}", highlight=False)
                continue
            spans = ", ".join(f"{low:.0f}–{high:.0f}" for low, high in band["bands_rpm"])
            jumps = "; ".join(f"{way} sweep jumps " + ", ".join(
                f"{'up' if item['amplitude'] == 'rises' else 'down'} near {item['speed_rpm']:.0f} rpm"
                for item in items) for way in ("up", "down") if (items := band.get(f"{way}_sweep_jumps")))
            console.print(f"  {prefix}{model}: up and down branches differ over {spans} rpm (hysteresis)"
                          f"{'; ' + jumps if jumps else ''}{steep_text}", highlight=False)


def save_figure(figure, plot: Path, store: Path) -> str:
    """Write a sweep's ``figure`` to ``plot`` and close it; the path written. A disk that refuses is a CaseError
    that says the study itself is complete in ``store``."""
    import matplotlib.pyplot as plt

    try:
        figure.savefig(plot, dpi=120)
    except OSError as error:
        raise CaseError("--plot", str(plot), "a writable figure file", f"the study is complete in {store}, but "
                        f"its figure could not be written: {error.strerror or error}") from None
    finally:
        plt.close(figure)
    return str(plot)
