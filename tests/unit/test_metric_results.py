"""Typed metrics: the frozen dataclasses give back exactly the metrics dict they were built from.

`thermogear run` reads the typed form; it must not change a key, the key order or a value (JSON written
from either is identical), and must refuse a dict that is not the solver's (a missing or an unknown key).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from backlash_textbook import textbook_problem

from thermogear.dynamics import MeshDynamicsProblem, periodic_steady_state, response_from_orbit
from thermogear.dynamics.backlash.nonlinear_response import nonlinear_response
from thermogear.dynamics.results.metric_results import LinearMetrics, NonlinearMetrics
from thermogear.errors import ProblemError

OMEGA = 2.0 * np.pi * 100.0  # [rad/s], 1 kg: a 100 Hz mesh mode


def _square_wave(frequency_ratio: float, damping_ratio: float) -> MeshDynamicsProblem:
    return MeshDynamicsProblem.square_wave(mass=1.0, mesh_period=1.0 / (frequency_ratio * 100.0), contact_ratio=1.6,
                                           single_stiffness=OMEGA**2, double_stiffness=1.5 * OMEGA**2,
                                           single_damping=2.0 * damping_ratio * OMEGA,
                                           double_damping=3.0 * damping_ratio * OMEGA, force=100.0, face_width=0.02)


def _same_json(first: dict, second: dict) -> bool:
    """Byte-equal JSON, NaN written as NaN: equal keys, order and values (no tolerance: nothing is recomputed)."""
    return json.dumps(first) == json.dumps(second)


@pytest.mark.parametrize("frequency_ratio, damping_ratio", [(0.3, 0.05), (0.9, 0.02), (1.8, 0.01)])
def test_linear_metrics_round_trip_exactly(frequency_ratio, damping_ratio):
    problem = _square_wave(frequency_ratio, damping_ratio)
    metrics = response_from_orbit(problem, periodic_steady_state(problem)).metrics
    typed = LinearMetrics.from_dict(metrics)
    assert _same_json(typed.as_dict(), metrics)
    assert typed.kv == metrics["kv"] and typed.contact_loss.detected == metrics["contact_loss"]["detected"]
    assert typed.floquet_multipliers_abs == tuple(metrics["floquet_multipliers_abs"])
    with pytest.raises(AttributeError):
        typed.kv = 1.0  # frozen
    with pytest.raises(TypeError):
        typed.equilibrium_per_region["single"] = 0.0  # read-only mapping


@pytest.mark.parametrize("ratio", [0.5, 1.0])
def test_nonlinear_metrics_round_trip_exactly(ratio):
    """Below resonance (contact kept) and at resonance (contact lost): NaN-free and lossy orbits alike."""
    metrics = nonlinear_response(textbook_problem(ratio, 0.05), check_coexistence=False).metrics
    typed = NonlinearMetrics.from_dict(metrics)
    assert _same_json(typed.as_dict(), metrics)
    assert typed.contact_loss.fraction == metrics["contact_loss_fraction"]


def test_a_dict_with_a_missing_or_unknown_key_is_refused():
    problem = _square_wave(0.3, 0.05)
    metrics = response_from_orbit(problem, periodic_steady_state(problem)).metrics
    with pytest.raises(ProblemError, match="missing \\['valid'\\]"):
        LinearMetrics.from_dict({key: value for key, value in metrics.items() if key != "valid"})
    with pytest.raises(ProblemError, match="unknown \\['extra'\\]"):
        LinearMetrics.from_dict({**metrics, "extra": 1.0})


def test_typed_metrics_picks_the_kind_and_leaves_the_extra_keys_in_the_dict():
    from thermogear.dynamics.results.metric_results import EXTRA_KEYS, typed_metrics

    problem = _square_wave(0.3, 0.05)
    metrics = response_from_orbit(problem, periodic_steady_state(problem)).metrics
    extended = {**metrics, "damping_ratio": 0.05, "transient_periods": 3}  # as a simulation's transient gives it
    typed = typed_metrics(extended)
    assert type(typed) is LinearMetrics and _same_json(typed.as_dict(), metrics)
    assert {"damping_ratio", "transient_periods"} <= EXTRA_KEYS
    # the views shared with a nonlinear response: every pair in contact, one periodic orbit, no free flight
    assert (typed.mesh, typed.response, typed.branch) == ("linear", "periodic", "unique")
    assert typed.contact_loss_fraction is None and not typed.back_side_contact and not typed.coexisting_orbits
    nonlinear = nonlinear_response(textbook_problem(0.5, 0.05), check_coexistence=False).metrics
    assert type(typed_metrics(nonlinear)) is NonlinearMetrics
    with pytest.raises(ProblemError, match="unknown \\['extra'\\]"):
        typed_metrics({**metrics, "extra": 1.0})
