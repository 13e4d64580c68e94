"""The pictures of a case's drivetrain, for the report and ``run --plot``: layout, mode shapes, interference
diagram and bearing-force spectra (:mod:`thermogear.drivetrain.plots` draws them; this module chooses what).

- ``drivetrain_layout``: the labelled sketch of the cold drivetrain.
- ``drivetrain_modes``: the shapes of the mesh-dominated mode (the largest mesh share of strain energy among all
  modes, not only the listed ones) and of the modes behind the largest bearing force (the two largest modal terms of
  that bearing's force at that mesh harmonic, :mod:`thermogear.drivetrain.participation`).
- ``drivetrain_campbell``: the interference diagram of the cold drivetrain from standstill to 1.2 times the larger
  of the case's speed and the speed where the first mesh harmonic meets the mesh-dominated mode, on 100 speeds,
  with every mode up to the mesh-dominated one (at least the section's ``mode_count``).
- ``drivetrain_bearing_spectra``: per model, each bearing's radial force amplitude at the first mesh harmonics.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # the captions are imported with the report; the drivetrain's modules when a picture is drawn
    from thermogear.drivetrain.case_model import CaseDrivetrain
    from thermogear.drivetrain.modes import DrivetrainModes

__all__ = ["CAMPBELL_SPEEDS", "PICTURES", "drivetrain_pictures", "largest_bearing_force", "pictured_modes"]

#: Picture name → caption.
PICTURES: dict[str, str] = {
    "drivetrain_layout": "Drivetrain layout: shafts to scale, gears (pitch diameter), disks, bearings (crossed "
                         "boxes), couplings and motor supports, labelled as in the case file.",
    "drivetrain_modes": "Mode shapes (cold drivetrain, undamped, mean mesh stiffness): the mesh-dominated mode and "
                        "the modes behind the largest bearing force; each shaft's x (solid) and y (dashed) "
                        "translation and its torsion at the surface r·θ (dotted), on the shaft axes of the layout.",
    "drivetrain_campbell": "Interference (Campbell) diagram of the cold drivetrain: the damped, spinning modes "
                           "coloured by their mesh share of strain energy, the mesh harmonics (dashed), every "
                           "crossing marked and those of modes the mesh reaches (share ≥ 0.01) numbered and listed "
                           "below; the vertical line is the case's speed.",
    "drivetrain_bearing_spectra": "Bearing forces on the housing at the case's speed: the radial amplitude "
                                  "√(X_j² + Y_j²) of each bearing's force at the first mesh harmonics, per model.",
}
#: Speeds of the interference diagram.
CAMPBELL_SPEEDS = 100
#: Modes drawn as "behind the largest bearing force".
_BEHIND = 2


def _first_model(built: CaseDrivetrain, data: dict[str, Any] | None) -> str:
    if data and data.get("models"):
        return next(iter(data["models"]))
    return next(iter(built.drivetrains))


def largest_bearing_force(built: CaseDrivetrain, data: dict[str, Any] | None,
                          model: str) -> tuple[str, int, float, float] | None:
    """(bearing, harmonic j, frequency [Hz], radial amplitude [N]) of the largest bearing-force harmonic of
    ``model`` (from ``data``, the results ``run`` reports, else from the periodic response solved here); None
    where no force is known (no orbit found)."""
    from thermogear.drivetrain.case_model import bearing_force_summary

    if data and model in data.get("models", {}):
        forces = data["models"][model]["bearing_forces"]
    else:
        forces = bearing_force_summary(built.response(model), built.section.bearing_harmonics)
    best = None
    for bearing, force in forces.items():
        for index, (frequency, amplitude) in enumerate(zip(force["harmonic_hz"], force["harmonic_amplitude_n"])):
            if amplitude is not None and np.isfinite(amplitude) and (best is None or amplitude > best[3]):
                best = (bearing, index + 1, float(frequency), float(amplitude))
    return best


def pictured_modes(built: CaseDrivetrain, modes: DrivetrainModes, data: dict[str, Any] | None,
                   model: str) -> list[tuple[int, str]]:
    """(index, why) of the modes to draw: the mesh-dominated one first, then the modes behind the largest bearing
    force (module docstring), each once."""
    from thermogear.drivetrain.case_layout import MESH_NAME
    from thermogear.drivetrain.case_model import MESH_DOMINATED_SHARE
    from thermogear.drivetrain.participation import bearing_force_terms

    shares = modes.mesh_share(MESH_NAME)
    mesh_mode = int(np.argmax(shares))
    chosen = [(mesh_mode, f"the largest mesh share, {shares[mesh_mode]:.2f}"
               + ("" if shares[mesh_mode] > MESH_DOMINATED_SHARE else " (no mode is mesh-dominated)"))]
    largest = largest_bearing_force(built, data, model)
    if largest is not None:
        bearing, harmonic, frequency, amplitude = largest
        terms = bearing_force_terms(built.assembled(model), modes, bearing, frequency)
        total = float(terms.sum())
        for index in np.argsort(terms)[::-1][:_BEHIND]:
            why = (f"{100.0 * terms[index] / total:.0f} % of the modal terms of the largest bearing force, "
                   f"{bearing} at {harmonic}× mesh ({frequency:.0f} Hz, {amplitude:.3g} N)")
            if int(index) == mesh_mode:
                chosen[0] = (mesh_mode, chosen[0][1] + "; " + why)
            else:
                chosen.append((int(index), why))
    return chosen


def _modes_figure(built: CaseDrivetrain, data: dict[str, Any] | None, model: str):
    import matplotlib.pyplot as plt

    from thermogear.drivetrain.modes import drivetrain_modes
    from thermogear.drivetrain.plots import plot_mode_shape

    assembled = built.assembled(model)
    modes = drivetrain_modes(assembled)
    chosen = pictured_modes(built, modes, data, model)
    figure, axes = plt.subplots(len(chosen), 1, figsize=(8.0, 2.9 * len(chosen)), constrained_layout=True,
                                squeeze=False)
    for ax, (index, why) in zip(axes[:, 0], chosen):
        plot_mode_shape(assembled, modes.shapes[:, index],
                        f"mode {index + 1}: {modes.frequencies_hz[index]:.0f} Hz, {modes.labels[index]} — {why}",
                        ax=ax)
    return figure


def campbell_for_case(built: CaseDrivetrain, model: str):
    """The interference diagram the report draws (module docstring)."""
    from thermogear.drivetrain.case_layout import MESH_NAME
    from thermogear.drivetrain.case_model import MESH_DOMINATED_SHARE
    from thermogear.drivetrain.modes import drivetrain_modes

    modes = drivetrain_modes(built.assembled(model))
    shares = modes.mesh_share(MESH_NAME)
    dominated = np.flatnonzero(shares > MESH_DOMINATED_SHARE)
    mesh_mode = int(dominated[-1]) if dominated.size else int(np.argmax(shares))
    count = min(max(built.section.mode_count, mesh_mode + 1), modes.frequencies_hz.size)
    speed = built.models[model].speed_rpm
    meets = 60.0 * modes.frequencies_hz[mesh_mode] / built.teeth
    speeds = np.linspace(0.0, 1.2 * max(speed, meets), CAMPBELL_SPEEDS)
    from thermogear.drivetrain.campbell import campbell_diagram

    return campbell_diagram(built.assembled(model), speeds, built.teeth, mode_count=count), speed


def _campbell_figure(built: CaseDrivetrain, model: str):
    diagram, speed = campbell_for_case(built, model)
    figure = diagram.plot_campbell()
    ax = figure.axes[0]
    ax.axvline(speed, color="k", lw=0.8, gid="operating-speed")
    ax.annotate(f"case: {speed:g} rpm", (speed, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -10),
                textcoords="offset points", fontsize=7)
    return figure


def _spectra_figure(built: CaseDrivetrain, data: dict[str, Any] | None):
    import matplotlib.pyplot as plt

    from thermogear.drivetrain.case_model import bearing_force_summary
    from thermogear.drivetrain.plots import plot_bearing_spectra

    if data and data.get("models"):
        models = {name: model["bearing_forces"] for name, model in data["models"].items()}
    else:
        models = {name: bearing_force_summary(built.response(name), built.section.bearing_harmonics)
                  for name in built.drivetrains}
    figure, axes = plt.subplots(1, len(models), figsize=(5.2 * len(models), 3.8), constrained_layout=True,
                                squeeze=False, sharey=True)
    for ax, (name, forces) in zip(axes[0], models.items()):
        spectra = {bearing: (force["harmonic_hz"], [np.nan if a is None else a
                                                    for a in force["harmonic_amplitude_n"]])
                   for bearing, force in forces.items()}
        plot_bearing_spectra(spectra, ax=ax, title=f"{name} model")
    return figure


def drivetrain_pictures(built: CaseDrivetrain, data: dict[str, Any] | None = None,
                        names: tuple[str, ...] | None = None) -> dict[str, Any]:
    """The pictures ``names`` (all of :data:`PICTURES` by default) of a case's drivetrain as matplotlib figures.
    ``data``: the drivetrain results ``run`` reports (:func:`~thermogear.drivetrain.case_model.drivetrain_results`),
    whose bearing forces are drawn; without it the linear periodic response is solved here."""
    from thermogear.drivetrain.plots import plot_layout

    model = _first_model(built, data)
    draw = {"drivetrain_layout": lambda: plot_layout(built.drivetrains[model]),
            "drivetrain_modes": lambda: _modes_figure(built, data, model),
            "drivetrain_campbell": lambda: _campbell_figure(built, model),
            "drivetrain_bearing_spectra": lambda: _spectra_figure(built, data)}
    return {name: draw[name]() for name in (names or PICTURES)}
