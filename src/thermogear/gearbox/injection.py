"""No-load gear loss of injection (oil-jet) lubrication: the impulse loss of accelerating the jet.

A jet of oil, volume flow Q [m³/s] at speed v_j [m/s], aimed at the mesh along the pitch-line direction, is caught
by the teeth and leaves with them at the pitch-line speed v_t = ω1·r_w1. The momentum balance of the oil over a
control volume around the mesh (the angular-momentum balance of Euler's turbomachine equation, with the oil
entering at ±v_j and leaving at v_t on the same radius) gives the power the gears spend on it:

    P_VZ0,jet = ρ·Q·v_t·(v_t − s·v_j)                                                         [W]   (1)

s = +1 for a jet into the mesh inlet, moving with the teeth that enter the mesh; s = −1 for a jet at the mesh
outlet, against the teeth that leave it (the oil's tangential momentum is reversed: v_t + v_j).

ρ the oil density at the sump temperature [kg/m³]. Gear-loss procedures for injection lubrication list this as
the *pulse* (impulse) loss beside squeeze and ventilation losses (the FVA-Workbench documentation, "Power loss",
names Ariura and Butsch for it); those works were not read for this module: (1) is derived here from the momentum
balance alone, and the docs give a hand calculation of it (docs/gearbox-temperature.md). The oil then leaves the
teeth at v_t and dissipates its kinetic energy in the housing and the sump, so the heat of (1) goes to the oil node.

Validity and what is left out:

* an inlet jet with 0 ≤ v_j ≤ v_t (the usual design: into-mesh jets at or below the pitch-line speed; Akin &
  Townsend, "Into-mesh lubrication of spur gears with arbitrary offset oil jet", J. Mech. Trans. Autom. Des. 105
  (1983) 713, find the best cooling at v_j = v_t). A faster inlet jet would drive the gears: (1) turns negative,
  which is not modelled; the loss is then taken as 0 and :func:`jet_validity` says so. An outlet jet: any v_j;
* the jet's own kinetic power ½·ρ·Q·v_j² comes from the external pump (not a loss of the gears); it also ends as
  heat in the gearbox and is left out of the heat balance;
* the squeezing (trapping) of oil and air between the teeth in the mesh and the windage of the gears in the
  oil mist: no formula from a source within reach of this project; not modelled (both grow with speed: (1) is a
  lower bound of the no-load gear loss of an injection-lubricated stage).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.errors import CaseError
from thermogear.registry import registered

__all__ = ["JET_POSITIONS", "OilJet", "jet_at_outlet", "jet_impulse_power", "jet_validity"]

#: Largest accepted flow [m³/s] (1000 L/min: far above any single-stage spur gear's jets) and jet speed [m/s].
LARGEST_FLOW = 1000.0 / 60000.0
FASTEST_JET = 200.0


@dataclass(frozen=True)
class OilJet:
    """An oil jet at the mesh: volume flow ``flow_rate`` [m³/s], jet speed ``jet_speed`` [m/s], and
    ``at_outlet``: aimed at the mesh outlet against the teeth (s = −1 in (1)) instead of into the inlet (s = +1)."""

    flow_rate: float
    jet_speed: float
    at_outlet: bool = False

    @property
    def sense(self) -> float:
        """s of (1): +1 with the teeth (inlet), −1 against them (outlet)."""
        return -1.0 if self.at_outlet else 1.0

    def __post_init__(self) -> None:
        for key, value, limit in (("flow_rate", self.flow_rate, LARGEST_FLOW),
                                  ("jet_speed", self.jet_speed, FASTEST_JET)):
            if (isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value)
                    or not 0.0 < value <= limit):
                raise CaseError(f"oil_jet.{key}", value, f"(0, {limit:g}] (SI)", "an oil jet's flow and speed")


#: Whether an into-mesh jet is aimed at the mesh outlet, against the teeth, rather than into the inlet with them, by
#: the ``[gearbox.oil] jet_position`` value (the first the default): the one place the names are compared.
JET_POSITIONS: dict[str, bool] = {"inlet": False, "outlet": True}


def jet_at_outlet(name: str) -> bool:
    """Whether the jet position ``name`` is the outlet (CaseError naming ``gearbox.oil.jet_position`` otherwise)."""
    return registered(JET_POSITIONS, name, "gearbox.oil.jet_position", "unknown jet position")


def jet_impulse_power(jet: OilJet, density: float, pitch_line_speed: float) -> float:
    """Impulse loss (1) of the module docstring [W]: ρ·Q·v_t·(v_t − s·v_j); 0 for an inlet jet faster than the
    pitch line. ``density`` ρ [kg/m³], ``pitch_line_speed`` v_t [m/s]."""
    relative = pitch_line_speed - jet.sense * jet.jet_speed
    return density * jet.flow_rate * pitch_line_speed * max(relative, 0.0)


def jet_validity(jet: OilJet, pitch_line_speed: float) -> str | None:
    """Why (1) does not apply at this pitch-line speed [m/s], or None."""
    if not jet.at_outlet and jet.jet_speed > pitch_line_speed:
        return (f"gearbox: the oil jet ({jet.jet_speed:g} m/s) is faster than the pitch line ({pitch_line_speed:.3g} "
                "m/s): it would drive the gears; the jet's impulse loss is taken as 0 (not modelled)")
    return None
