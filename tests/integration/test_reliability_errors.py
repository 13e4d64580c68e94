"""Inputs that used to end in a Python traceback (issue 15) now give exit status 2 and one `error:` message.

(How a long message is wrapped on a narrow stream is the console's business, issue 15 part B: the message is
counted by its ``error:`` prefix.)"""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pytest
from scipy.io import wavfile

import inprocess_cli


def _thermogear(*args: str, cwd=None) -> subprocess.CompletedProcess:
    # in this process: an exception escaping the command (a traceback on the command line) fails the test
    return inprocess_cli.run(*args, cwd=cwd)


def _assert_one_error(result: subprocess.CompletedProcess, *words: str) -> None:
    assert result.returncode == 2, result.stdout + result.stderr
    assert "Traceback" not in result.stderr
    assert result.stderr.count("error:") == 1 and result.stderr.lstrip().startswith("error:"), result.stderr
    flat = result.stderr.replace("\n", " ")
    for word in words:
        assert word in flat, result.stderr


@pytest.fixture
def wav(tmp_path) -> Path:
    path = tmp_path / "ok.wav"
    time = np.arange(2000) / 1000.0
    wavfile.write(path, 1000, (np.sin(2 * np.pi * 50 * time) * 10000).astype(np.int16))
    return path


def test_vibration_latin1_and_binary_files(tmp_path):
    latin1 = tmp_path / "latin1.csv"
    latin1.write_bytes("time,Beschleunigung µ\n0,1\n0.001,2\n0.002,3\n".encode("latin-1"))
    binary = tmp_path / "binary.wav"
    binary.write_bytes(bytes(range(256)) * 8)
    _assert_one_error(_thermogear("vibration", str(latin1)), "UTF-8")
    _assert_one_error(_thermogear("vibration", str(binary)), "WAV")


def test_vibration_wav_with_no_frames(tmp_path):
    path = tmp_path / "empty.wav"
    wavfile.write(path, 8000, np.zeros(0, dtype=np.int16))
    _assert_one_error(_thermogear("vibration", str(path)), "0 frame")


def test_vibration_plot_onto_an_existing_file_leaves_it(tmp_path, wav):
    target = tmp_path / "notes.txt"
    target.write_text("keep me")
    _assert_one_error(_thermogear("vibration", str(wav), "--plot", str(target)), "--plot", "file of that name")
    assert target.read_text() == "keep me"


def test_stiffness_plot_onto_an_existing_folder(tmp_path):
    folder = tmp_path / "figure.png"
    folder.mkdir()
    _assert_one_error(_thermogear("stiffness", "luo2019", "--plot", str(folder)), "--plot", "folder")
    assert folder.is_dir() and list(folder.iterdir()) == []


def test_stiffness_thermal_plot_with_a_text_suffix(tmp_path):
    _assert_one_error(_thermogear("stiffness", "luo2019", "--thermal", "--plot", str(tmp_path / "k.txt")),
                      "--plot", ".png")
    assert not (tmp_path / "k.txt").exists()


def test_sweep_on_an_unreachable_scheduler_leaves_no_store(tmp_path):
    out = tmp_path / "study.zarr"
    result = _thermogear("sweep", "luo2019", "--vary", "speed_rpm=1000,2000", "--scheduler", "tcp://127.0.0.1:1",
                         "--out", str(out), "--no-progress")
    _assert_one_error(result, "--scheduler", "tcp://127.0.0.1:1")
    assert not out.exists()


def test_check_of_a_non_utf8_case(tmp_path):
    path = tmp_path / "case.toml"
    path.write_bytes('[case]\nname = "Prüfstand"\n'.encode("latin-1"))
    _assert_one_error(_thermogear("check", str(path)), "UTF-8")
