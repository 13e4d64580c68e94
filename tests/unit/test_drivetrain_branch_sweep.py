"""The drivetrain study with the backlash mesh (issues 27, 34): each point's numbers are the backlash response at
that speed, and a point without an orbit is stored as missing with the reason (the study of
thermogear.sweep.drivetrain_study, serial, into its store)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from thermogear.case import case_from_document
from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
from thermogear.drivetrain.case_model import bearing_force_summary, case_drivetrain
from thermogear.sweep.drivetrain_branches import SAMPLES_PER_PIECE, SUBSTEPS

DATA = Path(__file__).resolve().parents[1] / "data"


def _case():
    import tomllib

    document = tomllib.loads((DATA / "two_shaft_drivetrain.toml").read_text(encoding="utf-8"))
    document["dynamics"]["mesh"] = "nonlinear"
    # a coarse mesh grid and a low cut-off keep the test fast (the numbers compared are the same computation's)
    document["drivetrain"].update(sweep_points_per_period=32, response_cutoff_hz=10000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_from_document(document, "two_shaft_backlash")


def _built(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_drivetrain(case, ("elastic",))


def _study(case, speeds, out: Path, **options):
    import thermogear

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return thermogear.sweep(case, vary={"speed_rpm": [float(speed) for speed in speeds]}, out=out,
                                model="elastic", scheduler="serial", **options)


def test_each_point_is_the_backlash_response_at_its_speed(tmp_path):
    case = _case()
    built = _built(case)
    speeds = np.array([3000.0, 5000.0])  # well below the mesh-coupled modes: one orbit, in permanent contact
    data = _study(case, speeds, tmp_path / "s.zarr")
    assert bool(data["valid"].all())
    section = built.section
    for index, speed in enumerate(speeds):
        state = built.models["elastic"].state(speed_rpm=speed, points_per_period=section.sweep_points_per_period)
        # shot on its own from the linear periodic state, not from the branch's: the orbit is unique here and both
        # shootings converge quadratically past their 1e-8 tolerance (measured 8e-15 apart in Kv and DTE RMS), so
        # 1e-9 lets rounding through but not a different orbit, basis or sampling (those move them by far more)
        direct = drivetrain_backlash_response(built.assembled("elastic"), state, None, SUBSTEPS, SAMPLES_PER_PIECE,
                                              section.response_cutoff_hz)
        forces = bearing_force_summary(direct, section.bearing_harmonics)
        for direction in ("up", "down"):
            point = data.sel(direction=direction, model="elastic").isel(speed_rpm=index)
            assert float(point["kv"]) == pytest.approx(direct.kv, rel=1e-9)
            assert float(point["dte_rms_um"]) == pytest.approx(direct.metrics["dte_rms"] * 1e6, rel=1e-9)
            assert float(point["dte_peak_to_peak_um"]) == pytest.approx(direct.metrics["dte_peak_to_peak"] * 1e6,
                                                                        rel=1e-9)
            assert float(point["contact_loss_fraction"]) == direct.contact_loss_fraction == 0.0
            np.testing.assert_allclose(point["bearing_harmonic_amplitude_n"].values,
                                       [forces[name]["harmonic_amplitude_n"] for name in forces], rtol=1e-9)


def test_a_point_without_an_orbit_is_missing_with_its_reason(tmp_path, monkeypatch):
    # a speed whose backlash system cannot be built (here: its matrices made to overflow, as a transition matrix
    # does at a speed far below the study's checked range) is stored as missing with the reason; the other speed is
    # computed, the up branch starting afresh after it and the down branch carrying on past it
    import thermogear.drivetrain.response as response

    built_system = response.drivetrain_backlash_system

    def overflowing(assembled, state):
        if state.speed_rpm == 1000.0:
            raise np.linalg.LinAlgError("the transition matrix overflowed")
        return built_system(assembled, state)

    monkeypatch.setattr(response, "drivetrain_backlash_system", overflowing)  # the serial study runs here
    data = _study(_case(), [1000.0, 3000.0], tmp_path / "s.zarr")
    for direction in ("up", "down"):
        point = data.sel(direction=direction, model="elastic")
        status = [str(value) for value in point["status"].values]
        assert status[0].startswith("not computed") and status[1] == "valid", status
        assert not point["valid"].values[0] and not point["converged"].values[0]
        assert np.isnan(point["kv"].values[0]) and np.isnan(point["bearing_harmonic_amplitude_n"].values[0]).all()
        assert np.isfinite(point["kv"].values[1])


def test_directions_are_checked(tmp_path):
    from thermogear.errors import CaseError

    with pytest.raises(CaseError, match="--direction"):
        _study(_case(), [3000.0], tmp_path / "s.zarr", direction="sideways")
    assert not (tmp_path / "s.zarr").exists()
