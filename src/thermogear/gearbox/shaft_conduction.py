"""Heat paths along a gear's shaft: the stretch of shaft between the gear's seat and each of its bearings as a fin.

A gear's body conducts its heat to the shaft at its bore (:meth:`GearboxDescription.gear_body_conductance`); from
there the heat runs along the shaft to the bearing seats (the shaft's node, where the bearings' friction heat is
also born and whence the bearings lead to the housing) and leaves the shaft's surface on the way into the oil mist.
One stretch of shaft of length L, conducting cross-section A_c and perimeter P, whose two ends are held at θ_b and
θ_L above the surrounding fluid, is a fin with prescribed temperatures at both ends (Incropera, DeWitt, Bergman &
Lavine, Fundamentals of Heat and Mass Transfer, 6th ed., Table 3.4 case B):

    q_b = √(h·P·k·A_c)·(cosh(mL)·θ_b − θ_L)/sinh(mL),   m = √(h·P/(k·A_c))                        (1)

into its first end (and the same with b and L exchanged into its second). Written as conductances, (1) is exactly a
triangle of three: between the two ends G_e = √(hPkA_c)/sinh(mL), and from each end to the fluid
G_f = √(hPkA_c)·(cosh(mL) − 1)/sinh(mL) = √(hPkA_c)·tanh(mL/2). Without convection (h → 0) they tend to plain
conduction k·A_c/L (Fourier's law, the same book's Eq. 3.6 for R = L/(kA)) and to h·P·L/2 at each end.

The gear's seat has no heat capacity of its own in the network: it is eliminated exactly by the star–mesh
transform (Kron reduction) of the seat's balance, Σ_j G_sj (T_j − T_s) = 0, which leaves equivalent conductances
G'_ij = G_ij + G_is·G_sj / Σ_k G_sk between the gear, its shaft's node and the oil. Assumptions: the shaft's surface
exchanges heat with the oil mist at the same coefficient as the gear's surfaces (the description's gear–oil
coefficient), the fit between gear and shaft and the seats of the bearings conduct without contact resistance,
and a stretch of several diameters is replaced by the uniform one with the same axial resistance Σ ΔL/(k·A) and
the same lateral area (exact for a uniform stretch).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.errors import CaseError


@dataclass(frozen=True)
class ShaftSpan:
    """A uniform stretch of shaft from the gear's mid-plane to one bearing's: length L [m], conducting
    cross-section A_c [m²] and perimeter P [m] wetted by the oil mist."""

    length: float
    area: float
    perimeter: float

    def __post_init__(self) -> None:
        for key in ("length", "area", "perimeter"):
            value = getattr(self, key)
            if not (math.isfinite(value) and value > 0.0):
                raise CaseError(f"shaft_span.{key}", value, "> 0", "a stretch of shaft between a gear and a bearing")

    @classmethod
    def between(cls, segments, start: float, end: float) -> "ShaftSpan":
        """The uniform stretch equivalent to the shaft's ``segments`` ((length, outer diameter, inner diameter) [m]
        in order from the shaft's first end) between the positions ``start`` and ``end`` [m]: the same axial
        resistance Σ ΔL/A and lateral area Σ π·D·ΔL (module docstring)."""
        low, high = sorted((float(start), float(end)))
        if not high - low > 0.0:
            raise CaseError("shaft_span.length", high - low, "> 0 m", "a gear and a bearing at different positions")
        resistance, lateral, position = 0.0, 0.0, 0.0
        for length, outer, inner in segments:
            overlap = min(high, position + length) - max(low, position)
            if overlap > 0.0:
                resistance += overlap / (0.25 * math.pi * (outer**2 - inner**2))
                lateral += math.pi * outer * overlap
            position += length
        span = high - low
        return cls(span, span / resistance, lateral / span)


def fin_conductances(span: ShaftSpan, conductivity: float, coefficient: float) -> tuple[float, float]:
    """(G_e between the two ends, G_f from each end to the fluid) [W/K] of a stretch of shaft of conductivity k
    [W/(m·K)] wetted at the coefficient h [W/(m²·K)]: Eq. (1) of the module docstring."""
    axial = conductivity * span.area / span.length
    if coefficient <= 0.0:
        return axial, 0.0
    scale = math.sqrt(coefficient * span.perimeter * conductivity * span.area)
    fin = span.length * math.sqrt(coefficient * span.perimeter / (conductivity * span.area))
    if fin < 1e-6:  # the series to first order: kA/L and hPL/2 (avoids 0/0 in the closed forms)
        return axial, 0.5 * coefficient * span.perimeter * span.length
    ends = scale / math.sinh(fin) if fin < 700.0 else 0.0
    return ends, scale * math.tanh(0.5 * fin)


def eliminate_node(conductances: np.ndarray, index: int) -> np.ndarray:
    """Symmetric conductances [W/K] among the other nodes once node ``index`` (no capacity, no source) is
    eliminated by the star–mesh transform G'_ij = G_ij + G_is·G_sj/Σ_k G_sk (module docstring)."""
    matrix = np.array(conductances, dtype=float)
    np.fill_diagonal(matrix, 0.0)
    row = matrix[index]
    total = float(np.sum(row))
    reduced = matrix + (np.outer(row, row) / total if total > 0.0 else 0.0)
    np.fill_diagonal(reduced, 0.0)
    keep = [node for node in range(matrix.shape[0]) if node != index]
    return reduced[np.ix_(keep, keep)]


