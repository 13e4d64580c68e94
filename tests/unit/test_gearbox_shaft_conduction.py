"""The stretches of shaft between a gear and its bearings as fins (thermogear.gearbox.shaft_conduction): the closed
form against a finite-difference solution of the fin equation, its limits, the exact elimination of the gear's
seat, the uniform equivalent of a stepped stretch, and the FZG test gearbox's paths by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.errors import CaseError
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
from thermogear.gearbox.shaft_conduction import (ShaftSpan, eliminate_node, fin_conductances, gear_shaft_paths)

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")
STEEL = 46.0  # [W/(m K)]
SHAFT_30 = ShaftSpan(0.05, math.pi * 0.03**2 / 4.0, math.pi * 0.03)  # Ø30 mm, 50 mm


def _fin_by_finite_differences(span: ShaftSpan, conductivity: float, coefficient: float, base: float, tip: float,
                               points: int = 4001) -> tuple[float, float]:
    """Heat [W] into each end of a fin held at θ = base and tip above the fluid: k A θ'' = h P θ by second-order
    differences, the end fluxes by a second-order one-sided derivative — an independent check of the closed form."""
    step = span.length / (points - 1)
    size = points - 2
    factor = coefficient * span.perimeter * step**2 / (conductivity * span.area)
    matrix = np.diag(np.full(size, -(2.0 + factor))) + np.diag(np.ones(size - 1), 1) + np.diag(np.ones(size - 1), -1)
    right = np.zeros(size)
    right[0], right[-1] = -base, -tip
    theta = np.concatenate([[base], np.linalg.solve(matrix, right), [tip]])
    flux = conductivity * span.area / step
    into_base = -flux * (-3.0 * theta[0] + 4.0 * theta[1] - theta[2]) / 2.0
    into_tip = -flux * (-3.0 * theta[-1] + 4.0 * theta[-2] - theta[-3]) / 2.0
    return into_base, into_tip


@pytest.mark.parametrize("coefficient", [20.0, 200.0, 2000.0])
def test_fin_conductances_reproduce_the_fin_equation(coefficient):
    ends, to_fluid = fin_conductances(SHAFT_30, STEEL, coefficient)
    base, tip = 30.0, 12.0
    into_base, into_tip = _fin_by_finite_differences(SHAFT_30, STEEL, coefficient, base, tip)
    # heat into each end: its own path to the fluid plus the path to the other end (the triangle of conductances)
    assert to_fluid * base + ends * (base - tip) == pytest.approx(into_base, rel=1e-5)
    assert to_fluid * tip + ends * (tip - base) == pytest.approx(into_tip, rel=1e-5)


def test_fin_conductances_reduce_to_conduction_and_convection():
    axial = STEEL * SHAFT_30.area / SHAFT_30.length
    assert fin_conductances(SHAFT_30, STEEL, 0.0) == (pytest.approx(axial, rel=1e-15), 0.0)
    # weak convection: kA/L along, hPL/2 to the fluid at each end (first order in h)
    ends, to_fluid = fin_conductances(SHAFT_30, STEEL, 1e-6)
    assert ends == pytest.approx(axial, rel=1e-8)
    assert to_fluid == pytest.approx(0.5e-6 * SHAFT_30.perimeter * SHAFT_30.length, rel=1e-8)
    # a very long fin: the ends decouple and each sheds √(hPkA) (the infinite fin, Table 3.4 case D)
    long = ShaftSpan(50.0, SHAFT_30.area, SHAFT_30.perimeter)
    ends, to_fluid = fin_conductances(long, STEEL, 200.0)
    assert ends < 1e-12
    assert to_fluid == pytest.approx(math.sqrt(200.0 * SHAFT_30.perimeter * STEEL * SHAFT_30.area), rel=1e-12)


def test_eliminating_the_seat_keeps_every_flow():
    generator = np.random.default_rng(7)
    upper = np.triu(generator.uniform(0.1, 5.0, (4, 4)), 1)
    matrix = upper + upper.T
    temperatures = np.array([80.0, 55.0, 40.0])  # the kept nodes; the eliminated one (index 3) floats
    seat = float(matrix[3, :3] @ temperatures / matrix[3, :3].sum())
    full = np.append(temperatures, seat)
    reduced = eliminate_node(matrix, 3)
    assert np.allclose(reduced, reduced.T) and np.all(reduced >= 0.0)
    for node in range(3):
        direct = float(matrix[node] @ (full - full[node]))
        assert float(reduced[node] @ (temperatures - temperatures[node])) == pytest.approx(direct, rel=1e-12)


def test_gear_shaft_paths_without_spans_are_the_body_alone():
    assert gear_shaft_paths(5.5, (), STEEL, 200.0) == (5.5, 0.0, 0.0)


def test_a_stepped_stretch_keeps_its_axial_resistance_and_lateral_area():
    segments = [(0.03, 0.04, 0.0), (0.05, 0.03, 0.01)]  # (length, outer, inner) [m]
    span = ShaftSpan.between(segments, 0.07, 0.01)
    resistance = 0.02 / (math.pi * 0.04**2 / 4.0) + 0.04 / (math.pi * (0.03**2 - 0.01**2) / 4.0)
    assert span.length == pytest.approx(0.06, rel=1e-14)
    assert span.length / span.area == pytest.approx(resistance, rel=1e-14)
    assert span.perimeter * span.length == pytest.approx(math.pi * (0.04 * 0.02 + 0.03 * 0.04), rel=1e-14)
    uniform = ShaftSpan.between([(0.1, 0.03, 0.0)], 0.05, 0.0)
    assert (uniform.area, uniform.perimeter) == (pytest.approx(SHAFT_30.area), pytest.approx(SHAFT_30.perimeter))
    with pytest.raises(CaseError, match="shaft_span.length"):
        ShaftSpan.between(segments, 0.02, 0.02)


def test_fzg_test_gearbox_paths_by_hand():
    # the set's drivetrain: each gear at 50 mm on a Ø30 mm, 100 mm shaft with an NJ 406 at 0 and at 100 mm
    description = illustrative_fzg_gearbox()
    assert len(description.pinion_shaft_spans) == len(description.wheel_shaft_spans) == 2
    for span in description.pinion_shaft_spans + description.wheel_shaft_spans:
        assert (span.length, span.area) == (pytest.approx(0.05), pytest.approx(SHAFT_30.area))
    # by hand, h 200 W/(m² K): √(hPkA) = 0.7829 W/K, mL = 1.2039 → G_e = 0.5163, G_f = 0.4215 W/K per stretch;
    # the seat's sum with the pinion's body 5.527: 5.527 + 2(0.5163 + 0.4215) = 7.402 W/K
    scale = math.sqrt(200.0 * math.pi * 0.03 * STEEL * SHAFT_30.area)
    fin = 0.05 * math.sqrt(200.0 * math.pi * 0.03 / (STEEL * SHAFT_30.area))
    assert (scale, fin) == (pytest.approx(0.7829, abs=1e-4), pytest.approx(1.2039, abs=1e-4))
    body = description.gear_body_conductance(False)
    seat = body + 2.0 * (0.5163 + 0.4215)
    gear_shaft, gear_oil, shaft_oil = description.shaft_paths(False)
    assert gear_shaft == pytest.approx(body * 2.0 * 0.5163 / seat, rel=2e-4)  # 0.771 W/K (5.53 without the shaft)
    assert gear_oil == pytest.approx(body * 2.0 * 0.4215 / seat, rel=2e-4)
    assert shaft_oil == pytest.approx(2.0 * 0.4215 + 2.0 * 0.5163 * 2.0 * 0.4215 / seat, rel=2e-4)


def _section(bearing_positions, loss=True, pinion_position=50.0):
    from types import SimpleNamespace

    shaft = SimpleNamespace(name="a", segments=[SimpleNamespace(length_mm=100.0, outer_diameter_mm=30.0,
                                                                inner_diameter_mm=0.0)])
    other = SimpleNamespace(name="b", segments=shaft.segments)
    bearings = [SimpleNamespace(shaft="a", position_mm=position, loss=object() if loss else None)
                for position in bearing_positions] + [SimpleNamespace(shaft="b", position_mm=0.0, loss=object())]
    return SimpleNamespace(shafts=[shaft, other], bearings=bearings,
                           pinion=SimpleNamespace(shaft="a", position_mm=pinion_position),
                           wheel=SimpleNamespace(shaft="b", position_mm=100.0))


def test_drivetrain_spans_come_from_the_gearbox_bearings_on_the_gears_own_shaft():
    from thermogear.gearbox.shaft_conduction import drivetrain_shaft_spans

    assert drivetrain_shaft_spans(None) == ((), ())
    pinion, wheel = drivetrain_shaft_spans(_section([0.0, 100.0]))
    assert [span.length for span in pinion] == [pytest.approx(0.05), pytest.approx(0.05)]
    assert [span.length for span in wheel] == [pytest.approx(0.1)]  # the wheel at 100 mm, its bearing at 0
    # bearings without loss data are not the gearbox's: no spans (the lumped seat), nor a bearing at the gear itself
    assert drivetrain_shaft_spans(_section([0.0, 100.0], loss=False))[0] == ()
    assert drivetrain_shaft_spans(_section([50.0, 100.0]))[0] == ()
