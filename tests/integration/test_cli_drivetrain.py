"""`run`, `check` and `sweep` on a case with a [drivetrain] (issue 27): the modes and bearing forces in --json, a bad
drivetrain refused the same way by check and run, and a small speed sweep into a zarr store."""

from __future__ import annotations

import json
import subprocess
import tomllib
from pathlib import Path

import pytest

import inprocess_cli

DATA = Path(__file__).resolve().parents[1] / "data"
TWO_SHAFTS = DATA / "two_shaft_drivetrain.toml"


def _cli(*args: str) -> subprocess.CompletedProcess:
    # one BLAS thread: the drivetrain's small matrices are slower multi-threaded on a shared machine
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=1):
        return inprocess_cli.run(*args)


def test_run_json_holds_the_drivetrain_modes_bearing_forces_and_heat():
    result = _cli("run", str(TWO_SHAFTS), "--json")
    assert result.returncode == 0, result.stderr
    payload = json.loads(result.stdout)
    drivetrain = payload["drivetrain"]
    assert set(drivetrain["models"]) == {"elastic", "thermal"}
    elastic = drivetrain["models"]["elastic"]
    assert len(elastic["modes"]) == 12 and all(mode["label"] for mode in elastic["modes"])
    assert {"mesh", "bearings", "shafts"} <= set(elastic["modes"][0]["energy_shares"])
    assert sorted(elastic["bearing_forces"]) == ["pinion bearing A", "pinion bearing B", "wheel bearing A",
                                                 "wheel bearing B"]
    force = elastic["bearing_forces"]["wheel bearing A"]
    assert force["dynamic_rms_n"] > 0.0 and len(force["harmonic_amplitude_n"]) == 3
    assert elastic["kv"] > 1.0 and elastic["stable"]
    # issue 38: the response states its cut-off's estimated error (issue 36: from the modes above the cut-off,
    # the highest of them its check_cutoff_hz, without a second solve)
    cutoff = elastic["cutoff_error"]
    assert cutoff["check_cutoff_hz"] > cutoff["cutoff_hz"] == drivetrain["response_cutoff_hz"]
    assert "modes above it" in cutoff["estimated_from"] and cutoff["check_coordinates"] > cutoff["coordinates"]
    assert 0.0 < cutoff["dte_relative"] < 0.01 and 0.0 < cutoff["bearing_force_relative"] < 0.1
    assert len(drivetrain["heat"]) == 12 and "dominant_cause" in drivetrain["heat"][0]
    # the pair's own results are still there, beside the drivetrain's
    assert set(payload["models"]) == {"elastic", "thermal"}
    # issue 36: the headline Kv is the drivetrain's, the 1-DOF pair's beside it, labelled
    for model in ("elastic", "thermal"):
        headline = payload["headline"][model]
        assert headline["system"] == "drivetrain" and headline["kv"] == drivetrain["models"][model]["kv"]
        assert headline["pair_kv"] == payload["models"][model]["kv"] != headline["kv"]
    # issue 36: every line that went to stderr (model checks, warnings) is in "messages"
    printed = [line for line in result.stderr.splitlines() if line.strip()]
    assert printed and all(line in payload["messages"] for line in printed), (printed, payload["messages"])
    # the two dynamic factors are explained, the stiffness step that sets the second one given: far below resonance
    # (frequency ratio 0.11) the deflection at the step into double contact is nearly the single-contact static one,
    # so the total force jumps to about the step ratio × the static load (measured 0.09 % and 0.3 % apart; 1 % is
    # the margin for the deflection's small dynamic part at the step)
    assert "Eq. 29" in payload["dynamic_factors"]
    for numbers in payload["models"].values():
        assert numbers["max_system_load_ratio"] == pytest.approx(numbers["mesh_stiffness_step_ratio"], rel=0.01)


def test_run_table_prints_the_drivetrain_tables():
    result = _cli("run", str(TWO_SHAFTS), "--model", "elastic")
    assert result.returncode == 0, result.stderr
    for words in ("drivetrain modes", "lateral pinion shaft", "pinion bearing A: dynamic RMS", "1× mesh",
                  "estimated error"):
        assert words in result.stdout, words


def test_check_and_run_refuse_a_bearing_off_its_shaft_the_same_way(tmp_path):
    text = TWO_SHAFTS.read_text(encoding="utf-8").replace("position_mm = 300.0", "position_mm = 320.0")
    case = tmp_path / "bad.toml"
    case.write_text(text, encoding="utf-8")
    answers = [_cli(command, str(case)) for command in ("check", "run")]
    for answer in answers:
        assert answer.returncode != 0
        assert "drivetrain.bearings 'wheel bearing B'.position_mm = 320" in answer.stderr, answer.stderr
        assert "[0, 300] mm" in answer.stderr
    assert answers[0].stderr == answers[1].stderr


