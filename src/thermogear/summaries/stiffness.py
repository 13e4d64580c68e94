"""The elastic mesh stiffness of a case as ``thermogear stiffness`` shows it: the pair and single-tooth stiffness
along the path (potential energy method), the mesh stiffness over one period from the mesh model, and the ISO 6336-1
Method B cross-check, per unit face width in N/(mm·μm); and its figure."""

from __future__ import annotations

import warnings

import numpy as np

from thermogear.errors import ExtrapolationWarning
from thermogear.materials import Material
from thermogear.mesh.model import MeshModel
from thermogear.operating import OperatingPoint
from thermogear.stiffness.fillet_foundation import gear_sainsot_messages
from thermogear.stiffness.iso6336 import N_PER_MM_UM, iso6336_stiffness
from thermogear.stiffness.table import pair_compliance_table, tooth_compliance_at

__all__ = ["MESH_GRID_COUNT", "POINTS", "plot_stiffness", "stiffness_summary"]

POINTS = ("A", "B", "C", "D", "E")
MESH_GRID_COUNT = 2048


def stiffness_summary(mesh: MeshModel, material: Material, operating: OperatingPoint, name: str
                      ) -> tuple[dict, list[str]]:
    """The JSON summary of the elastic stiffness of the elastic mesh model ``mesh`` of a case named ``name``, its
    pair of ``material`` at the operating point ``operating`` (per-unit-width values in N/(mm·μm)), and the
    extrapolation warnings raised while computing it."""
    pair = mesh.gear_pair
    width = pair.face_width
    per_width = 1.0 / (width * N_PER_MM_UM)  # N/m total → N/(mm·μm)
    messages = (gear_sainsot_messages(pair.pinion, "pinion") + gear_sainsot_messages(pair.wheel, "wheel"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ExtrapolationWarning)
        points = pair.path_points
        rolls = np.array([points[name] for name in POINTS])
        pair_k = mesh.pair_stiffness_at(rolls)
        delta_1, delta_2 = tooth_compliance_at(pair, material, rolls)
        table = pair_compliance_table(pair, material)
        state = mesh.state(points_per_period=MESH_GRID_COUNT, damping=False)
        grid, mesh_k = state.grid, state.mesh_stiffness
        iso = iso6336_stiffness(pair, material, operating)  # ISO 6336-1 Method B of the same pair
    messages += [str(w.message) for w in caught
                 if issubclass(w.category, ExtrapolationWarning) and "Sainsot" not in str(w.message)]
    gamma = pair.gamma(rolls)
    mean = float(grid.time_average(mesh_k))
    summary = {
        "case": name,
        "contact_ratio": pair.contact_ratio,
        "centre_distance_mm": pair.centre_distance * 1e3,
        "operating_pressure_angle_deg": float(np.degrees(pair.operating_pressure_angle)),
        "face_width_mm": width * 1e3,
        "base_pitch_mm": pair.base_pitch * 1e3,
        "mesh_period_s": state.period,
        "path_mm": {name: float(points[name] * 1e3) for name in POINTS},
        "gamma": {name: float(value) for name, value in zip(POINTS, gamma)},
        "pair_stiffness_n_per_mm_um": {name: float(k * per_width) for name, k in zip(POINTS, pair_k)},
        "tooth_stiffness_n_per_mm_um": {
            "pinion": {name: float(per_width / (d - 0.5 * table.hertz)) for name, d in zip(POINTS, delta_1)},
            "wheel": {name: float(per_width / (d - 0.5 * table.hertz)) for name, d in zip(POINTS, delta_2)},
            "hertz": float(per_width / table.hertz),
        },
        "mesh_stiffness_n_per_mm_um": {"min": float(mesh_k.min() * per_width), "mean": mean * per_width,
                                       "max": float(mesh_k.max() * per_width)},
        "mesh_stiffness_total_n_per_m": {"min": float(mesh_k.min()), "mean": mean, "max": float(mesh_k.max())},
        "iso6336": {"c_prime_n_per_mm_um": iso["c_prime"] / N_PER_MM_UM,
                    "c_gamma_alpha_n_per_mm_um": iso["c_gamma_alpha"] / N_PER_MM_UM},
        "pem_mean_over_iso_c_gamma_alpha": mean * per_width / (iso["c_gamma_alpha"] / N_PER_MM_UM),
        "method": "potential energy method (Hertz, bending, shear, axial, Sainsot fillet foundation); "
                  "pairs in parallel; ISO 6336-1 Method B cross-check",
        "warnings": messages,
    }
    if mesh.case.helical_pair is not None:  # the pair's own: the slice model's K_t (mesh.state) and ISO's helical c′
        from thermogear.summaries.helical import helical_stiffness_summary  # noqa: PLC0415

        helical = helical_stiffness_summary(mesh)
        summary.update(helical=helical, iso6336=helical["iso6336"],
                       pem_mean_over_iso_c_gamma_alpha=helical["slice_mean_over_iso_c_gamma_alpha"],
                       method=helical["method"])
    return summary, messages


def plot_stiffness(mesh: MeshModel, material: Material, name: str, ax=None):
    """Figure: pair and single-tooth stiffness along Γ, and the mesh stiffness over one period (per mm of face
    width) of the elastic mesh model ``mesh`` of a case named ``name``, its pair of ``material``. ``ax``: an array of
    three axes, or None for a new figure. Returns the figure."""
    import matplotlib.pyplot as plt

    pair = mesh.gear_pair
    per_width = 1.0 / (pair.face_width * N_PER_MM_UM)
    table = pair_compliance_table(pair, material)
    gamma = pair.gamma(table.roll)
    if ax is None:
        figure, ax = plt.subplots(1, 3, figsize=(15, 4.2), constrained_layout=True)
    else:
        figure = ax[0].figure
    ax[0].plot(gamma, table.stiffness * per_width, color="k")
    for name, roll in pair.path_points.items():
        ax[0].axvline(pair.gamma(roll), color="0.8", lw=0.8)
        ax[0].annotate(name, (pair.gamma(roll), ax[0].get_ylim()[0]), textcoords="offset points", xytext=(2, 4))
    ax[0].set(xlabel="Γ", ylabel="pair stiffness [N/(mm·μm)]", title="Tooth pair along the path of contact")
    ax[1].plot(gamma, per_width / table.pinion.total, label="pinion tooth")
    ax[1].plot(gamma, per_width / table.wheel.total, label="wheel tooth")
    ax[1].axhline(per_width / table.hertz, color="0.5", ls="--", label="Hertz")
    ax[1].set(xlabel="Γ", ylabel="stiffness [N/(mm·μm)]", title="Single-tooth stiffness", yscale="log")
    ax[1].legend()
    state = mesh.state(points_per_period=MESH_GRID_COUNT, damping=False)
    grid, per_pair, total = state.grid, state.pair_stiffness, state.mesh_stiffness
    period = grid.nodes[-1]
    ax[2].plot(grid.midpoints / period, total * per_width, color="k", label="mesh")
    for slot in range(per_pair.shape[0]):
        values = np.where(grid.in_contact[slot], per_pair[slot] * per_width, np.nan)
        ax[2].plot(grid.midpoints / period, values, lw=0.8, label=f"pair {slot}")
    ax[2].set(xlabel="τ / T_m", ylabel="stiffness [N/(mm·μm)]", title="Mesh stiffness over one period")
    ax[2].legend()
    figure.suptitle(f"{name}: elastic mesh stiffness (potential energy method)")
    return figure
