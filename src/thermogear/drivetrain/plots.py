"""Pictures of a drivetrain: its layout, mode shapes, interference (Campbell) diagram and bearing-force spectra.

Each ``plot_*`` function draws on ``ax`` (a new figure when None) and returns the figure; matplotlib is imported
when a picture is drawn. The artists that carry the content have a ``gid`` ("shaft:<name>", "bearing:<name>",
"gear:<name>", "disk:<name>", "coupling:<name>", "support:<name>", "crossings", "mode:<shaft>:<component>",
"bearing-spectrum:<name>") so that what a picture shows can be checked, not only that it exists.

The layout is a side view in the plane of the shafts' axes (z along the page): shafts to scale (each segment its
outer diameter), placed along z by the couplings that join them end to end and across by the meshes, whose gears
(pitch diameter, operating pitch circle r_b/cos α_w) touch at the pitch point; bearings are crossed boxes under and
over the shaft, disks rectangles of the diameter of a solid disk of their mass and polar inertia, I_p = m·R²/2.
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain, Drivetrain

__all__ = ["plot_bearing_spectra", "plot_campbell", "plot_layout", "plot_mode_shape", "shaft_placement"]

_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan")


@dataclass(frozen=True)
class _Placement:
    """Where a shaft is drawn: ``offset`` [m] of its first end along z, ``row`` [m] of its axis across."""

    offset: float
    row: float


def _pitch_radii(drivetrain: Drivetrain) -> dict[tuple[str, float], float]:
    """Operating pitch radius [m] of every gear by (shaft, position)."""
    radii = {}
    for mesh in drivetrain.meshes:
        cosine = math.cos(mesh.operating_pressure_angle)
        radii[(mesh.gear_1.shaft, mesh.gear_1.position)] = mesh.base_radius_1 / cosine
        radii[(mesh.gear_2.shaft, mesh.gear_2.position)] = mesh.base_radius_2 / cosine
    return radii


def _largest_radius(shaft) -> float:
    return max(segment.section.outer_diameter for segment in shaft.segments) / 2.0


def shaft_placement(drivetrain: Drivetrain) -> dict[str, _Placement]:
    """Where each shaft is drawn (module docstring): from the first shaft on, a meshing shaft one centre distance
    (the two pitch radii) below its partner with the gears at the same z, a coupled shaft on the same axis with the
    coupling's two points at the same z (on a row of its own if it would overlap a shaft there), any other shaft
    on a row of its own below."""
    shafts = {shaft.name: shaft for shaft in drivetrain.shafts}
    radii = _pitch_radii(drivetrain)
    spacing = 4.0 * max(max(radii.values(), default=0.0), max(_largest_radius(s) for s in shafts.values()))
    placed = {drivetrain.shafts[0].name: _Placement(0.0, 0.0)}
    links = [(mesh.gear_1, mesh.gear_2, "mesh") for mesh in drivetrain.meshes]
    links += [(coupling.first, coupling.second, "coupling") for coupling in drivetrain.couplings
              if coupling.first.shaft != coupling.second.shaft]

    def overlaps(row: float, start: float, stop: float) -> bool:
        return any(abs(p.row - row) < 1e-12 and start < p.offset + shafts[n].length and p.offset < stop
                   for n, p in placed.items())

    while len(placed) < len(shafts):
        for first, second, kind in links:
            if (first.shaft in placed) == (second.shaft in placed):
                continue
            known, new = (first, second) if first.shaft in placed else (second, first)
            anchor = placed[known.shaft]
            offset = anchor.offset + known.position - new.position
            if kind == "mesh":
                row = anchor.row - (radii[(known.shaft, known.position)] + radii[(new.shaft, new.position)])
            else:
                row = anchor.row
                while overlaps(row, offset, offset + shafts[new.shaft].length):
                    row -= spacing
            placed[new.shaft] = _Placement(offset, row)
            break
        else:  # a shaft joined to nothing placed yet: a row of its own
            name = next(name for name in shafts if name not in placed)
            placed[name] = _Placement(0.0, min(p.row for p in placed.values()) - spacing)
    return placed


def _new_axes(ax, size=(8.0, 4.5)):
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=size, constrained_layout=True)
    return ax


def plot_layout(drivetrain: Drivetrain | AssembledDrivetrain, ax=None):
    """A labelled sketch of the drivetrain (module docstring): shafts, gears, disks, bearings, couplings and
    motor supports, in millimetres; returns the figure."""
    from matplotlib.patches import Rectangle

    if isinstance(drivetrain, AssembledDrivetrain):
        drivetrain = drivetrain.drivetrain
    ax = _new_axes(ax)
    placement = shaft_placement(drivetrain)
    radii = _pitch_radii(drivetrain)
    mm = 1e3
    shafts = {shaft.name: shaft for shaft in drivetrain.shafts}

    def at(location) -> tuple[float, float]:
        place = placement[location.shaft]
        return (place.offset + location.position) * mm, place.row * mm

    def shaft_radius(location) -> float:
        shaft = shafts[location.shaft]
        ends = shaft.segment_ends
        index = min(max(int(np.searchsorted(ends, location.position, side="right")) - 1, 0), len(shaft.segments) - 1)
        return shaft.segments[index].section.outer_diameter / 2.0 * mm

    longest = max(shaft.length for shaft in drivetrain.shafts) * mm
    for number, shaft in enumerate(drivetrain.shafts):
        place = placement[shaft.name]
        colour = _COLOURS[number % len(_COLOURS)]
        for segment, start in zip(shaft.segments, shaft.segment_ends[:-1]):
            radius = segment.section.outer_diameter / 2.0 * mm
            ax.add_patch(Rectangle(((place.offset + start) * mm, place.row * mm - radius), segment.length * mm,
                                   2.0 * radius, facecolor=colour, alpha=0.35, edgecolor=colour,
                                   gid=f"shaft:{shaft.name}"))
        ax.plot([place.offset * mm - 0.03 * longest, (place.offset + shaft.length) * mm + 0.03 * longest],
                [place.row * mm] * 2, color="0.4", lw=0.6, ls="-.")  # the axis
        ax.annotate(shaft.name, (place.offset * mm - 0.07 * longest, place.row * mm), ha="right", va="center",
                    fontsize=8, color=colour, fontweight="bold")
    gear_width = 0.06 * longest
    gears = set(radii)
    for disk in drivetrain.disks:
        z, row = at(disk.location)
        key = (disk.location.shaft, disk.location.position)
        if key in gears:
            radius, kind, style = radii[key] * mm, "gear", {"facecolor": "0.75", "hatch": "|||", "edgecolor": "k"}
        else:
            radius = math.sqrt(2.0 * disk.polar_inertia / disk.mass) * mm if disk.mass > 0 else shaft_radius(
                disk.location)
            kind, style = "disk", {"facecolor": "0.55", "edgecolor": "k"}
        ax.add_patch(Rectangle((z - gear_width / 2, row - radius), gear_width, 2.0 * radius, lw=0.8,
                               gid=f"{kind}:{disk.name}", **style))
        ax.annotate(disk.name, (z + gear_width / 2, row + 0.5 * radius), xytext=(3, 0), textcoords="offset points",
                    ha="left", va="center", fontsize=8)
    for key in gears - {(d.location.shaft, d.location.position) for d in drivetrain.disks}:
        location = next(p for m in drivetrain.meshes for p in (m.gear_1, m.gear_2) if (p.shaft, p.position) == key)
        z, row = at(location)
        ax.add_patch(Rectangle((z - gear_width / 2, row - radii[key] * mm), gear_width, 2.0 * radii[key] * mm,
                               facecolor="0.75", hatch="|||", edgecolor="k", lw=0.8, gid=f"gear:{key[0]}"))
    for mesh in drivetrain.meshes:
        z, row = at(mesh.gear_1)
        pitch = row - radii[(mesh.gear_1.shaft, mesh.gear_1.position)] * mm
        ax.plot([z], [pitch], marker="o", color="crimson", ms=5, gid=f"mesh:{mesh.name}")
        ax.annotate(mesh.name, (z + gear_width / 2, pitch), xytext=(4, 0), textcoords="offset points",
                    ha="left", va="center", fontsize=8, color="crimson")
    box = 0.05 * longest
    for bearing in drivetrain.bearings:
        z, row = at(bearing.location)
        radius = shaft_radius(bearing.location)
        for sign in (-1.0, 1.0):
            corner = (z - box / 2, row + sign * radius + (0.0 if sign > 0 else -box))
            ax.add_patch(Rectangle(corner, box, box, facecolor="white", edgecolor="k", lw=0.9,
                                   gid=f"bearing:{bearing.name}" if sign < 0 else None))
            ax.plot([corner[0], corner[0] + box], [corner[1], corner[1] + box], color="k", lw=0.6)
            ax.plot([corner[0], corner[0] + box], [corner[1] + box, corner[1]], color="k", lw=0.6)
        ax.annotate(bearing.name, (z, row - radius - box), xytext=(0, -3), textcoords="offset points",
                    ha="center", va="top", fontsize=7)
    for coupling in drivetrain.couplings:
        (z1, row1), (z2, row2) = at(coupling.first), at(coupling.second)
        ax.plot([z1, z2], [row1, row2], color="darkgreen", lw=3.0, solid_capstyle="butt", alpha=0.6)
        ax.plot([0.5 * (z1 + z2)], [0.5 * (row1 + row2)], marker="D", color="darkgreen", ms=7,
                gid=f"coupling:{coupling.name}")
        ax.annotate(coupling.name, (0.5 * (z1 + z2), 0.5 * (row1 + row2)), xytext=(0, 8), textcoords="offset points",
                    ha="center", va="bottom", fontsize=7, color="darkgreen")
    for support in drivetrain.torsional_supports:
        z, row = at(support.location)
        ax.plot([z], [row], marker="s", color="purple", ms=9, gid=f"support:{support.name}")
        ax.annotate(support.name, (z, row), xytext=(0, -10), textcoords="offset points", ha="center", va="top",
                    fontsize=7, color="purple")
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.margins(0.08)
    ax.set_xlabel("axial position z [mm]")
    ax.set_ylabel("across the shafts [mm]")
    ax.set_title("drivetrain layout (side view, to scale)", fontsize=10)
    return ax.figure


def _node_shape(assembled: AssembledDrivetrain, shape: np.ndarray, shaft: str) -> dict[str, np.ndarray]:
    """The x, y translations and the torsion at the shaft's outer surface (r·θ) of one real shape, per node."""
    offset = assembled.node_offsets[shaft]
    count = assembled.node_positions[shaft].size
    nodes = shape[6 * offset: 6 * (offset + count)].reshape(count, 6)
    radius = _largest_radius(next(s for s in assembled.drivetrain.shafts if s.name == shaft))
    return {"x": nodes[:, 0], "y": nodes[:, 1], "torsion": nodes[:, 5] * radius}