def test_check_run_and_sweep_refuse_a_bearing_clearance_under_the_linear_mesh(tmp_path):
    # the worked case's mesh is linear, which cannot represent a clearance: every command refuses it at load time,
    # none ignores it, and the reason says which mesh takes it
    text = TWO_SHAFTS.read_text(encoding="utf-8").replace("position_mm = 300.0",
                                                          "position_mm = 300.0\nradial_clearance_um = 15.0")
    case = tmp_path / "clearance.toml"
    case.write_text(text, encoding="utf-8")
    answers = [_cli(*command) for command in (("check", str(case)), ("run", str(case)),
                                              ("sweep", str(case), "--vary", "speed_rpm=1000,2000",
                                               "--out", str(tmp_path / "x.zarr")))]
    for answer in answers:
        assert answer.returncode != 0 and "Traceback" not in answer.stderr, answer.stderr
        assert "drivetrain.bearings 'wheel bearing B'.radial_clearance_um = 15" in answer.stderr, answer.stderr
        assert "dynamics.mesh = 'nonlinear'" in answer.stderr
    assert not (tmp_path / "x.zarr").exists()


def _nonlinear_case(tmp_path, clearance_um: float = 0.0) -> Path:
    """The worked case with the nonlinear (backlash) mesh and, optionally, a clearance in one wheel bearing."""
    text = TWO_SHAFTS.read_text(encoding="utf-8")
    assert 'mesh = "linear"' in text
    text = text.replace('mesh = "linear"', 'mesh = "nonlinear"')
    if clearance_um:
        text = text.replace("position_mm = 300.0", f"position_mm = 300.0\nradial_clearance_um = {clearance_um}")
    case = tmp_path / "nonlinear.toml"
    case.write_text(text, encoding="utf-8")
    return case


@pytest.mark.slow
def test_run_solves_the_backlash_drivetrain_with_a_bearing_clearance(tmp_path):
    # the nonlinear mesh takes a bearing clearance (accepted at load), and run reports the backlash orbit: found,
    # its contact loss and back-flank contact, Kv from it; the linear keys keep their meaning; the table says so
    case = _nonlinear_case(tmp_path, clearance_um=2.0)
    assert _cli("check", str(case)).returncode == 0
    result = _cli("run", str(case), "--model", "elastic", "--json")
    assert result.returncode == 0, result.stderr
    drivetrain = json.loads(result.stdout)["drivetrain"]
    assert drivetrain["backlash_mesh"] and drivetrain["mesh"] == "nonlinear (backlash) on the drivetrain"
    elastic = drivetrain["models"]["elastic"]
    assert elastic["converged"] and elastic["failure"] == "" and elastic["stable"]
    assert 0.0 <= elastic["contact_loss_fraction"] < 1.0 and elastic["back_side_contact"] in (True, False)
    assert elastic["kv"] > 1.0 and elastic["dte_rms_um"] > 0.0
    assert not any("permanent contact" in note for note in drivetrain["notes"])
    # the clearance lets the wheel shaft move inside ±2 μm: its bearing still carries the mean load
    assert elastic["bearing_forces"]["wheel bearing B"]["mean_radial_n"] > 0.0
    table = _cli("run", str(case), "--model", "elastic")  # the tables of the typed results
    assert table.returncode == 0, table.stderr
    text = table.stdout
    for words in ("mesh nonlinear (backlash)", "time without contact", "back flanks struck",
                  "periodic orbit found (stable)"):
        assert words in text, words


@pytest.mark.slow
def test_run_transient_on_a_drivetrain_case_reports_the_last_period_from_rest(tmp_path):
    result = _cli("run", str(TWO_SHAFTS), "--model", "elastic", "--method", "transient", "--json")
    assert result.returncode == 0, result.stderr
    drivetrain = json.loads(result.stdout)["drivetrain"]
    assert drivetrain["transient"] and "periods from rest" in drivetrain["mesh"]
    elastic = drivetrain["models"]["elastic"]
    assert elastic["transient_periods"] >= 1 and elastic["kv"] > 1.0
    assert elastic["largest_floquet_multiplier_abs"] is None  # no orbit: no multipliers said


@pytest.mark.slow
def test_sweep_of_a_drivetrain_case_stores_kv_dte_and_bearing_forces_per_speed(tmp_path):
    import xarray as xr

    out = tmp_path / "study.zarr"
    plot = tmp_path / "sweep.png"
    result = _cli("sweep", str(TWO_SHAFTS), "--vary", "speed_rpm=2000:12000:6", "--out", str(out), "--plot",
                  str(plot), "--json", "--workers", "1")
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["points"] == 6 and summary["models"] == ["elastic", "thermal"]
    assert "per-speed path" in summary["path"]
    data = xr.open_zarr(out)
    assert data["kv"].shape == (2, 6)
    assert data["bearing_harmonic_amplitude_n"].shape == (2, 6, 4, 3)
    assert bool(data["valid"].all())
    # the wheel shaft's mesh-dominated lateral mode (4.19 kHz, mesh share 0.21) meets the 1st mesh harmonic at
    # 9317 rpm: the summary lists it, marked mesh-dominated
    crossings = [r for r in summary["resonances"]["elastic"] if r["mesh_dominated"] and r["harmonic"] == 1]
    assert crossings and 2000.0 <= crossings[0]["speed_rpm"] <= 12000.0
    assert plot.stat().st_size > 10_000


