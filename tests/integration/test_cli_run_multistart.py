"""`thermogear run CASE --multistart N` (issue 36): every stable orbit of the backlash drivetrain that N starts
settle on, with its basin share, in the table and the JSON; refused with the reason where it does not apply."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from inprocess_cli import invoke

DATA = Path(__file__).resolve().parents[1] / "data"


def _case(tmp_path: Path, speed_rpm: float = 9000.0, mesh: str = "nonlinear", extra: str = "") -> Path:
    # the worked two-shaft case with the backlash mesh near its wheel shaft's mesh-coupled mode (1× mesh at 9317
    # rpm), where the teeth separate; a coarse mesh grid and a 10 kHz cut-off keep it fast
    text = (DATA / "two_shaft_drivetrain.toml").read_text(encoding="utf-8")
    text = text.replace('mesh = "linear"', f'mesh = "{mesh}"').replace(
        "speed_rpm = 1500.0", f"speed_rpm = {speed_rpm}").replace("points_per_period = 256", "points_per_period = 64")
    text = text.replace("[drivetrain]\n", "[drivetrain]\nresponse_cutoff_hz = 10000.0\n", 1) + extra
    case = tmp_path / "multistart.toml"
    case.write_text(text, encoding="utf-8")
    return case


@pytest.mark.slow
def test_every_stable_orbit_is_listed_with_its_basin_share(tmp_path):
    case = _case(tmp_path)
    code, stdout, stderr = invoke("run", str(case), "--model", "elastic", "--multistart", "3", "--json")
    assert code == 0, stderr
    payload = json.loads(stdout)
    search = payload["drivetrain"]["multistart"]["elastic"]
    assert search["starts"] == 3 and search["orbits"]
    counted = sum(orbit["start_count"] for orbit in search["orbits"])
    shares = sum(orbit["basin_share"] for orbit in search["orbits"])
    assert counted <= 3 and shares + search["unresolved_share"] + search["unbounded_share"] == pytest.approx(1.0)
    shares_listed = [orbit["basin_share"] for orbit in search["orbits"]]
    assert shares_listed == sorted(shares_listed, reverse=True)  # largest basin first
    # `run` reports the orbit a start from rest settles on: the search's start from rest reaches the same one
    (from_rest,) = [orbit for orbit in search["orbits"] if orbit["reached_from_rest"]]
    reported = payload["drivetrain"]["models"]["elastic"]
    assert from_rest["kv"] == pytest.approx(reported["kv"], rel=1e-6)
    assert from_rest["contact_loss_fraction"] == pytest.approx(reported["contact_loss_fraction"], abs=1e-6)
    assert from_rest["contact_loss_fraction"] > 0.1  # near the mode the teeth separate (0.31 measured)
    code, stdout, stderr = invoke("run", str(case), "--model", "elastic", "--multistart", "3")
    assert code == 0, stderr
    text = " ".join(stdout.split())
    assert "stable orbits of a multi-start search (3 starts" in text and "basin share" in text
    assert "starts that settled on none" in text


@pytest.mark.parametrize("change, arguments, needs", [
    ({"mesh": "linear"}, (), 'dynamics.mesh = "nonlinear"'),
    ({}, ("--method", "transient"), "--method periodic"),
    ({}, ("--out", "{tmp}/report"), "without --out"),
])
def test_refused_with_the_reason_where_it_does_not_apply(tmp_path, change, arguments, needs):
    case = _case(tmp_path, **change)
    arguments = tuple(argument.replace("{tmp}", str(tmp_path)) for argument in arguments)
    code, stdout, stderr = invoke("run", str(case), "--multistart", "4", *arguments)
    assert code != 0 and not stdout
    message = " ".join(stderr.split())
    assert "--multistart" in message and needs in message
    assert not (tmp_path / "report").exists()  # refused before any work


def test_refused_on_the_pair_without_a_drivetrain():
    code, stdout, stderr = invoke("run", "luo2019", "--multistart", "4")
    message = " ".join(stderr.split())
    assert code != 0 and "--multistart" in message and "[drivetrain]" in message and "sweep --multistart" in message