def plot_mode_shape(assembled: AssembledDrivetrain, shape: np.ndarray, title: str = "", ax=None):
    """One mode shape (DOFs,) drawn on the layout's shaft axes: each shaft's x (solid) and y (dashed)
    translation and its torsion at the surface r·θ (dotted) along z, scaled together so that the largest is
    0.4 of the spacing between rows; gears and bearings as ticks. Returns the figure."""
    assembled_shape = np.real_if_close(np.asarray(shape))
    if np.iscomplexobj(assembled_shape):  # a damped mode: the phase of its largest entry made real
        peak = assembled_shape[np.abs(assembled_shape).argmax()]
        assembled_shape = np.real(assembled_shape * np.conj(peak) / abs(peak))
    ax = _new_axes(ax, (8.0, 3.8))
    drivetrain = assembled.drivetrain
    placement = shaft_placement(drivetrain)
    rows = sorted({p.row for p in placement.values()})
    spacing = min(np.diff(rows)) if len(rows) > 1 else 4.0 * max(_largest_radius(s) for s in drivetrain.shafts)
    parts = {shaft.name: _node_shape(assembled, assembled_shape, shaft.name) for shaft in drivetrain.shafts}
    largest = max(float(np.abs(values).max()) for part in parts.values() for values in part.values())
    scale = 0.4 * spacing / largest if largest > 0 else 0.0
    mm = 1e3
    styles = {"x": "-", "y": "--", "torsion": ":"}
    for number, shaft in enumerate(drivetrain.shafts):
        place = placement[shaft.name]
        z = (place.offset + assembled.node_positions[shaft.name]) * mm
        colour = _COLOURS[number % len(_COLOURS)]
        ax.plot([z[0], z[-1]], [place.row * mm] * 2, color="0.7", lw=0.8)
        ax.annotate(shaft.name, (z[0], place.row * mm), xytext=(-8, 0), textcoords="offset points", ha="right",
                    va="center", fontsize=7, color=colour)
        for component, values in parts[shaft.name].items():
            ax.plot(z, (place.row + scale * values) * mm, styles[component], color=colour, lw=1.4,
                    gid=f"mode:{shaft.name}:{component}",
                    label=f"{shaft.name}: {component if component != 'torsion' else 'torsion r·θ'}")
    for bearing in drivetrain.bearings:
        place = placement[bearing.location.shaft]
        ax.plot([(place.offset + bearing.location.position) * mm], [place.row * mm], marker="^", color="k", ms=6,
                ls="none")
    for mesh in drivetrain.meshes:
        for gear in (mesh.gear_1, mesh.gear_2):
            place = placement[gear.shaft]
            ax.plot([(place.offset + gear.position) * mm], [place.row * mm], marker="|", color="crimson", ms=14,
                    ls="none")
    ax.set_xlabel("axial position z [mm]")
    ax.set_yticks([])
    ax.set_title("\n".join(textwrap.wrap(title, 110)), fontsize=8)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0), frameon=False)
    return ax.figure


