"""Multi-start search for the stable orbits of the backlash model, on the textbook oscillator."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.backlash.backlash_continuation import follow_branch
from thermogear.dynamics.backlash.backlash_orbits import start_grid, stable_orbits
from thermogear.dynamics.backlash.backlash_periodic import periodic_response
from thermogear.errors import ProblemError

from backlash_textbook import X_STATIC, textbook_problem

ZETA = 0.03  # the damping ratio of the continuation tests: a softening primary resonance with hysteresis


def test_far_from_resonance_every_start_settles_on_the_one_orbit():
    # Ω = 0.5: small excitation, teeth always in contact; the linear response is the only attractor
    problem = textbook_problem(0.5, ZETA)
    census = stable_orbits(problem, starts=16)
    assert len(census.orbits) == 1 and census.orbits[0].basin_share == 1.0
    assert census.unresolved == 0 and census.unbounded == 0 and np.all(census.outcome == 0)
    reference = periodic_response(problem)
    # both are Newton solutions to a scaled residual of 1e-10: equal states to 1e-8 of the static deflection
    found, expected = census.orbits[0].orbit.initial_state, reference.initial_state
    assert found[0] == pytest.approx(expected[0], rel=0, abs=1e-8 * X_STATIC)
    assert found[1] == pytest.approx(expected[1], rel=0, abs=1e-8 * X_STATIC * 1e4)  # ω_n = 1e4 rad/s


def test_inside_the_hysteresis_band_both_branches_are_found():
    # Ω = 0.9 lies in the band where the up sweep rides the low branch and the down sweep the high one: the
    # search finds both (and no other), with basin shares that add up to one
    ratios = np.round(np.arange(0.80, 1.1001, 0.01), 6)
    problems = [textbook_problem(r, ZETA) for r in ratios]
    at = int(np.flatnonzero(ratios == 0.9)[0])
    up, down = follow_branch(problems, "up", ratios), follow_branch(problems, "down", ratios)
    census = stable_orbits(problems[at], starts=36)
    swings = sorted(np.ptp(item.orbit.history.displacement) for item in census.orbits)
    assert len(census.orbits) == 2
    # the branch metrics sample the orbit once per interval, the census four times (extrema are exact in both)
    assert swings[0] == pytest.approx(up["dte_peak_to_peak"][at], rel=1e-9)
    assert swings[1] == pytest.approx(down["dte_peak_to_peak"][at], rel=1e-9)
    assert sum(item.basin_share for item in census.orbits) == pytest.approx(1.0)
    shares = [item.basin_share for item in census.orbits]
    assert shares == sorted(shares, reverse=True)
    assert [item.start_count for item in census.orbits] == [int(np.sum(census.outcome == i)) for i in range(2)]


def test_the_start_grid_spans_both_flanks_and_refuses_bad_counts():
    problem = textbook_problem(0.9, ZETA)
    grid = start_grid(problem, 9)
    reach = 2.0 * (problem.backlash + 2.0 * problem.displacement_scale)
    assert grid.shape == (9, 2)
    assert grid[:, 0].min() == pytest.approx(-reach) and grid[:, 0].max() == pytest.approx(reach)
    assert grid[:, 0].min() < -problem.backlash  # starts beyond the back flank too
    with pytest.raises(ProblemError, match="starts"):
        stable_orbits(problem, starts=0)
    with pytest.raises(ProblemError, match="start_states"):
        stable_orbits(problem, start_states=np.array([[np.nan, 0.0]]))


def test_the_coexistence_note_never_implies_at_most_two_orbits(monkeypatch):
    # the linear start and the start from rest settling on different orbits show that several coexist, never
    # how many: the note says "at least two" and points to the search (it said "two stable orbits coexist")
    from thermogear.dynamics.backlash import nonlinear_response as module

    problem = textbook_problem(0.9, ZETA)
    low, high = sorted((item.orbit for item in stable_orbits(problem, starts=36).orbits),
                       key=lambda orbit: np.ptp(orbit.history.displacement))
    answers = iter((low, high))
    monkeypatch.setattr(module, "periodic_response", lambda *args, **kwargs: next(answers))
    response = module.nonlinear_response(problem)
    assert response.metrics["coexisting_orbits"] and response.metrics["branch"] == "low"
    (note,) = response.warnings
    assert "at least two stable orbits" in note and "--multistart" in note
    assert not note.startswith("two stable orbits coexist")  # the old wording
