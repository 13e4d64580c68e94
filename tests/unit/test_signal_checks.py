"""Signal files that used to end in a traceback (issue 15): not UTF-8, a WAV file with no frames."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.io import wavfile

from thermogear.experiment.signals import SignalError, read_signal


def test_latin1_csv_is_a_signal_error(tmp_path):
    path = tmp_path / "latin1.csv"
    path.write_bytes("time,Beschleunigung µ\n0,1\n0.001,2\n0.002,3\n".encode("latin-1"))
    with pytest.raises(SignalError, match="not UTF-8"):
        read_signal(path)


def test_binary_csv_is_a_signal_error(tmp_path):
    path = tmp_path / "binary.csv"
    path.write_bytes(bytes(range(256)) * 8)
    with pytest.raises(SignalError, match="not UTF-8"):
        read_signal(path)


@pytest.mark.parametrize("shape", [(0,), (0, 2)])
def test_wav_with_no_frames_is_a_signal_error(tmp_path, shape):
    path = tmp_path / "empty.wav"
    wavfile.write(path, 8000, np.zeros(shape, dtype=np.int16))
    with pytest.raises(SignalError, match="0 frame"):
        read_signal(path)


def test_utf8_csv_with_units_still_reads(tmp_path):
    path = tmp_path / "utf8.csv"
    path.write_text("time,acceleration µ\n0,1\n0.001,2\n0.002,3\n", encoding="utf-8")
    assert read_signal(path).values.size == 3
