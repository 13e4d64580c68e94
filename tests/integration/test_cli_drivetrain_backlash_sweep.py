"""`thermogear sweep` on a drivetrain case with the backlash mesh (issue 27): the orbit followed up and down in
speed through the mesh-coupled resonance, the branches stored, the jumps and the largest Kv per direction in the
summary, and the figure."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest

import inprocess_cli

DATA = Path(__file__).resolve().parents[1] / "data"


def _cli(*args: str) -> subprocess.CompletedProcess:
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=1):
        return inprocess_cli.run(*args)


def _backlash_case(tmp_path: Path) -> Path:
    # the worked two-shaft case with its default backlash mesh; a coarse mesh grid and a 10 kHz cut-off keep it fast
    text = (DATA / "two_shaft_drivetrain.toml").read_text(encoding="utf-8")
    text = text.replace('mesh = "linear"', 'mesh = "nonlinear"').replace(
        "[drivetrain]\n", "[drivetrain]\nsweep_points_per_period = 32\nresponse_cutoff_hz = 10000.0\n", 1)
    case = tmp_path / "backlash.toml"
    case.write_text(text, encoding="utf-8")
    return case


@pytest.mark.slow
def test_the_backlash_sweep_follows_both_branches_and_reports_the_jump(tmp_path):
    import numpy as np
    import xarray as xr

    out, plot = tmp_path / "branches.zarr", tmp_path / "branches.png"
    # through the wheel shaft's mesh-coupled lateral mode (4.19 kHz: 1× mesh at 9317 rpm), where the teeth separate
    result = _cli("sweep", str(_backlash_case(tmp_path)), "--vary", "speed_rpm=8000,8600,9000,9600,10200",
                  "--model", "elastic", "--out", str(out), "--plot", str(plot), "--json")
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["mesh"] == "nonlinear" and summary["directions"] == ["up", "down"]
    data = xr.open_zarr(out)
    assert data.attrs["mesh"].startswith("nonlinear") and data.attrs["directions"] == "up, down"
    assert data["kv"].dims == ("model", "direction", "speed_rpm") and data["kv"].shape == (1, 2, 5)
    assert data["bearing_harmonic_amplitude_n"].shape == (1, 2, 5, 4, 3)
    swing = data["dte_peak_to_peak_um"].sel(model="elastic")
    # the softening resonance: below it the down sweep stays on the large-amplitude branch with contact loss, the
    # up sweep on the small one — they differ by far more than the 2 % the summary counts as a difference
    up, down = float(swing.sel(direction="up", speed_rpm=8600.0)), float(swing.sel(direction="down",
                                                                                     speed_rpm=8600.0))
    assert down > 1.5 * up, (up, down)
    assert float(data["contact_loss_fraction"].sel(model="elastic", direction="down", speed_rpm=8600.0)) > 0.0
    band = summary["hysteresis"]["elastic"]
    assert band["differ"] and any(low <= 8600.0 <= high for low, high in band["bands_rpm"])
    assert band["up_sweep_jumps"] and band["down_sweep_jumps"]
    for key in ("elastic/up", "elastic/down"):
        largest = summary["kv_max"][key]
        assert largest["kv"] > 1.0 and 8000.0 <= largest["speed_rpm"] <= 10200.0
        valid = data["valid"].sel(model="elastic", direction=key.split("/")[1]).values
        assert summary["valid_points"][key] == int(valid.sum()) >= 3
    # far from the resonance the orbit is unique: both directions agree
    assert float(swing.sel(direction="up", speed_rpm=10200.0)) == pytest.approx(
        float(swing.sel(direction="down", speed_rpm=10200.0)), rel=1e-6)
    # no point is NaN and valid
    assert not np.any(np.isnan(data["kv"].values) & data["valid"].values)
    assert plot.stat().st_size > 10_000


def test_the_table_lists_the_jumps_and_direction_is_refused_on_the_linear_mesh(tmp_path):
    case = _backlash_case(tmp_path)
    result = _cli("sweep", str(case), "--vary", "speed_rpm=3000,5000", "--model", "elastic", "--direction", "up",
                  "--out", str(tmp_path / "up.zarr"), "--no-progress")
    assert result.returncode == 0, result.stderr
    # one direction: only the up branch is summarised (the study engine's summary names each model/direction)
    assert "elastic/up: max Kv" in result.stdout and "elastic/down" not in result.stdout
    linear = _cli("sweep", str(DATA / "two_shaft_drivetrain.toml"), "--vary", "speed_rpm=3000,5000", "--direction",
                  "up", "--out", str(tmp_path / "linear.zarr"))
    assert linear.returncode != 0 and "--direction" in linear.stderr and "Traceback" not in linear.stderr
    assert not (tmp_path / "linear.zarr").exists()
