"""The paper's rig predicted in the luo2019 report (thermogear.luo2020.report.rig_section): one prediction row per
Table 3 temperature, counted in the headline, with the rig's assumptions stated."""

from __future__ import annotations

import pytest

from thermogear import forked
from thermogear.luo2020.rig.prediction import RIG_AMBIENT_C, predicted_runs
from thermogear.luo2020.report.checks import known_gaps, table_counts
from thermogear.luo2020.report.rig_section import (FIXED_K, GAP_SPEEDS_RPM, RISE_SHARE, rig_rows, rig_section,
                                                   rig_verdicts, start_rig_prediction, with_rig_section)

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


@pytest.fixture(scope="module")
def rig():
    background = start_rig_prediction()
    background.result()
    return background


@pytest.fixture(scope="module")
def verdicts(rig):
    return rig_verdicts(rig)


def _failed() -> forked.Background:
    def fail():
        raise RuntimeError("injected")
    return forked.start("rig prediction", fail)


def test_one_prediction_row_per_measured_temperature():
    rows = rig_rows(predicted_runs(chained=False)[0])
    assert len(rows) == 9 and len({row.key for row in rows}) == 9
    for row in rows:
        assert row.kind == "prediction" and row.unit == "°C" and len(row.argument) > 10
        # the argued tolerance: FIXED_K plus RISE_SHARE of the measured rise above the assumed ambient
        # (rounded to 0.1 K, the precision Table 3 prints)
        assert row.check.tolerance == pytest.approx(FIXED_K + RISE_SHARE * (row.paper - RIG_AMBIENT_C), abs=0.05)
        assert "stand-in" in row.note and "1.25 L" in row.note  # the rig's assumptions travel with the row


# the cold-start predictions against Table 3: 400 rpm within (about 1 K), 900 and 1400 rpm outside (9-27 K cooler,
# the documented known gap: the rig's gearbox is not published); a change of the model that moves them fails here
@pytest.mark.parametrize("speed", [400.0, 900.0, 1400.0])
def test_statuses_of_the_runs(verdicts, speed):
    rows = [verdict for verdict in verdicts if f".n{speed:g}_" in verdict.row.key]
    assert len(rows) == 3
    expected = "outside" if speed in GAP_SPEEDS_RPM else "within"
    assert [verdict.status for verdict in rows] == [expected] * 3
    assert all(bool(verdict.row.gap) == (speed in GAP_SPEEDS_RPM) for verdict in rows)


def test_the_rows_count_in_the_headline_and_every_row_outside_is_a_known_gap(verdicts):
    counts = table_counts(verdicts)
    assert counts["prediction"] == {"total": 9, "within": 3, "outside": 6, "not computed": 0}
    assert all(gap.row.gap for gap in known_gaps(verdicts))
    assert len(known_gaps(verdicts)) == 6


def test_value_is_the_predicted_oil_temperature(verdicts):
    cold = predicted_runs(chained=False)[0]
    for verdict, prediction in zip(verdicts, cold):
        assert verdict.value == pytest.approx(prediction.oil_c, abs=1e-12)
        assert verdict.row.paper == prediction.measured_c
        # shown in kelvin (a per cent of a Celsius temperature means nothing)
        assert verdict.deviation is None and f"{prediction.deviation:+.1f} K" in verdict.reason


def test_section_states_assumptions_and_both_starts(rig):
    text = rig_section(rig)
    assert "stand-in" in text and "1.25 L" in text and "not counted" in text
    assert text.count("<tr>") == 10  # header and nine rows
    page = "<h2 id='results'>r</h2><h2 id='paper'>p</h2><h2 id='references'>x</h2>"
    placed = with_rig_section(page, text)
    assert placed.index("id='rig'") < placed.index("id='paper'")
    assert with_rig_section("<h2 id='references'>x</h2>", "S").startswith("S")


def test_a_failed_prediction_leaves_its_rows_not_computed():
    failed = _failed()
    verdicts = rig_verdicts(failed)
    assert len(verdicts) == 9 and all(verdict.status == "not computed" for verdict in verdicts)
    assert all("injected" in verdict.reason for verdict in verdicts)
    assert "injected" in rig_section(failed)
