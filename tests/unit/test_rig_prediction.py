"""The paper's rig runs (Luo & Li 2020 Table 3) predicted by the gearbox thermal model: predictions beside the
measurements, labelled as such, with no parameter taken from the measurements."""

from __future__ import annotations

import pytest

from thermogear.luo2020.rig.prediction import RIG_ASSUMPTIONS, predict_table3, table3_markdown

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


@pytest.fixture(scope="module")
def cold():
    return predict_table3(chained=False)


@pytest.fixture(scope="module")
def chained():
    return predict_table3(chained=True)


# Table 3 of Luo & Li (2020): (rpm, minute, temperature °C) as printed
@pytest.mark.parametrize("speed, minute, measured", [
    (400, 3, 20.2), (400, 5, 21.6), (400, 10, 24.8), (900, 3, 32.3), (900, 5, 35.6), (900, 10, 42.7),
    (1400, 3, 52.1), (1400, 5, 53.2), (1400, 10, 59.5)])
def test_every_measured_row_has_its_prediction(cold, speed, minute, measured):
    row = next(row for row in cold if row.speed_rpm == speed and row.minute == minute)
    assert row.measured_c == measured
    assert row.start == "cold"
    assert row.deviation == pytest.approx(row.oil_c - measured, abs=1e-12)


def test_predictions_heat_in_time_and_with_speed(cold):
    for speed in (400.0, 900.0, 1400.0):
        oil = [row.oil_c for row in cold if row.speed_rpm == speed]
        assert oil == sorted(oil) and oil[0] > 20.0  # from the 20 °C ambient, heating
    at_ten = [row.oil_c for row in cold if row.minute == 10]
    assert at_ten == sorted(at_ten)  # more speed, more loss, hotter
    assert all(row.pinion_c > row.oil_c > row.housing_c for row in cold)


def test_chained_runs_start_where_the_previous_ended(cold, chained):
    # the first run has no predecessor: identical; the later ones start warmer than from cold
    for first, second in zip(cold, chained):
        if first.speed_rpm == 400.0:
            assert second.oil_c == pytest.approx(first.oil_c, abs=1e-9)
        else:
            assert second.oil_c > first.oil_c


def test_the_report_says_predictions_and_states_the_assumptions(cold):
    text = table3_markdown(cold)
    assert "not fitted to the measurements" in text and "Luo, W. Li" in text
    assert any("stand-in" in line for line in RIG_ASSUMPTIONS) and any("1.25 L" in line for line in RIG_ASSUMPTIONS)
