"""Figures of the FE verification: Luo & Li Fig. 3(b) (tooth bulk temperature), 3(c) (flank temperature along
Γ) and 15 (FE elastic and thermo-elastic stiffness along the path, beside the analytical curves). Each
``plot_*(analysis, ax=None)`` returns the matplotlib figure."""

from __future__ import annotations


def _axes(ax, size=(6.0, 4.0)):
    import matplotlib.pyplot as plt  # noqa: PLC0415

    if ax is None:
        figure, ax = plt.subplots(figsize=size, constrained_layout=True)
        return figure, ax
    return ax.figure, ax


def plot_temperature_field(analysis, ax=None, which: str = "pinion"):
    """Fig. 3(b): steady bulk temperature of one tooth sector [°C]."""
    figure, ax = _axes(ax, (4.5, 5.0))
    temperature = analysis.temperatures[which]
    mesh = temperature.mesh.mesh
    shading = ax.tripcolor(mesh.p[0] * 1e3, mesh.p[1] * 1e3, mesh.t.T, temperature.vertex_values,
                           shading="gouraud", cmap="inferno")
    figure.colorbar(shading, ax=ax, label="temperature [°C]")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"{which} tooth bulk temperature (FE)")
    return figure


def plot_flank_temperature(analysis, ax=None, paper_band: tuple[float, float] | None = None):
    """Fig. 3(c): meshing-flank temperature along the path, FE points and the fitted polynomial; ``paper_band``
    (lowest, highest) [°C]: the paper's range, shaded (the caller passes it for a parameter set of the paper:
    :func:`thermogear.luo2020.report.table.paper_reference`)."""
    figure, ax = _axes(ax)
    pair = analysis.gear_pair
    roll = pair.roll_grid(81)
    gamma = pair.gamma(roll)
    ax.plot(gamma, analysis.temperatures["pinion"].flank_c(roll), label="FE pinion flank")
    ax.plot(gamma, analysis.temperature_field.pinion_flank_c(gamma), "--", label="fitted polynomial (to the chain)")
    wheel_roll = pair.line_of_action_length - roll
    ax.plot(gamma, analysis.temperatures["wheel"].flank_c(wheel_roll), ":", label="FE wheel flank")
    if paper_band is not None:
        ax.axhspan(*paper_band, color="0.85", label="Luo & Li Fig. 3(c) range")
    ax.set_xlabel("contact position Γ [–]")
    ax.set_ylabel("flank bulk temperature [°C]")
    ax.legend(fontsize=8)
    return figure


def plot_stiffness_along_path(analysis, ax=None):
    """Fig. 15: FE pair stiffness (elastic, thermo-elastic) and the PEM's along the path [N/(mm·μm)]."""
    from thermogear.stiffness.potential_energy import pair_compliance  # noqa: PLC0415

    figure, ax = _axes(ax, (6.5, 4.0))
    pair, material = analysis.gear_pair, analysis.inputs.material
    width = pair.face_width
    scale = 1.0 / (width * 1e9)
    result = analysis.thermal_result()
    ax.plot(analysis.gamma, result.elastic_stiffness * scale, "o-", label="FE elastic")
    ax.plot(analysis.gamma, result.stiffness * scale, "s-", label=f"FE thermo-elastic (X_te = {analysis.x_te:.3g})")
    pem = pair_compliance(pair, material, analysis.roll)
    ax.plot(analysis.gamma, pem.stiffness * scale, "k:", label="PEM elastic")
    ax.set_xlabel("contact position Γ [–]")
    ax.set_ylabel("pair stiffness [N/(mm·μm)]")
    ax.legend(fontsize=8)
    return figure


def plot_compliance_comparison(analysis, ax=None):
    """FE and PEM single-tooth stiffness of both gears along the path [N/(mm·μm)]."""
    figure, ax = _axes(ax)
    width = analysis.gear_pair.face_width
    for name, marker in (("pinion", "o"), ("wheel", "s")):
        item = analysis.deflection[name]
        ax.plot(analysis.gamma, 1.0 / (item.compliance * width * 1e9), marker + "-", label=f"{name} FE")
        ax.plot(analysis.gamma, 1.0 / (item.pem * width * 1e9), marker + ":", label=f"{name} PEM")
    ax.set_xlabel("contact position Γ [–]")
    ax.set_ylabel("single-tooth stiffness [N/(mm·μm)]")
    ax.legend(fontsize=8)
    return figure


__all__ = ["plot_compliance_comparison", "plot_flank_temperature", "plot_stiffness_along_path",
           "plot_temperature_field"]

