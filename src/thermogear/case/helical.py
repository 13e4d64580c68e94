"""Load-time checks and the transverse view of a helical pair's ``[gears]`` section (issue 37).

A helical pair runs through the models as its transverse section (:class:`~thermogear.helical.geometry.HelicalPair`)
plus its helix. What the transverse model reads of ``[gears]`` in normal-section terms is converted once here: the
normal backlash j_bn becomes the backlash along the transverse line of action, j_bt = j_bn / cos β_b (the normal
plane is inclined at β_b to the transverse plane on the plane of action, ISO 21771 §5.4). What is not yet built for
a helical pair is refused with the key and the reason.
"""

from __future__ import annotations

import math

from thermogear.errors import CaseError
from thermogear.helical.geometry import HelicalPair
from thermogear.temperature.kinds import TEMPERATURE_SOURCES, temperature_source
from thermogear.choices.thermal_models import thermal_model_rules

__all__ = ["check_helical_case", "check_face_gradient", "transverse_gears_section"]


def transverse_gears_section(gears, helical: HelicalPair):
    """The ``[gears]`` section as the transverse model reads it: the normal backlash along the transverse line of
    action (module docstring); the same object for a spur pair."""
    if helical.helix_angle == 0.0 or gears.backlash_normal_um is None:
        return gears
    return gears.model_copy(update={"backlash_normal_um": gears.backlash_normal_um
                                    / math.cos(helical.base_helix_angle)})


def check_helical_case(model) -> None:
    """Refuse, for a helical pair (``[gears] helix_angle_deg`` > 0; before its geometry is built), what the models
    do not build for one: a thermal model that is spur-only (the paper's ``luo2020``) and a temperature model whose
    heat input is the spur pair's (the FE model; a ``[drivetrain]`` takes the helical pair through its helical mesh
    element, :mod:`thermogear.drivetrain.mesh_element`, and the gearbox network its helical losses)."""
    if model.gears.helix_angle_deg == 0.0:
        return
    rules = thermal_model_rules(model.thermal.model)
    if rules.spur_only:
        raise CaseError("thermal.model", model.thermal.model, "'thermoelastic' with gears.helix_angle_deg > 0",
                        "the paper's thermal stiffness (Luo & Li 2020, Eqs. 13–23, X_te fitted on a spur pair) is "
                        "spur-only; the thermo-elastic model takes a helical pair")
    if not temperature_source(model.temperature.model).takes_helical:
        allowed = " | ".join(name for name, kind in TEMPERATURE_SOURCES.items() if kind.takes_helical)
        raise CaseError("temperature.model", model.temperature.model, f"{allowed} with gears.helix_angle_deg > 0",
                        "the FE temperature model computes the spur pair's heat input; a helical pair takes given "
                        "temperatures (and temperature.face_gradient_k across the face) or the gearbox network's")


def check_face_gradient(model, helical: HelicalPair) -> None:
    """A temperature gradient across the face distorts the lead, which the slice model of a helical pair carries;
    the spur pair's mesh has no slices across the face, so a spur case with a gradient is refused."""
    gradient = model.temperature.face_gradient_k
    if gradient != 0.0 and helical.helix_angle == 0.0:
        raise CaseError("temperature.face_gradient_k", gradient, "0 with gears.helix_angle_deg = 0",
                        "the lead distortion across the face is carried by the helical slice model; the spur "
                        "pair's mesh has no slices across the face")
    if gradient != 0.0 and not thermal_model_rules(model.thermal.model).expands_geometry:
        raise CaseError("temperature.face_gradient_k", gradient, "0 unless thermal.model expands the geometry",
                        "the lead distortion is a thermal expansion, which only the thermo-elastic model takes")
