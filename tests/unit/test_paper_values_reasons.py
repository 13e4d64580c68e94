"""Every row of the paper table gets a value or a reason, never an unexplained failure.

The rows are read with named exceptions only (``ValueUnavailable`` for a stage that does not apply, a model's
``ThermogearError``): on a case where most stages do not apply (a pair under the thermo-elastic model, one model,
no transients, no FE) each missing row must carry a reason that says which stage or which model it needs.
"""

from __future__ import annotations

import warnings

import pytest

from thermogear import load_case
from thermogear.evaluation import evaluate_case
from thermogear.luo2020.report.table import PAPER_ROWS
from thermogear.luo2020.report.values import paper_values


@pytest.fixture(scope="module")
def values():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        evaluation = evaluate_case(load_case("fzg_type_c"), models=("elastic",), transient=False)
    return paper_values(evaluation)


def test_every_row_has_a_value_or_a_reason(values):
    for item in PAPER_ROWS:
        value = values.get(item.key)
        if isinstance(value, tuple):
            assert value[0] is None and isinstance(value[1], str) and value[1], item.key


def test_the_reasons_name_what_is_missing(values):
    assert "thermal.model = 'luo2020'" in values["fig4.drop_at_C"][1]
    assert "has no thermal" in values["fig9.two_levels"][1]
    assert "has no elastic, thermal" in values["fig9.period_equals_mesh_period"][1]
    assert "parameter set of the paper" in values["fig15.fe_kt_below_ke"][1]


def test_a_programming_error_is_not_swallowed(monkeypatch):
    """Only the named exceptions become reasons: a TypeError inside a row's reading propagates."""
    from thermogear.luo2020.report import values as module

    class Broken:
        case = load_case("fzg_type_c")
        problems: dict = {}
        temperature_field = object()  # no pinion_flank_c: an AttributeError, a programming error

        def problem(self, *stages):
            return ""

    with pytest.raises(AttributeError):
        module.paper_values(Broken())