def gear_shaft_paths(body: float, spans: tuple[ShaftSpan, ...], conductivity: float,
                     coefficient: float) -> tuple[float, float, float]:
    """(gear–shaft node, gear–oil, shaft node–oil) [W/K] of a gear whose body conducts ``body`` [W/K] to its seat,
    from which the ``spans`` of shaft lead to its bearings (module docstring); (body, 0, 0) without spans (the
    seat and the bearings then one node, as the lumped network had it)."""
    if not spans:
        return float(body), 0.0, 0.0
    gear, shaft, fluid, seat = range(4)
    matrix = np.zeros((4, 4))
    matrix[gear, seat] = matrix[seat, gear] = body
    for span in spans:
        ends, to_fluid = fin_conductances(span, conductivity, coefficient)
        matrix[seat, shaft] += ends
        matrix[shaft, seat] += ends
        for end in (seat, shaft):
            matrix[end, fluid] += to_fluid
            matrix[fluid, end] += to_fluid
    reduced = eliminate_node(matrix, seat)
    return float(reduced[gear, shaft]), float(reduced[gear, fluid]), float(reduced[shaft, fluid])


def drivetrain_shaft_spans(section) -> tuple[tuple[ShaftSpan, ...], tuple[ShaftSpan, ...]]:
    """(pinion's, wheel's) stretches of shaft from the gear's position to each bearing with loss data on the same
    shaft of the ``[drivetrain]`` ``section`` (the gearbox's bearings; None: no section), each the uniform
    equivalent of the segments between (:meth:`ShaftSpan.between`). A gear whose shaft carries no such bearing, or
    one at the gear's own position, gets none: its seat and bearings stay one node."""
    if section is None:
        return (), ()
    shafts = {shaft.name: shaft for shaft in section.shafts}
    found = []
    for mount in (section.pinion, section.wheel):
        shaft = shafts[mount.shaft]
        segments = [(segment.length_mm * 1e-3, segment.outer_diameter_mm * 1e-3, segment.inner_diameter_mm * 1e-3)
                    for segment in shaft.segments]
        positions = [bearing.position_mm for bearing in section.bearings
                     if bearing.shaft == mount.shaft and bearing.loss is not None]
        if not positions or any(abs(position - mount.position_mm) < 1e-6 for position in positions):
            found.append(())
            continue
        found.append(tuple(ShaftSpan.between(segments, mount.position_mm * 1e-3, position * 1e-3)
                           for position in positions))
    return found[0], found[1]
