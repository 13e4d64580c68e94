"""A helical drivetrain under the backlash mesh (``[dynamics] mesh = "nonlinear"``) end to end through the CLI: the
two-shaft rotor of docs/drivetrain.md with its pair cut at β = 15° (spread contact), ``run`` (table and --json) and a
speed ``sweep``. At its load the teeth never separate, so the backlash orbit is the linear response of the same case
(test_helical_drivetrain.py checks it on the library's response; here through the commands)."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]


def _document(mesh: str) -> dict:
    """tests/data/two_shaft_drivetrain.toml with a 15° right-hand pinion, the spread contact and coarse settings
    (64 points per period, 60 mm elements, modes to 20 kHz) under ``mesh``."""
    document = tomllib.loads((ROOT / "tests" / "data" / "two_shaft_drivetrain.toml").read_text(encoding="utf-8"))
    document["gears"].update(helix_angle_deg=15.0, hand="right")
    document["dynamics"].update(mesh=mesh, points_per_period=64)
    document["drivetrain"].update(helical_contact="spread", maximum_element_length_mm=60.0,
                                  response_cutoff_hz=20000.0)
    return document


def _case_file(tmp_path: Path, mesh: str) -> Path:
    import tomli_w

    path = tmp_path / f"helical_{mesh}.toml"
    path.write_text(tomli_w.dumps(_document(mesh)), encoding="utf-8")
    return path


def _invoke(arguments: list[str]):
    from typer.testing import CliRunner

    from thermogear.cli.app import app

    outcome = CliRunner().invoke(app, arguments)
    assert outcome.exit_code == 0, outcome.output
    return outcome


def _run_json(path: Path) -> dict:
    stdout = _invoke(["run", str(path), "--json"]).stdout
    return json.loads(stdout[stdout.index("{"):])["drivetrain"]


def test_run_json_of_the_helical_drivetrain_with_the_backlash_mesh_is_its_linear_response(tmp_path):
    nonlinear, linear = (_run_json(_case_file(tmp_path, mesh)) for mesh in ("nonlinear", "linear"))
    assert nonlinear["backlash_mesh"] and not linear["backlash_mesh"]
    assert set(nonlinear["models"]) == {"elastic", "thermal"}
    for model, values in nonlinear["models"].items():
        assert values["converged"] and values["failure"] == "" and values["stable"]
        assert values["contact_loss_fraction"] == 0.0 and values["back_contact_fraction"] == 0.0
        theirs = linear["models"][model]
        # the same orbit: the bearing forces' harmonics (Fourier coefficients of the orbit) agree to 1e-9 of the
        # largest (measured 2e-11); the means and RMS are integrals of the sampled orbit, sampled at other times
        # (the backlash path adds each piece's extrema), so they agree to the sampling only
        largest = max(max(force["harmonic_amplitude_n"]) for force in theirs["bearing_forces"].values())
        for name, force in values["bearing_forces"].items():
            np.testing.assert_allclose(force["harmonic_amplitude_n"], theirs["bearing_forces"][name][
                "harmonic_amplitude_n"], rtol=0.0, atol=1e-9 * largest)
            assert force["mean_axial_n"] == pytest.approx(theirs["bearing_forces"][name]["mean_axial_n"], rel=1e-6,
                                                          abs=1e-9)
        # Kv: the maximum of the sampled δ, the backlash samples a superset (see the train's test): within 1e-4
        assert theirs["kv"] * (1.0 - 1e-12) <= values["kv"] <= theirs["kv"] * (1.0 + 1e-4)
        # the thrust: the pinion shaft's locating bearing carries W tan β_b, the wheel shaft's the reaction
        axial = {name: force["mean_axial_n"] for name, force in values["bearing_forces"].items()}
        assert axial["pinion bearing A"] > 0.0 and axial["pinion bearing A"] == pytest.approx(
            -axial["wheel bearing A"], rel=1e-6)


def test_run_table_of_the_helical_drivetrain_with_the_backlash_mesh(tmp_path):
    output = _invoke(["run", str(_case_file(tmp_path, "nonlinear")), "--model", "elastic"]).stdout
    assert "mesh nonlinear (backlash) on the drivetrain" in output
    assert "mean axial" in output and "mean tilting moment" in output
    assert "periodic orbit found (stable)" in output


@pytest.mark.slow
def test_a_speed_sweep_of_the_helical_drivetrain_with_the_backlash_mesh(tmp_path):
    import xarray as xr

    store = tmp_path / "sweep.zarr"
    stdout = _invoke(["sweep", str(_case_file(tmp_path, "nonlinear")), "--vary", "speed_rpm=1200:1800:2",
                      "--model", "elastic", "--out", str(store), "--json"]).stdout
    summary = json.loads(stdout[stdout.index("{"):])
    assert summary["mesh"] == "nonlinear"
    assert all(count == 2 for count in summary["valid_points"].values())
    assert all(count == 0 for count in summary["contact_loss_points"].values())
    with xr.open_zarr(store) as result:
        kv = result["kv"].sel(model="elastic").values
        amplitudes = result["bearing_harmonic_amplitude_n"].sel(model="elastic").values
    assert np.all(np.isfinite(kv)) and np.all(kv > 1.0)
    assert np.all(np.isfinite(amplitudes)) and np.all(amplitudes > 0.0)
    np.testing.assert_allclose(kv[0], kv[1], rtol=1e-9)  # the orbit followed up and down is one orbit
