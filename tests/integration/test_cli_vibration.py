"""`thermogear vibration FILE`: JSON contract, WAV input, windows, plots and clear errors on bad files."""

from __future__ import annotations

import json
import subprocess

import numpy as np
import pytest

import inprocess_cli
from scipy.io import wavfile


def run(*arguments: str) -> subprocess.CompletedProcess:
    return inprocess_cli.run("vibration", *arguments)


@pytest.fixture(scope="module")
def rig_csv(tmp_path_factory):
    """30 s at 2 kHz: 0.5 m/s² at 349.25 Hz, 0.2 m/s² at 240 Hz (mesh), noise, temperature rising 30 → 40 °C."""
    rate = 2000.0
    time = np.arange(int(rate * 30)) / rate
    values = (0.5 * np.sin(2 * np.pi * 349.25 * time) + 0.2 * np.sin(2 * np.pi * 240.0 * time)
              + np.random.default_rng(0).normal(0, 0.05, time.size))
    path = tmp_path_factory.mktemp("rig") / "rig.csv"
    np.savetxt(path, np.column_stack([time, values, 30 + time / 3]), delimiter=",", fmt="%.7f",
               header="time_s,accel_m_s2,temperature_c", comments="")
    return path


def test_json_contract_and_values(rig_csv, tmp_path):
    completed = run(str(rig_csv), "--json", "--band", "200:400", "--windows", "3", "--mesh-frequency", "240",
                    "--plot", str(tmp_path / "figures"))
    assert completed.returncode == 0, completed.stderr
    payload = json.loads(completed.stdout)
    assert payload["sampling_rate_hz"] == pytest.approx(2000.0)
    for key in ("mean_amplitude", "max_amplitude", "peaks"):
        assert key in payload
    first, second = payload["peaks"][:2]
    assert first["frequency_hz"] == pytest.approx(349.25, abs=0.1 * payload["resolution_hz"])
    assert first["amplitude"] == pytest.approx(0.5, rel=0.01)
    assert second["frequency_hz"] == pytest.approx(240.0, abs=0.1 * payload["resolution_hz"])
    assert second["amplitude"] == pytest.approx(0.2, rel=0.01)
    assert payload["mesh_orders"][0]["amplitude"] == pytest.approx(0.2, rel=0.01)
    windows = payload["windows"]
    assert len(windows) == 3
    assert [round(w["temperature_c"], 1) for w in windows] == [31.7, 35.0, 38.3]
    assert all(w["peak_frequency_hz"] == pytest.approx(349.25, abs=0.01) for w in windows)
    assert {p.split("/")[-1] for p in payload["plots"]} == {"spectrum.png", "waterfall.png", "windows.png"}
    assert all((tmp_path / "figures" / name).stat().st_size > 1000 for name in ("spectrum.png", "waterfall.png"))


def test_wav_with_scale_and_rate_from_header(tmp_path):
    rate = 8000
    time = np.arange(rate * 2) / rate
    samples = np.round(0.25 * np.sin(2 * np.pi * 1000.3 * time) * 32767).astype(np.int16)
    path = tmp_path / "acc.wav"
    wavfile.write(path, rate, samples)
    completed = run(str(path), "--json", "--scale", "20", "--method", "fft")  # 20 m/s² at full scale
    assert completed.returncode == 0, completed.stderr
    payload = json.loads(completed.stdout)
    assert payload["sampling_rate_hz"] == rate
    assert payload["peaks"][0]["frequency_hz"] == pytest.approx(1000.3, abs=0.1 * payload["resolution_hz"])
    assert payload["peaks"][0]["amplitude"] == pytest.approx(20 * 0.25 * 32767 / 32768, rel=0.01)


def test_wav_cut_short_says_so_once_in_thermogears_format(tmp_path):
    path = tmp_path / "acc.wav"
    wavfile.write(path, 8000, np.round(8000 * np.sin(0.3 * np.arange(8000))).astype(np.int16))
    path.write_bytes(path.read_bytes()[:8023])  # half the data (a copy interrupted), mid-sample
    completed = run(str(path))
    assert completed.returncode == 0, completed.stderr
    lines = [line for line in completed.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("warning: ") and "cut short" in lines[0], completed.stderr
    assert "EOF" not in completed.stderr and "WavFileWarning" not in completed.stderr


def test_human_readable_output(rig_csv):
    completed = run(str(rig_csv), "--band", "300:400")
    assert completed.returncode == 0, completed.stderr
    assert "349.2" in completed.stdout and "mean |a−ā|" in completed.stdout


@pytest.mark.parametrize("content, arguments, message", [
    ("time_s,accel\n0,1\n0.001,x\n", (), "not a number"),
    ("time_s,accel\n0,1\n0.001,2\n", ("--column", "acc"), "column 'acc' not found"),
    ("a\n1\n2\n", (), "no time column"),
    ("time_s,accel\n0,1\n0,2\n", (), "duplicate time stamps"),
    ("time_s,accel\n" + "".join(f"{i / 100},{i}\n" for i in range(50)), ("--band", "40:30"), "LO < HI"),
])
def test_bad_input_exits_2_with_one_clear_line(tmp_path, content, arguments, message):
    path = tmp_path / "bad.csv"
    path.write_text(content)
    completed = run(str(path), *arguments)
    assert completed.returncode == 2
    assert message in " ".join(completed.stderr.split())  # rich wraps long lines
    assert "Traceback" not in completed.stderr
