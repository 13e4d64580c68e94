"""Where a drivetrain's temperatures come from: a model that predicts them (the gearbox thermal network, under
``[temperature].model = "gearbox"``) hands the drivetrain its shafts' temperatures and its bearings' ring
temperatures as a :class:`DrivetrainHeat`.

The provider is found by the temperature model's name in :data:`thermogear.composition.DRIVETRAIN_HEAT`
(``provider(case) -> DrivetrainHeat``; looked up by the drivetrain's resolver,
:func:`thermogear.drivetrain.case_model.case_drivetrain`); a temperature model without one leaves the shafts at the default of
:mod:`thermogear.drivetrain.case_model` (each shaft's ``temperature_c``, else the gears' mean tooth temperature).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from thermogear.drivetrain.bearing_clearance import OperatingClearance, operating_clearance

__all__ = ["BearingRings", "DrivetrainHeat"]


@dataclass(frozen=True)
class BearingRings:
    """One bearing's inner-ring (shaft side) and outer-ring (housing side) temperatures [°C], where its size is
    known its outer raceway diameter [m] (None: its clearance is held), and where the model computes its loss, the
    radial load [N] and the power loss [W] it gave there."""

    inner_c: float
    outer_c: float
    outer_raceway_diameter: float | None = None
    radial_load: float | None = None
    loss: float | None = None


@dataclass(frozen=True)
class DrivetrainHeat:
    """Temperatures a model predicts for the drivetrain: ``shaft_temperature_c`` shaft name → uniform temperature
    [°C], ``bearings`` bearing name → :class:`BearingRings`, ``source`` one line saying where they came from, and
    ``nodes_c`` the predicting network's node temperatures [°C] by name (for the report)."""

    shaft_temperature_c: Mapping[str, float]
    bearings: Mapping[str, BearingRings]
    source: str
    nodes_c: Mapping[str, float] = field(default_factory=dict)

    def clearance(self, name: str, mounted: float) -> OperatingClearance | None:
        """The operating play of bearing ``name`` mounted with ± ``mounted`` [m] at its ring temperatures
        (:func:`~thermogear.drivetrain.bearing_clearance.operating_clearance`); None where its size is unknown."""
        rings = self.bearings.get(name)
        if rings is None or rings.outer_raceway_diameter is None:
            return None
        return operating_clearance(mounted, rings.outer_raceway_diameter, rings.inner_c, rings.outer_c)
