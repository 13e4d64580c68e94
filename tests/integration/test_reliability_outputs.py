"""Paths, files and own outputs (issue 25): every output path is checked before any work (5 000-character
paths, unsupported figure suffixes, a folder given as a figure); bad signal files and options are one clear
error; no file's content is echoed; thermogear replaces only what it wrote and one process writes a store."""

from __future__ import annotations

import json

import numpy as np
import pytest

from thermogear.ownership import MARKER, exclusive_writer, is_owned

from inprocess_cli import invoke

LONG = "x" * 5000
SWEEP = ("sweep", "luo2019", "--vary", "speed_rpm=1000,2000", "--model", "elastic", "--scheduler", "serial",
         "--no-progress")


def _one_error(code: int, err: str, key: str) -> str:
    assert code == 2, err
    lines = [line for line in err.splitlines() if line.startswith("error:")]
    assert len(lines) == 1 and key in lines[0], err
    return lines[0]


SIMPLE_CASE = """[case]
name = "simple"
[gears]
module_mm = 3.0
face_width_mm = 20.0
[gears.pinion]
teeth = 20
[gears.wheel]
teeth = 40
[operating]
speed_rpm = 1000.0
torque_nm = 100.0
"""


@pytest.mark.parametrize("arguments, key", [
    (("check", f"/tmp/{LONG}.toml"), "case"),
    (("stiffness", "luo2019", "--plot", f"{LONG}.png"), "--plot"),
    (("vibration", f"{LONG}.csv"), "no such file"),
    (("run", "luo2019", "--out", LONG), "--out"),
    (("reproduce", "luo2019", "--out", LONG), "--out"),
    ((*SWEEP, "--out", LONG), "--out"),
    ((*SWEEP, "--out", "OUT", "--plot", "figure.bmp"), "--plot"),   # after the study: a traceback
    ((*SWEEP, "--out", "OUT", "--plot", "."), "--plot"),            # wrote ./.png silently
    (("damping", "luo2019", "--plot", f"{LONG}.png"), "--plot"),
    (("warmup", "luo2019", "--model", "first-order", "--plot", f"{LONG}.svg"), "--plot"),
])
def test_every_output_path_is_checked_before_any_work(arguments, key, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = invoke(*(str(tmp_path / "study.zarr") if a == "OUT" else a for a in arguments))
    message = _one_error(code, err, key)
    assert len(message) < 600  # the 5000-character path is cut in the message
    assert list(tmp_path.iterdir()) == []  # nothing computed, nothing written


def test_a_temperature_csv_with_a_long_name_or_a_bad_header_is_one_error_without_its_content(tmp_path):
    case = tmp_path / "case.toml"
    table = '[temperature]\nmodel = "tabulated"\ncsv = "{}"\npinion_base_c = 60.0\n'
    case.write_text(SIMPLE_CASE + table.format(LONG + ".csv"), encoding="utf-8")
    _one_error(*invoke("check", str(case))[::2], "temperature.csv")
    (tmp_path / "t.csv").write_text("secret-first-line,42\n1,2\n", encoding="utf-8")
    case.write_text(SIMPLE_CASE + table.format("t.csv"), encoding="utf-8")
    message = _one_error(*invoke("check", str(case))[::2], "temperature.csv")
    assert "secret" not in message  # the file's first line is not echoed


def test_an_escape_sequence_in_the_case_name_is_refused_not_printed(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(SIMPLE_CASE.replace('"simple"', '"evil\\u001b[2J"') + "[temperature]\nbulk_c = 60.0\n",
                    encoding="utf-8")
    code, out, err = invoke("check", str(case))
    _one_error(code, err, "case.name")
    assert "\x1b" not in out + err


def _signal_file(tmp_path, values, temperature=None):
    time = np.arange(values.size) / 10000.0
    columns = ["time_s", "accel"] + (["temperature_c"] if temperature is not None else [])
    rows = [time, values] + ([temperature] if temperature is not None else [])
    path = tmp_path / "signal.csv"
    path.write_text(",".join(columns) + "\n" + "\n".join(",".join(repr(float(v)) for v in row)
                                                        for row in zip(*rows)), encoding="utf-8")
    return path


@pytest.mark.parametrize("samples, options, temperature, words", [
    (1e300, ("--json",), None, "overflow"),          # crashed --json (NaN) and printed NaN
    (1.0, ("--band", "0:inf"), None, "--band"),      # traceback
    (1.0, ("--scale", "1e308"), None, "overflow"),   # traceback
    (1.0, (), -1e6, "temperature"),                  # accepted
])
def test_vibration_refuses_absurd_signals_and_options(samples, options, temperature, words, tmp_path):
    values = samples * np.sin(2 * np.pi * 300.0 * np.arange(2000) / 10000.0)
    path = _signal_file(tmp_path, values, None if temperature is None else np.full(values.size, temperature))
    code, out, err = invoke("vibration", str(path), *options)
    _one_error(code, err, words)


def test_a_signal_header_with_an_escape_sequence_is_refused_not_printed(tmp_path):
    path = tmp_path / "signal.csv"
    path.write_text("time_s,accel\x1b[31m\n0,1\n0.1,2\n0.2,3\n", encoding="utf-8")
    code, out, err = invoke("vibration", str(path))
    _one_error(code, err, "control characters")
    assert "\x1b" not in out + err


def test_vibration_refuses_a_truncated_wav(tmp_path):
    from scipy.io import wavfile

    whole = tmp_path / "whole.wav"
    wavfile.write(whole, 10000, (3000 * np.sin(np.arange(2000) / 10.0)).astype(np.int16))
    for length in (10, 30, 40):  # inside the RIFF header, inside the fmt chunk (UnboundLocalError before)
        cut = tmp_path / f"cut{length}.wav"
        cut.write_bytes(whole.read_bytes()[:length])
        _one_error(*invoke("vibration", str(cut))[::2], "WAV")


def test_warmup_refuses_a_speed_that_is_not_a_number():
    _one_error(*invoke("warmup", "luo2019", "--temperature-history", "luo2019:abc")[::2], "--temperature-history")


# --------------------------------------------------------------------------------------------- own outputs
def test_sweep_overwrite_refuses_to_delete_a_users_file_in_its_store(tmp_path):
    target = tmp_path / "study.zarr"
    assert invoke(*SWEEP, "--out", str(target))[0] == 0
    (target / "notes.txt").write_text("mine", encoding="utf-8")
    message = _one_error(*invoke(*SWEEP, "--out", str(target), "--overwrite")[::2], "notes.txt")
    assert "never deletes" in message
    assert (target / "notes.txt").read_text(encoding="utf-8") == "mine" and is_owned(target, "sweep-store")
    (target / "notes.txt").unlink()
    assert invoke(*SWEEP, "--out", str(target), "--overwrite")[0] == 0  # its own store alone is replaced


def test_a_second_sweep_into_a_store_being_written_is_refused(tmp_path):
    target = tmp_path / "study.zarr"
    with exclusive_writer(target):  # another process writing the store (flock: per open file, so this conflicts)
        message = _one_error(*invoke(*SWEEP, "--out", str(target), "--overwrite")[::2], "--out")
    assert "another thermogear process" in message
    assert not target.exists()
    assert invoke(*SWEEP, "--out", str(target))[0] == 0  # released: the next one runs
    assert not (tmp_path / ".study.zarr.lock").exists()


def test_replacing_a_report_folder_keeps_the_users_files(tmp_path):
    from thermogear.report.writer import OutputFolder

    target = tmp_path / "report"
    with OutputFolder(target) as folder:
        (folder.path / "report.html").write_text("first", encoding="utf-8")
        (folder.path / "figures").mkdir()
        (folder.path / "figures" / "old.png").write_text("thermogear's", encoding="utf-8")
    assert json.loads((target / MARKER).read_text())["files"] == ["figures/old.png", "report.html"]
    (target / "notes.txt").write_text("mine", encoding="utf-8")
    (target / "figures" / "mine").mkdir()
    (target / "figures" / "mine" / "sketch.txt").write_text("mine too", encoding="utf-8")
    (target / "empty").mkdir()
    with OutputFolder(target, force=True) as folder:
        (folder.path / "report.html").write_text("second", encoding="utf-8")
    assert (target / "report.html").read_text(encoding="utf-8") == "second"
    assert not (target / "figures" / "old.png").exists()  # thermogear's own old file is replaced (gone)
    assert (target / "notes.txt").read_text(encoding="utf-8") == "mine"
    assert (target / "figures" / "mine" / "sketch.txt").read_text(encoding="utf-8") == "mine too"
    assert (target / "empty").is_dir()


def test_two_sweeps_into_one_store_at_once_leave_one_complete_store_of_thermogear(tmp_path):
    # issue 25: 4 of 4 tries gave a traceback (ContainsArrayError, KeyError: 'kv') and once a store without its
    # marker. Now one writes and the other is refused at once (or runs after it): never both at once.
    import subprocess
    import sys

    target = tmp_path / "same.zarr"
    command = [sys.executable, "-m", "thermogear", *SWEEP, "--out", str(target), "--overwrite", "--json"]
    first = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    second = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    results = [process.communicate(timeout=300) + (process.returncode,) for process in (first, second)]
    codes = sorted(code for _, _, code in results)
    assert codes in ([0, 0], [0, 2]), results
    for out, err, code in results:
        assert "Traceback" not in err
        if code == 2:
            assert "another thermogear process" in err
    assert is_owned(target, "sweep-store")
    import zarr

    assert "kv" in zarr.open_group(str(target), mode="r")
