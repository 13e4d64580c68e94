"""The ``thermal`` object of ``thermogear stiffness CASE --thermal --json`` and its figure.

:func:`thermal_block` answers for either thermal model of a case resolved into :class:`ThermalModels`: the thermo-elastic model's keys (``model``, ``operating``,
``cold``, ``youngs_modulus_gpa``, ``mesh_stiffness_n_per_mm_um``, ``deviation_um``,
``loaded_transmission_error_um``, ``jamming_bulk_temperature_c``, ``jamming_margin_k`` — the jamming
temperature above the hotter gear's operating bulk temperature —, …) and, where the case configures X_te, the
paper's model (Luo & Li 2020) beside it — at the top level for ``model = "luo2020"`` (today's keys, unchanged) with
the thermo-elastic prediction under ``thermoelastic``, else under ``luo2020``. Plain floats; stiffness per unit face
width in N/(mm·μm), lengths in μm and mm, temperatures in °C.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from thermogear.case.keys import LUO2020_KEYS, luo2020_complete
from thermogear.errors import ExtrapolationWarning
from thermogear.mesh.model import MeshModel
from thermogear.temperature.source import TemperatureField
from thermogear.thermoelastic.mesh import ThermoelasticMesh

if TYPE_CHECKING:
    from thermogear.luo2020.thermal.case_stiffness import PaperThermalModel

#: N/m per metre of face width → N/(mm·μm)
PER_WIDTH_TO_N_PER_MM_UM = 1e-9


#: Roll positions along the path for the deviation's peak-to-peak [–].
PATH_POINT_COUNT = 401


def _geometry(pair, backlash: float) -> dict:
    return {"centre_distance_mm": pair.centre_distance * 1e3,
            "pressure_angle_deg": math.degrees(pair.operating_pressure_angle),
            "contact_ratio": pair.contact_ratio, "backlash_normal_um": backlash * 1e6}


def _statistics(grid, values, scale: float) -> dict:
    return {"min": float(values.min() * scale), "mean": float(grid.time_average(values) * scale),
            "max": float(values.max() * scale)}


@dataclass(frozen=True, eq=False)
class ThermalModels:
    """What the stiffness command shows of a case's thermal models, resolved by the command: the paper's k_T model
    ``paper`` (Luo & Li 2020; cheap to resolve, and it holds the case's ``[thermal]`` section and temperature field,
    which the thermo-elastic summary reads too), the ``elastic`` and ``thermal`` mesh models, the thermo-elastic
    component (``component_of()``, built when first asked: the paper's figure does not need it) and the case's name
    (``name``, the figure's title)."""

    paper: "PaperThermalModel"
    elastic: MeshModel
    thermal: MeshModel
    component_of: Callable[[], ThermoelasticMesh]
    name: str


def thermoelastic_summary(component: ThermoelasticMesh, thermal_model: str, temperature: TemperatureField) -> dict:
    """The thermo-elastic model's JSON object (module docstring) of the ``component`` of a case whose ``[thermal]
    model`` is ``thermal_model``, with the case's ``temperature`` field described."""
    hot, cold = component.gear_pair, component.cold_gear_pair
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)  # the elastic summary reports them
        grid, stiffness = component.mesh_stiffness()
        cold_grid, cold_stiffness = component.mesh_stiffness(cold=True)
        _, loaded = component.loaded_transmission_error()
        _, cold_loaded = component.loaded_transmission_error(cold=True)
        flags = list(component.plausibility)
    roll = hot.roll_grid(PATH_POINT_COUNT)
    parts = component.deviation_parts_at(roll)
    deviation = parts["tip_relief"] + parts["base_pitch"] + parts["thermal_distortion"]
    hot_scale = PER_WIDTH_TO_N_PER_MM_UM / hot.face_width
    cold_scale = PER_WIDTH_TO_N_PER_MM_UM / cold.face_width
    mean_change = grid.time_average(stiffness) / cold_grid.time_average(cold_stiffness) - 1.0
    pinion, wheel = component.gears
    return {
        "model": thermal_model,
        "operating": _geometry(hot, component.backlash_normal),
        "cold": _geometry(cold, component.backlash_normal_cold),
        "temperatures_c": {"reference": component.reference_c, "housing": component.housing_c,
                           "bulk": {"pinion": component.bulk_c[0], "wheel": component.bulk_c[1]},
                           "tooth": {"pinion": component.tooth_c[0], "wheel": component.tooth_c[1]}},
        "youngs_modulus_gpa": {"pinion": component.youngs_modulus[0] * 1e-9,
                               "wheel": component.youngs_modulus[1] * 1e-9},
        "mesh_stiffness_n_per_mm_um": _statistics(grid, stiffness, hot_scale),
        "mesh_stiffness_change_percent": float(100.0 * mean_change),
        "deviation_um": {"peak_to_peak": float(np.ptp(deviation) * 1e6),
                         **{f"{name}_peak_to_peak": float(np.ptp(values) * 1e6) for name, values in parts.items()}},
        "loaded_transmission_error_um": {"mean": float(grid.time_average(loaded.approach) * 1e6),
                                         "peak_to_peak": loaded.peak_to_peak * 1e6},
        "jamming_bulk_temperature_c": component.jamming_bulk_temperature_c,
        "jamming_margin_k": (None if component.jamming_bulk_temperature_c is None
                             else component.jamming_bulk_temperature_c - max(component.bulk_c)),
        "elastic": {"youngs_modulus_gpa": {"pinion": component.youngs_modulus_cold[0] * 1e-9,
                                           "wheel": component.youngs_modulus_cold[1] * 1e-9},
                    "mesh_stiffness_n_per_mm_um": _statistics(cold_grid, cold_stiffness, cold_scale),
                    "loaded_transmission_error_um": {
                        "mean": float(cold_grid.time_average(cold_loaded.approach) * 1e6),
                        "peak_to_peak": cold_loaded.peak_to_peak * 1e6}},
        "normal_load_n": component.normal_load,
        "assumptions": {
            "backlash": f"normal backlash at {component.reference_c:g} °C: {component.allowance.nominal * 1e6:.1f} μm "
                        f"({component.allowance.source})",
            "youngs_modulus": f"E(T) = E(20 °C)·[1 + β_E (T − 20 °C)], β_E pinion "
                              f"{pinion.modulus_coefficient_per_k:.3g} /K ({pinion.modulus_source}), wheel "
                              f"{wheel.modulus_coefficient_per_k:.3g} /K ({wheel.modulus_source})",
            "housing": f"housing expansion {component.housing.expansion_per_k:.3g} /K at {component.housing_c:g} °C "
                       f"({component.housing.source})",
            "geometry": "gears scaled by their equivalent bulk rise (the uniform rise with the same base-circle "
                        "expansion, Luo & Li Eq. 10); the rest of the field distorts the loaded flank (consistent "
                        "Eqs. 8–12)",
        },
        "plausibility": flags,
        "temperature": temperature.describe(),
    }


def _luo2020_configured(section) -> bool:
    """The ``[thermal]`` section sets the paper's keys and they define X_te completely (else they are named as
    having no effect when the case loads, :mod:`thermogear.case.keys`)."""
    return bool(set(LUO2020_KEYS) & section.model_fields_set) and luo2020_complete(section)


def _paper_summary(models: ThermalModels) -> dict:
    """The paper's k_T summary (:func:`thermogear.summaries.thermal.thermal_stiffness_summary`)."""
    from thermogear.summaries.thermal import thermal_stiffness_summary  # noqa: PLC0415  (the paper's model)

    return thermal_stiffness_summary(models.paper, models.elastic, models.thermal)


def _thermoelastic_summary(models: ThermalModels) -> dict:
    """:func:`thermoelastic_summary` of the case's thermo-elastic component."""
    return thermoelastic_summary(models.component_of(), models.paper.section.model, models.paper.temperature)


def thermal_block(models: ThermalModels) -> dict:
    """The ``thermal`` object of the stiffness command for the case's thermal model (module docstring)."""
    if models.thermal.pair_model.uses_x_te:
        block = {"model": "luo2020", **_paper_summary(models)}
        block["thermoelastic"] = _thermoelastic_summary(models)
        return block
    block = _thermoelastic_summary(models)
    if _luo2020_configured(models.paper.section):
        block["luo2020"] = _paper_summary(models)
    return block


def write_thermal_plot(models: ThermalModels, path) -> None:
    """Write the thermal figure of the stiffness command to ``path`` (atomically; format from the suffix): the
    paper's Fig. 4 for ``luo2020``, else deviation, loaded STE and load share, elastic and thermal."""
    from thermogear.summaries.thermal_plots import save_figure_atomically  # noqa: PLC0415

    if models.thermal.pair_model.uses_x_te:
        from thermogear.summaries.thermal_plots import plot_thermal_curves  # noqa: PLC0415
        from thermogear.summaries.thermal import thermal_curves  # noqa: PLC0415

        figure = plot_thermal_curves(thermal_curves(models.paper), models.name)
    else:
        from thermogear.summaries.thermoelastic_plots import plot_thermoelastic  # noqa: PLC0415

        figure = plot_thermoelastic(models.component_of(), title=models.name)
    save_figure_atomically(figure, path)


#: The names the stiffness command calls (``thermal_module.thermal_stiffness_summary`` / ``.plot_thermal_stiffness``).
thermal_stiffness_summary = thermal_block
plot_thermal_stiffness = write_thermal_plot