def plot_bearing_spectra(spectra: dict[str, tuple[np.ndarray, np.ndarray]], ax=None, title: str = ""):
    """Bars of each bearing's radial force amplitude √(X_j² + Y_j²) [N] at the mesh harmonics j (``spectra``:
    bearing → (frequencies [Hz] of harmonics 1…J, amplitudes (J,) [N])), bearings side by side per harmonic.
    Returns the figure."""
    ax = _new_axes(ax, (7.0, 3.8))
    names = list(spectra)
    width = 0.8 / max(len(names), 1)
    frequencies = None
    for number, name in enumerate(names):
        frequencies, amplitudes = (np.asarray(values, dtype=float) for values in spectra[name])
        harmonics = np.arange(1, amplitudes.size + 1)
        ax.bar(harmonics - 0.4 + (number + 0.5) * width, np.nan_to_num(amplitudes), width,
               color=_COLOURS[number % len(_COLOURS)], label=name, gid=f"bearing-spectrum:{name}")
    if frequencies is not None:
        ax.set_xticks(np.arange(1, frequencies.size + 1),
                      [f"{j}×\n{f:.0f} Hz" for j, f in enumerate(frequencies, start=1)], fontsize=7)
    ax.set_xlabel("mesh harmonic")
    ax.set_ylabel("radial force amplitude [N]")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    return ax.figure