def test_a_drivetrain_sweep_varies_other_keys_than_speed(tmp_path):
    """Issue 34: a drivetrain study varies any key (it used to refuse all but speed_rpm): each torque is a point
    with its own response, in the store."""
    import xarray as xr

    result = _cli("sweep", str(TWO_SHAFTS), "--vary", "torque_nm=100,200", "--out", str(tmp_path / "x.zarr"))
    assert result.returncode == 0, result.stderr
    data = xr.open_zarr(tmp_path / "x.zarr")
    assert "torque_nm" in data.dims and list(data["torque_nm"].values) == [100.0, 200.0]
    assert "2 valid points" in result.stdout


def test_the_docs_page_shows_the_worked_case_file_verbatim():
    page = (Path(__file__).resolve().parents[2] / "docs" / "drivetrain.md").read_text(encoding="utf-8")
    block = page.split("```toml\n", 1)[1].split("```", 1)[0]
    # the block is the case file minus its two header comment lines, so what users copy is what the tests run
    body = TWO_SHAFTS.read_text(encoding="utf-8").split("\n", 2)[2]
    assert block == body
    assert tomllib.loads(block)["drivetrain"]["pinion"]["position_mm"] == 125.0


@pytest.mark.slow
def test_the_report_has_a_drivetrain_section_and_summary_json_its_numbers(tmp_path):
    out = tmp_path / "report"
    result = _cli("run", str(TWO_SHAFTS), "--out", str(out), "--json")
    assert result.returncode == 0, result.stderr
    payload = json.loads(result.stdout)
    page = (out / "report.html").read_text(encoding="utf-8")
    assert "The pair in its drivetrain" in page and "Dynamic bearing forces on the housing" in page
    # issue 36: the drivetrain in the top links, its Kv in the headline with the 1-DOF pair's labelled beside it
    top = page.split("<h2 id='case'>", 1)[0]
    assert "<a href='#drivetrain'>drivetrain</a>" in top
    kv = payload["drivetrain"]["models"]["elastic"]["kv"]
    assert f"elastic: drivetrain Kv {kv:.3f} (1-DOF pair on rigid supports" in top
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    # run --json and the report's summary.json carry the same drivetrain numbers (computed once, by the report)
    assert summary["drivetrain"] == payload["drivetrain"]
    assert len(summary["drivetrain"]["heat"]) == 12
    # the bearing forces in time are in results.nc, one group per model; their mean and mesh harmonics are the
    # numbers the tables print (the radial amplitude √(X² + Y²) of each harmonic, the mean radial force)
    import numpy as np
    import xarray as xr

    for model, numbers in payload["drivetrain"]["models"].items():
        with xr.open_dataset(out / "results.nc", group=f"drivetrain_{model}") as series:
            assert series["bearing_force"].dims == ("bearing", "sample", "axis")
            assert series["time"].size == series["transmission_error"].size > 100
            for bearing, printed in numbers["bearing_forces"].items():
                lines = series["bearing_harmonic_amplitude"].sel(bearing=bearing)
                radial = np.hypot(lines.sel(axis="x"), lines.sel(axis="y")).values
                # the printed numbers come from the same spectrum: equal to rounding
                np.testing.assert_allclose(radial[1:], printed["harmonic_amplitude_n"], rtol=1e-9)
                # the printed mean is the trapezoid over the solver's samples, the file's harmonic 0 the mean of
                # the uniform resampling the spectrum takes: equal to the resampling's error (measured 1.7e-7)
                assert float(radial[0]) == pytest.approx(printed["mean_radial_n"], rel=1e-6)


def test_a_drivetrain_orbit_not_found_prints_no_number_and_says_why():
    # a backlash drivetrain whose shooting failed: every number of the model reads "not found", the orbit row "NO",
    # and the reason is printed (table and report alike), never a value labelled valid
    import io

    from rich.console import Console

    from thermogear.cli.run_drivetrain import print_drivetrain
    from thermogear.report.drivetrain_section import drivetrain_section

    from thermogear.drivetrain.results import (BearingForces, DrivetrainBacklashResult, DrivetrainResults,
                                               ModeRow)

    unknown = BearingForces(None, None, (500.0,), (None,))
    mode = ModeRow(900.0, "torsional", 0.9, {"mesh": 0.9}, {}, True)
    model = DrivetrainBacklashResult(None, None, None, None, False, {"bearing A": unknown}, (mode,), (),
                                     converged=False, failure="Newton stopped at residual 0.3 > 1e-08")
    results = DrivetrainResults(12, 3e4, "nonlinear (backlash) on the drivetrain", True, False,
                                "modes up to 30000 Hz", (), {"elastic": model})
    buffer = io.StringIO()
    print_drivetrain(results, Console(file=buffer, width=200))
    text = buffer.getvalue()
    assert "no periodic orbit — Newton stopped" in text and "periodic orbit found (stable)" in text
    kv_row = next(line for line in text.splitlines() if "│ Kv" in line)
    assert "not found" in kv_row and not any(character.isdigit() for character in kv_row)
    page = drivetrain_section(results)
    assert "no periodic orbit — Newton stopped" in page and "<td class=num>NO</td>" in page
