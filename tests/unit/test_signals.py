"""Reading and validating measured signals (CSV, WAV): good files load, malformed ones give clear errors."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.io import wavfile

from thermogear.errors import ThermogearError
from thermogear.experiment.signals import (Signal, SignalError, parse_csv_signal, read_signal, read_wav_signal,
                                           wav_full_scale)


def csv_text(rate=1000.0, n=50, header="time_s,accel,temperature_c"):
    time = np.arange(n) / rate
    lines = [header] + [f"{t:.9f},{np.sin(2 * np.pi * 50 * t):.9f},{30 + t:.3f}" for t in time]
    return "\n".join(lines)


def test_csv_with_time_column_gives_rate_start_and_temperature():
    signal = parse_csv_signal(csv_text(rate=2000.0))
    assert signal.sampling_rate_hz == pytest.approx(2000.0, rel=1e-9)
    assert signal.name == "accel"
    assert signal.start_time_s == 0.0
    assert signal.temperature_c is not None and signal.temperature_c[0] == pytest.approx(30.0)
    assert signal.values.size == 50


def test_csv_without_time_column_needs_rate():
    text = "a,b\n" + "\n".join(f"{i},{2 * i}" for i in range(20))
    with pytest.raises(SignalError, match="no time column"):
        parse_csv_signal(text)
    signal = parse_csv_signal(text, column="b", rate_hz=100.0)
    assert signal.sampling_rate_hz == 100.0 and signal.values[3] == 6.0


def test_semicolon_delimiter_and_rounded_time_stamps_accepted():
    rate = 51200.0  # time stamps rounded to 1 μs are up to 2.6 % of a step off the grid
    lines = ["t;acc"] + [f"{i / rate:.6f};{i % 7}" for i in range(200)]
    signal = parse_csv_signal("\n".join(lines))
    assert signal.sampling_rate_hz == pytest.approx(rate, rel=1e-4)


def test_rate_that_disagrees_with_time_column_is_refused():
    with pytest.raises(SignalError, match="disagrees"):
        parse_csv_signal(csv_text(rate=1000.0), rate_hz=1200.0)


@pytest.mark.parametrize("text, message", [
    ("", "empty"),
    ("time_s,accel", "no samples"),
    ("time_s,accel\n0,1\n0.001,abc\n0.002,3", r"row 3 is not a number"),  # the content is not echoed
    ("time_s,accel\n0,1\n0.001,\n0.002,3", "not a number"),
    ("time_s,accel\n0,1\n0.001,nan\n0.002,3", "NaN"),
    ("time_s,accel\n0,1\n0.001,1\n0.001,3\n0.002,1", "duplicate time stamps"),
    ("time_s,accel\n0,1\n0.002,1\n0.001,3\n0.003,1", "unsorted"),
    ("time_s,accel\n0,1\n0.001,1\n0.0025,3\n0.003,1", "not uniformly sampled"),
    ("time_s,accel\n0,1\n0.001,1,5\n0.002,3", "row 3 has 3 fields"),
    ("time_s,temperature_c\n0,1\n0.001,1", "no signal column"),
    ("time_s,accel,accel\n0,1,1\n0.001,1,1", "repeated"),
])
def test_malformed_csv_gives_clear_error(text, message):
    with pytest.raises(SignalError, match=message):
        parse_csv_signal(text)


def test_missing_column_names_the_columns():
    with pytest.raises(SignalError, match=r"column 'acc' not found; columns are \['time_s', 'accel'"):
        parse_csv_signal(csv_text(), column="acc")


def test_signal_error_is_a_thermogear_error_for_the_cli():
    assert issubclass(SignalError, ThermogearError)


def test_signal_refuses_nan_and_bad_rate():
    with pytest.raises(SignalError, match="NaN"):
        Signal(np.array([0.0, np.nan, 1.0]), 100.0)
    with pytest.raises(SignalError, match="allowed > 0"):
        Signal(np.zeros(10), 0.0)
    with pytest.raises(SignalError, match="at least 2"):
        Signal(np.zeros(1), 10.0)


def test_between_cuts_on_the_time_axis():
    signal = Signal(np.arange(100.0), 10.0, start_time_s=5.0)
    part = signal.between(6.0, 7.0)
    assert part.values[0] == 10.0 and part.values.size == 10 and part.start_time_s == pytest.approx(6.0)
    with pytest.raises(SignalError, match="fewer than 2"):
        signal.between(100.0, 200.0)


def test_read_signal_from_files(tmp_path):
    path = tmp_path / "rig.csv"
    path.write_text(csv_text(rate=500.0))
    assert read_signal(path).sampling_rate_hz == pytest.approx(500.0)
    assert read_signal(path, scale=2.0).values.max() == pytest.approx(2 * parse_csv_signal(csv_text(500.0)).values.max())
    with pytest.raises(SignalError, match="no such file"):
        read_signal(tmp_path / "missing.csv")
    other = tmp_path / "rig.xlsx"
    other.write_text("x")
    with pytest.raises(SignalError, match="not supported"):
        read_signal(other)


def test_wav_integer_full_scale_and_scale_option(tmp_path):
    rate = 8000
    samples = np.array([[0, 16384], [-32768, 32767], [8192, -16384]], dtype=np.int16)
    path = tmp_path / "acc.wav"
    wavfile.write(path, rate, samples)
    left = read_wav_signal(path)
    assert left.sampling_rate_hz == rate and left.name == "channel_0"
    np.testing.assert_allclose(left.values, [0.0, -1.0, 0.25])
    right = read_wav_signal(path, column="1", scale=50.0)  # 50 m/s² at full scale
    np.testing.assert_allclose(right.values, 50.0 * np.array([0.5, 32767 / 32768, -0.5]))
    with pytest.raises(SignalError, match="channels are"):
        read_wav_signal(path, column="channel_2")


def test_wav_full_scale_of_other_types():
    np.testing.assert_allclose(wav_full_scale(np.array([0, 128, 255], dtype=np.uint8)), [-1.0, 0.0, 127 / 128])
    np.testing.assert_allclose(wav_full_scale(np.array([2**30], dtype=np.int32)), [0.5])
    np.testing.assert_allclose(wav_full_scale(np.array([0.25], dtype=np.float32)), [0.25])


def test_wav_cut_short_is_read_with_one_warning_of_thermogear(tmp_path):
    """A WAV whose data ends before its header's length: the frames present, one warning in thermogear's words
    (how many frames the header announced, how many there are), none of SciPy's."""
    import warnings

    from thermogear.errors import ModelAssumptionWarning

    rate = 8000
    path = tmp_path / "acc.wav"
    wavfile.write(path, rate, (np.arange(1000) % 100).astype(np.int16))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        complete = read_wav_signal(path)
    assert complete.values.size == 1000 and not caught  # a whole file: nothing to say
    data = path.read_bytes()
    path.write_bytes(data[:44 + 2 * 600 + 1])  # 44-byte header, 600 int16 frames and one byte of the next
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        short = read_wav_signal(path)
    assert short.values.size == 600
    np.testing.assert_array_equal(short.values, complete.values[:600])
    assert [warning.category for warning in caught] == [ModelAssumptionWarning], [str(w.message) for w in caught]
    message = str(caught[0].message)
    assert "cut short" in message and "announces 1000 frames" in message and "holds 600" in message
    assert "EOF" not in message


@pytest.mark.filterwarnings("ignore::scipy.io.wavfile.WavFileWarning")
def test_broken_wav_is_refused(tmp_path):
    path = tmp_path / "broken.wav"
    path.write_bytes(b"RIFF1234WAVEjunk")
    with pytest.raises(SignalError, match="not a readable WAV"):
        read_signal(path)
