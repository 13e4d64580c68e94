"""The lumped thermal network: a five-node linear example (hand-checked steady state and time constants),
energy balance and identity, limits, runaway and the warm-up tending to the steady state."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.errors import ProblemError
from thermogear.gearbox.network import (NoSteadyStateError, ThermalNetwork, integrate_transient,
                                        solve_steady_state)

# five nodes (pinion, wheel, shafts, oil, housing): masses 0.6/1.2/4 kg steel (465 J/(kg K)), 1.09 kg oil
# (2000 J/(kg K)), 25 kg housing (500 J/(kg K)); conductances [W/K]; losses 90/90/40/10/0 W; ambient 20 °C
CAPACITIES = np.array([0.6 * 465, 1.2 * 465, 4 * 465, 1.09 * 2000, 25 * 500.0])
LINKS = [(0, 3, 2.3), (1, 3, 4.6), (0, 2, 3.0), (1, 2, 3.0), (2, 3, 4.0), (2, 4, 8.0), (3, 4, 15.0)]
POWER = np.array([90.0, 90.0, 40.0, 10.0, 0.0])


def conductance_matrix(links=LINKS, size=5) -> np.ndarray:
    matrix = np.zeros((size, size))
    for first, second, value in links:
        matrix[first, second] = matrix[second, first] = value
    return matrix


def network(capacities=CAPACITIES, links=LINKS, boundary=(0, 0, 0, 0, 7.2), power=POWER) -> ThermalNetwork:
    matrix, to_ambient = conductance_matrix(links, len(capacities)), np.array(boundary, dtype=float)
    return ThermalNetwork(np.array(capacities, float), lambda t: (matrix, to_ambient),
                          lambda t, time: np.array(power, float), lambda time: 20.0)


def test_linear_example_steady_state_and_time_constants():
    # independent values: housing = 20 + 230/7.2 = 51.944 °C exactly; the rest by hand elimination (0.05 K
    # rounding); τ from the eigenvalues of C⁻¹K (rounded to 1 s)
    steady = solve_steady_state(network(), np.full(5, 20.0))
    assert steady.temperatures == pytest.approx([79.7, 74.0, 64.4, 60.6, 51.9], abs=0.05)
    assert steady.temperatures[4] == pytest.approx(20.0 + 230.0 / 7.2, rel=1e-12)
    assert steady.time_constants == pytest.approx([46, 62, 82, 167, 2482], abs=0.5)


def test_energy_balance_at_steady_state():
    # the brief's bound: heat out equals the losses to 1e-9 relative
    steady = solve_steady_state(network(), np.full(5, 20.0))
    assert steady.energy_residual < 1e-9
    assert steady.heat_out == pytest.approx(230.0, rel=1e-9)


@pytest.mark.parametrize("method", ["Radau", "BDF"])
def test_warm_up_ends_at_the_steady_state_and_keeps_the_energy_identity(method):
    # 20 housing time constants: the slowest mode has decayed by e^-20 (2e-9 of 32 K); rtol 1e-8
    times = np.linspace(0.0, 20 * 2482.0, 41)
    transient = integrate_transient(network(), np.full(5, 20.0), times, method=method, rtol=1e-8, atol=1e-9)
    steady = solve_steady_state(network(), np.full(5, 20.0))
    assert transient.temperatures[:, -1] == pytest.approx(steady.temperatures, abs=1e-3)
    # ∫P dt = ΔΣCT + ∫Q_out dt: a linear invariant of the augmented system, kept to rounding by Radau and BDF;
    # it checks the assembly (symmetric exchange, boundary flux), the warm-up's end checks the accuracy
    assert transient.energy_residual < 1e-9


def test_radau_and_bdf_agree():
    times = np.array([0.0, 60.0, 300.0, 600.0, 1800.0])
    radau = integrate_transient(network(), np.full(5, 20.0), times, "Radau")
    bdf = integrate_transient(network(), np.full(5, 20.0), times, "BDF")
    assert radau.temperatures == pytest.approx(bdf.temperatures, abs=0.01)


def test_time_constants_scale_with_the_capacities():
    # doubling every capacity doubles every τ (C⁻¹K scales by 1/2): exact up to eigenvalue rounding
    base = solve_steady_state(network(), np.full(5, 20.0)).time_constants
    doubled = solve_steady_state(network(capacities=2 * CAPACITIES), np.full(5, 20.0)).time_constants
    assert doubled == pytest.approx(2.0 * base, rel=1e-10)


def test_infinite_internal_conductances_give_one_temperature():
    # every pair joined by 1e6 W/K: the node differences are of order P/G ≤ 90/1e6 ≈ 1e-4 K (a larger G only
    # worsens the conditioning), so one temperature 20 + ΣP/g to 1e-3 K
    links = [(i, j, 1e6) for i in range(5) for j in range(i + 1, 5)]
    steady = solve_steady_state(network(links=links), np.full(5, 20.0))
    assert steady.temperatures == pytest.approx(np.full(5, 20.0 + 230.0 / 7.2), abs=1e-3)
    assert np.ptp(steady.temperatures) < 1e-3


def test_adiabatic_node_heats_linearly_and_has_no_steady_state():
    # the pinion cut from every other node: T = T0 + P t / C exactly, and no steady state exists
    links = [link for link in LINKS if 0 not in link[:2]]
    times = np.linspace(0.0, 600.0, 7)
    transient = integrate_transient(network(links=links), np.full(5, 20.0), times)
    assert transient.temperatures[0] == pytest.approx(20.0 + 90.0 * times / CAPACITIES[0], rel=1e-7)
    with pytest.raises(NoSteadyStateError, match="no conductive path"):
        solve_steady_state(network(links=links), np.full(5, 20.0))


def runaway_network(gain: float) -> ThermalNetwork:
    # one node, G = 1 W/K to 0 °C, P = P0·exp(k·T): a steady state exists iff P0·k·e <= G (tangency); the
    # exponent is capped at 50 (1000 °C) only to keep the solver's trial points finite
    return ThermalNetwork(np.array([100.0]), lambda t: (np.zeros((1, 1)), np.array([1.0])),
                          lambda t, time: np.array([gain * np.exp(min(0.05 * t[0], 50.0))]), lambda time: 0.0)


def test_runaway_is_reported():
    # critical P0 = G/(k e) = 7.36 W: at 0.9× a stable steady state, at 1.2× none
    critical = 1.0 / (0.05 * np.e)
    steady = solve_steady_state(runaway_network(0.9 * critical), np.array([0.0]))
    assert steady.temperatures[0] == pytest.approx(steady.sources[0], rel=1e-9)
    with pytest.raises(NoSteadyStateError, match="runaway"):
        solve_steady_state(runaway_network(1.2 * critical), np.array([0.0]))


def test_bad_network_inputs():
    with pytest.raises(ProblemError, match="capacities"):
        network(capacities=[1.0, 0.0, 1.0, 1.0, 1.0])
    asymmetric = ThermalNetwork(np.ones(2), lambda t: (np.array([[0.0, 1.0], [2.0, 0.0]]), np.ones(2)),
                                lambda t, time: np.zeros(2), lambda time: 0.0)
    with pytest.raises(ProblemError, match="symmetric"):
        solve_steady_state(asymmetric, np.zeros(2))
