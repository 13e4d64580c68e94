"""Operating radial clearance of a rolling bearing whose rings run at different temperatures.

Each ring expands freely with its own temperature. The diametral (radial internal) clearance is
P_d = d_o − d_i − 2·D_w (outer raceway diameter d_o, inner raceway diameter d_i, rolling-element diameter D_w), so
with the clearance small against the diameters (d_o ≈ d_i + 2·D_w) the change from the mounting temperature T_0 is

    ΔP_d = λ·[d_o·(T_o − T_0) − (d_i + 2·D_w)·(T_i − T_0)] = −λ·E·(T_i − T_o)

with the rolling elements at the inner ring's temperature (inner ring and rolling elements "considered as one unit")
and E = d_o the outer-ring raceway (bore) diameter: the relation Δδ = α·Δt·E of IKO's needle roller bearing
catalogue (IKO Nippon Thompson, "Needle Roller Bearings", p. A39, Eq. (29); α ≈ 12.5e-6 /K for bearing steel,
Δt = 5–10 K in normal operation, 15–20 K at high speeds). Equal ring temperatures leave the clearance unchanged,
whatever they are; a hotter inner ring reduces it.

The inner ring sits on the shaft (interference fit) and takes the shaft's temperature, the outer ring the housing
seat's. Not included (stated): the change of the fits themselves with the shaft's and the housing's own expansion
(a light-alloy housing loosens the outer ring's fit, SKF "Other influences on clearance/preload"), elastic
deformation under load, and centrifugal growth of the inner ring.

The drivetrain's ``radial_clearance`` is the play ± c of the shaft about the bearing centre per direction: the
radial internal clearance is the total movement 2c, so c changes by ½·ΔP_d. A clearance taken up entirely (c ≤ 0)
is a bearing without play (in the drivetrain: c = 0, a preload is not modelled).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.errors import CaseError

__all__ = ["BEARING_STEEL_EXPANSION_PER_K", "OperatingClearance", "estimated_outer_raceway_diameter",
           "operating_clearance", "radial_clearance_change"]

#: Linear expansion coefficient of bearing steel [1/K] (IKO catalogue p. A39: ≈ 12.5e-6 /°C).
BEARING_STEEL_EXPANSION_PER_K = 12.5e-6


def estimated_outer_raceway_diameter(bore: float, outside: float) -> float:
    """E ≈ (d + 3D)/4 [same unit as d, D]: the pitch diameter (d + D)/2 plus a rolling element of a quarter of
    D − d (rolling elements filling half the radial section; an estimate where the catalogue's E is not given;
    NJ 406: 75 mm)."""
    return 0.25 * (bore + 3.0 * outside)


def radial_clearance_change(outer_raceway_diameter: float, inner_c: float, outer_c: float,
                            expansion_per_k: float = BEARING_STEEL_EXPANSION_PER_K) -> float:
    """Change of the radial internal clearance ΔP_d = −λ·E·(T_i − T_o) [m] (module docstring) for an outer raceway
    diameter E [m], inner ring (with rolling elements) and outer ring temperatures [°C], λ [1/K]."""
    if not (math.isfinite(outer_raceway_diameter) and outer_raceway_diameter > 0.0):
        raise CaseError("outer_raceway_diameter", outer_raceway_diameter, "> 0 m", "a bearing's raceway diameter")
    if not 0.0 <= expansion_per_k <= 5e-5:
        raise CaseError("expansion_per_k", expansion_per_k, "[0, 5e-5] 1/K", "λ of a bearing steel")
    return -expansion_per_k * outer_raceway_diameter * (float(inner_c) - float(outer_c))


@dataclass(frozen=True)
class OperatingClearance:
    """The play ± c [m] of one bearing: as mounted, at its ring temperatures [°C], and whether the heat took it up
    entirely (``taken_up``: the operating value is then 0)."""

    mounted: float
    operating: float
    inner_c: float
    outer_c: float
    taken_up: bool


def operating_clearance(mounted: float, outer_raceway_diameter: float, inner_c: float, outer_c: float,
                        expansion_per_k: float = BEARING_STEEL_EXPANSION_PER_K) -> OperatingClearance:
    """The play ± c [m] at the ring temperatures: c = c_0 + ½·ΔP_d, at least 0 (module docstring); ``mounted``
    c_0 [m] holds with both rings at the same temperature."""
    if not (math.isfinite(mounted) and mounted >= 0.0):
        raise CaseError("radial_clearance", mounted, ">= 0 m", "a bearing's play")
    value = mounted + 0.5 * radial_clearance_change(outer_raceway_diameter, inner_c, outer_c, expansion_per_k)
    return OperatingClearance(mounted, max(value, 0.0), float(inner_c), float(outer_c), value <= 0.0 < mounted)
