"""The steps of a report, in the order :func:`thermogear.report.build.build_report` announces them: here, apart
from the report's code, so that a command can show its progress before it imports the model (``reproduce``)."""

from __future__ import annotations

__all__ = ["steps_of_report"]


def steps_of_report(paper: bool, models=("elastic", "thermal"), drivetrain: bool = False) -> list[str]:
    """Step names of a report with (``paper``) or without the paper's own stages; ``drivetrain``: the case has a
    ``[drivetrain]``."""
    steps = [f"{model} model" for model in models] + (["drivetrain"] if drivetrain else [])
    steps += ["thermal stiffness", "damping", "start-up transients"]
    if paper:  # the FE verification runs beside the other stages and the figures; the last figure needs it
        return steps + ["thermoelastic prediction", "rig trend", "figures", "FE verification", "files"]
    return steps + ["figures", "files"]
