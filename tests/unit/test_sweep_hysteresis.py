"""Hysteresis bands of a branch study, on constructed branch pairs (exact numbers, so exact bands)."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.sweep.hysteresis import difference_bands, hysteresis_bands


def _branches(speeds, up, down):
    import xarray as xr

    values = np.stack([up, down])[:, None, :]  # (direction, model, speed)
    return xr.Dataset({"dte_peak_to_peak": (("direction", "model", "speed_rpm"), values)},
                      coords={"direction": ["up", "down"], "model": ["elastic"], "speed_rpm": speeds})


def test_separate_bands_are_not_merged():
    # the case: the branches differ over 6000–6100 and 7300–10800 rpm and coincide over 6200–7200 rpm;
    # one band [6000, 10800] would claim two stable responses where there is one
    speeds = np.arange(5000.0, 12001.0, 100.0)
    up = 30e-6 + 1e-9 * (speeds - 5000.0)
    down = up.copy()
    differ = ((speeds >= 6000) & (speeds <= 6100)) | ((speeds >= 7300) & (speeds <= 10800))
    down[differ] *= 3.0
    entry = hysteresis_bands(_branches(speeds, up, down))["elastic"]
    assert entry["differ"]
    assert entry["bands_rpm"] == [[6000.0, 6100.0], [7300.0, 10800.0]]
    assert entry["band_rpm"] == [7300.0, 10800.0]  # the widest
    # each band's ends are jumps of the down branch: up at 10850 (met first, from above), down at 7250, ...
    down_jumps = [(item["speed_rpm"], item["amplitude"]) for item in entry["down_sweep_jumps"]]
    assert down_jumps == [(10850.0, "rises"), (7250.0, "falls"), (6150.0, "rises"), (5950.0, "falls")]
    assert entry["up_sweep_jumps"] == []


def test_coinciding_branches_have_no_band():
    speeds = np.linspace(1000.0, 2000.0, 11)
    values = np.linspace(1e-6, 2e-6, 11)
    entry = hysteresis_bands(_branches(speeds, values, values * (1 + 0.019)))["elastic"]  # within the 2 % tolerance
    assert entry == {"differ": False, "bands_rpm": [], "up_sweep_jumps": [], "down_sweep_jumps": [],
                     "up_sweep_steep_changes": [], "down_sweep_steep_changes": []}


def test_a_steep_slope_where_the_branches_coincide_is_no_jump():
    # issue 36: a coarse grid over a steep flank (both branches alike) was listed as jumps at 750 and 1250 rpm
    # while the branches coincide; a jump is where the two branches differ, the rest is a steep change
    speeds = np.array([500.0, 1000.0, 1500.0, 2000.0])
    values = np.array([1e-6, 5e-6, 1e-6, 1e-6])
    entry = hysteresis_bands(_branches(speeds, values, values.copy()))["elastic"]
    assert not entry["differ"] and entry["up_sweep_jumps"] == [] and entry["down_sweep_jumps"] == []
    assert [item["speed_rpm"] for item in entry["up_sweep_steep_changes"]] == [750.0, 1250.0]
    assert [item["speed_rpm"] for item in entry["down_sweep_steep_changes"]] == [1250.0, 750.0]


@pytest.mark.parametrize("up, down, bands", [
    ([1, 1, 1, 1], [2, 2, 2, 2], [[0.0, 3.0]]),  # the whole range
    ([1, 1, 1, 1], [2, 1, 1, 2], [[0.0, 0.0], [3.0, 3.0]]),  # one speed at each end
    ([1, 1, np.nan, 1], [2, 2, 2, 2], [[0.0, 1.0], [3.0, 3.0]]),  # a speed without a value ends a band
])
def test_difference_bands(up, down, bands):
    assert difference_bands([0.0, 1.0, 2.0, 3.0], up, down) == bands