def plot_campbell(diagram, ax=None, label_share: float = 0.01):
    """Draw a :class:`~thermogear.drivetrain.campbell.CampbellDiagram` on ``ax`` (a new figure if None) and return
    the figure (:meth:`~thermogear.drivetrain.campbell.CampbellDiagram.plot_campbell` says what it shows)."""
    from matplotlib.collections import LineCollection
    from matplotlib.colors import LinearSegmentedColormap, Normalize

    ax = _new_axes(ax, (8.0, 5.0))
    speeds = diagram.speeds_rpm
    norm = Normalize(0.0, 1.0)
    colours = LinearSegmentedColormap.from_list("mesh share", ["#a7b0ba", "#1f5fa8", "#d62728"])
    lines = None
    for mode in range(diagram.frequencies_hz.shape[1]):
        points = np.column_stack([speeds, diagram.frequencies_hz[:, mode]])
        segments = np.stack([points[:-1], points[1:]], axis=1)
        share = 0.5 * (diagram.mesh_shares[:-1, mode] + diagram.mesh_shares[1:, mode])
        lines = LineCollection(segments, cmap=colours, norm=norm, linewidths=1.0 + 2.5 * share, gid=f"mode:{mode}")
        lines.set_array(share)
        ax.add_collection(lines)
    top = 1.08 * float(np.nanmax(diagram.frequencies_hz))
    for harmonic in diagram.harmonics:
        line = harmonic * diagram.teeth * speeds / 60.0
        ax.plot(speeds, line, color="0.35", ls="--", lw=0.8, gid=f"harmonic:{harmonic}")
        end = min(speeds[-1], 60.0 * top / (harmonic * diagram.teeth))  # where the line leaves the axes
        ax.annotate(f"{harmonic}× mesh", (end, harmonic * diagram.teeth * end / 60.0), xytext=(-3, -3),
                    textcoords="offset points", ha="right", va="top", fontsize=7, color="0.25")
    crossings = diagram.crossings
    ax.scatter([c.speed_rpm for c in crossings], [c.frequency_hz for c in crossings],
               c=[c.mesh_share for c in crossings], cmap=colours, norm=norm, s=[18 + 60 * c.mesh_share
                                                                                for c in crossings],
               edgecolors="k", linewidths=0.6, zorder=3, gid="crossings")
    labelled = [c for c in crossings if c.mesh_share >= label_share]
    ax.set_xlim(speeds[0], speeds[-1])
    ax.set_ylim(0.0, top)
    taken: list[tuple[float, float]] = []  # number positions in axes fractions, to keep them apart
    for number, crossing in enumerate(sorted(labelled, key=lambda c: (c.speed_rpm, c.frequency_hz)), start=1):
        x = (crossing.speed_rpm - speeds[0]) / (speeds[-1] - speeds[0])
        y = crossing.frequency_hz / top
        lift = 0
        while any(abs(x - a) < 0.03 and abs(y + lift * 0.03 - b) < 0.025 for a, b in taken):
            lift += 1
        taken.append((x, y + lift * 0.03))
        ax.annotate(str(number), (crossing.speed_rpm, crossing.frequency_hz), xytext=(4, 2 + 9 * lift),
                    textcoords="offset points", fontsize=7, fontweight="bold", gid="crossing-label",
                    bbox={"boxstyle": "round,pad=0.1", "facecolor": "white", "edgecolor": "none", "alpha": 0.8},
                    arrowprops={"arrowstyle": "-", "color": "0.5", "lw": 0.5} if lift else None)
        # an empty line whose marker is the number: the legend entry (also where a report gathers legends)
        ax.plot([], [], ls="none", marker=f"${number}$", color="k", markersize=5 + 2 * len(str(number)),
                label=f"{crossing.harmonic}× at {crossing.speed_rpm:.0f} rpm, {crossing.frequency_hz:.0f} Hz "
                      f"{crossing.label}, share {crossing.mesh_share:.2f}")
    if labelled:
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.14), ncol=2, frameon=False)
    if lines is not None:
        colourbar = ax.figure.colorbar(lines, ax=ax, pad=0.01)
        colourbar.set_label("mesh share of modal strain energy [–]", fontsize=8)
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"interference diagram: {len(crossings)} crossings marked, the {len(labelled)} of modes with a "
                 f"mesh share ≥ {label_share:g} numbered", fontsize=9)
    return ax.figure
