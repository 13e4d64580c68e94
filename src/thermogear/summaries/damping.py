"""The friction damping of a case, elastic and thermal, as the ``thermogear damping`` command and the report
show it (Luo & Li (2020) Eqs. 26–28, Figs. 7–8), computed by the mesh model."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from thermogear.friction.damping import MODELS, contact_region_means, damping_rule, mesh_damping
from thermogear.lubricant import Lubricant
from thermogear.mesh.model import MeshModel
from thermogear.schema.dynamics import DampingSection


@dataclass(frozen=True)
class DampingSummary:
    """Elastic and thermal friction damping of a case: per pair along the path and c(τ) over one mesh cycle.

    ``path``: PairDamping per model on an even roll grid A–E; ``mesh``: c(τ) [N·s/m] per model on ``grids``
    (a MeshGrid per model: the thermoelastic model meshes on the hot pair's path); ``region_means: time means of c(τ) over the single- and double-pair regions per model.
    """

    case_name: str
    rule: str
    stiffness: str
    lubricant: Lubricant
    path: dict
    grids: dict
    mesh: dict
    region_means: dict
    pitch: dict  # PairDamping at C per model

    def to_dict(self) -> dict:
        """The JSON summary of ``thermogear damping`` (the command adds the paper's means for a parameter set of
        the paper: they are the paper table's, :func:`thermogear.luo2020.report.table.paper_reference`)."""
        oil, pitch = self.lubricant, self.pitch
        flank_viscosity = float(np.mean(self.path["thermal"].viscosity))
        result = {
            "case": self.case_name, "rule": self.rule, "stiffness": self.stiffness,
            "lubricant": {"name": oil.name, "base_oil": oil.base_oil, "lubricant_factor_oil": oil.lubricant_factor},
            "friction_coefficient_pitch": {model: float(pitch[model].friction_coefficient[0]) for model in MODELS},
            "damping_n_s_per_m": self.region_means,
            "thermal_over_elastic": {region: self.region_means["thermal"][region]
                                     / self.region_means["elastic"][region] for region in ("single", "double")},
            "viscosity_mpa_s": {"oil_reference": float(pitch["elastic"].viscosity[0]) * 1e3,
                                "flank_mean": flank_viscosity * 1e3},
            "temperature_c": {"oil_reference": float(pitch["elastic"].temperature_c[0]),
                              "flank_mean": float(np.mean(self.path["thermal"].temperature_c))},
            "along_path": {"gamma": self.path["elastic"].gamma,
                           "elastic_n_s_per_m": self.path["elastic"].damping,
                           "thermal_n_s_per_m": self.path["thermal"].damping,
                           "friction_elastic": self.path["elastic"].friction_coefficient,
                           "friction_thermal": self.path["thermal"].friction_coefficient},
        }
        return result


def damping_summary(meshes: Mapping[str, MeshModel], section: DampingSection, name: str, count: int = 720,
                    path_points: int = 81, rule: str | None = None) -> DampingSummary:
    """The elastic and thermal friction damping of a case named ``name`` at its operating point (per pair along the
    path and over the mesh cycle), from its mesh model of each model (``meshes``: model name → mesh model) and its
    ``[damping]`` section (the rule unless ``rule`` is given)."""
    rule = section.rule if rule is None else rule
    damping_rule(rule)  # an unknown rule is refused before any model runs
    path, mesh, means, pitch, grids = {}, {}, {}, {}, {}
    oil = None
    for model in MODELS:
        mesh_model = meshes[model]
        oil = mesh_model.lubricant
        pair = mesh_model.gear_pair
        path[model] = mesh_model.pair_damping_at(pair.roll_grid(path_points))
        pitch[model] = mesh_model.pair_damping_at(np.array([pair.path_points["C"]]))
        state = mesh_model.section_state(points_per_period=count)  # a helical pair: its transverse section's pairs
        grid = grids[model] = state.grid
        mesh[model] = mesh_damping(state.pair_damping, grid.in_contact, rule)
        means[model] = contact_region_means(mesh[model], grid.contact_count, grid.steps)
    return DampingSummary(case_name=name, rule=rule, stiffness=section.stiffness, lubricant=oil,
                          path=path, grids=grids, mesh=mesh, region_means=means, pitch=pitch)


__all__ = ["DampingSummary", "damping_summary"]
