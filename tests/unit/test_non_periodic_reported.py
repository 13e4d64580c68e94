"""A non-periodic response is never reported as valid (issue 25): the nonlinear response says valid = False,
``run --json`` gives status "non-periodic" and null where no number exists (it raised "non-finite number nan in
a JSON result"), and the table says "not found" (it said "steady orbit found: yes" beside NaN multipliers)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from thermogear.cli.run import _print_table, model_json
from thermogear.dynamics.backlash.nonlinear_response import nonlinear_response

from backlash_textbook import textbook_problem


@pytest.fixture(scope="module")
def response():
    return non_periodic_response()


def non_periodic_response():
    # the textbook backlash oscillator that test_backlash_solver shows to have no repeating orbit
    problem = textbook_problem(0.6, zeta=0.02, eps=0.1, deviation=3.0, backlash=2.0, n=16)
    return nonlinear_response(problem, label="elastic", check_coexistence=False)


def test_non_periodic_response_is_not_valid_and_its_json_carries_null_and_a_status(response):
    assert response.metrics["response"] == "non-periodic"
    assert not response.valid
    data = model_json(response)
    assert data["status"] == "non-periodic" and data["valid"] is False
    assert data["floquet_multipliers_abs"][0] is None  # NaN multipliers: no orbit, no multiplier
    text = json.dumps(data, allow_nan=False)  # raises on any NaN left
    assert "NaN" not in text


def test_the_table_says_not_found_for_a_non_periodic_response(response):
    from rich.console import Console

    from thermogear.dynamics.results.metric_results import typed_metrics
    from thermogear.orchestrator import PairResult

    console = Console(record=True, width=140, color_system=None)
    pair = PairResult("elastic", response, typed_metrics(response.metrics), None, np.array([1.0, 2.0]))
    _print_table("textbook", {"elastic": pair}, console)
    text = console.export_text()
    assert "nan" not in text.lower().replace("not found", "")
    row = next(line for line in text.splitlines() if "steady orbit found" in line)
    assert "not found" in row and "yes" not in row
    row = next(line for line in text.splitlines() if "Floquet" in line)
    assert "not found" in row
    assert np.isnan(response.orbit.multipliers).all()


def test_the_result_files_of_a_non_periodic_response_carry_null_not_an_error(response):
    # summary.json and the results file of `run --out` take metrics_json(): it raised on the NaN multipliers
    metrics = response.metrics_json()
    assert metrics["floquet_multipliers_abs"][0] is None and metrics["valid"] is False
    json.dumps(metrics, allow_nan=False)
    assert "non-periodic" in response.to_xarray().attrs["metrics"]
