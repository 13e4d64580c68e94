"""Measured signals: read acceleration (and optional temperature) time series from CSV or WAV and validate them.

CSV files have one header line. A time column (``time``, ``time_s``, ``t`` or ``t_s``, seconds) gives the
sampling rate, or the rate is passed explicitly; every other numeric column is a signal, except a temperature
column (``temperature_c``, ``temperature``, ``temp_c``, °C), which travels with the signal.

WAV files are read with :func:`scipy.io.wavfile.read`. Integer samples are scaled to ±1 full scale
(int16 / 2¹⁵, int32 and 24-bit / 2³¹, uint8 (x − 128) / 2⁷); float samples are taken as they are. The result
is then multiplied by ``scale`` (signal unit per full scale, e.g. the accelerometer's m/s² at full scale; 1 by
default). Channels are named ``channel_0``, ``channel_1``, …

Every problem with a file raises :class:`SignalError`, naming the file, the column and the row.
"""

from __future__ import annotations

import csv
import io
import unicodedata
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from thermogear.errors import ModelAssumptionWarning, ThermogearError

#: Header names recognised as the time column [s] and as the temperature column [°C] (case-insensitive).
TIME_COLUMN_NAMES = ("time", "time_s", "t", "t_s")
TEMPERATURE_COLUMN_NAMES = ("temperature_c", "temperature", "temp_c")

#: Relative disagreement accepted between a given rate and the rate of the time column / WAV header.
UNIFORM_SAMPLING_TOLERANCE = 1e-3
#: Largest distance of a time stamp from the uniform grid, in steps (rounded time stamps are fine).
TIME_JITTER_TOLERANCE = 0.1


#: Largest sample magnitude [signal unit]: power spectra and RMS square the samples, and 10³⁰⁸ (the float
#: limit) squared is infinite; 10¹⁰⁰ squared and summed over any record stays finite (samples near 10³⁰⁰
#: crashed --json with NaN, issue 25). No accelerometer unit comes near it.
LARGEST_SAMPLE = 1e100
#: Temperatures a measured temperature column may hold [°C]: those of a case (thermogear.schema.temperature).
TEMPERATURE_RANGE_C = (-60.0, 200.0)


class SignalError(ThermogearError, ValueError):
    """A measured-signal file or array that cannot be analysed (what is wrong, where, and what is allowed)."""


@dataclass(frozen=True)
class Signal:
    """A uniformly sampled signal.

    Attributes
    ----------
    values:
        Samples in the signal's unit (acceleration [m/s²] for the rig).
    sampling_rate_hz:
        Sampling rate [Hz].
    name:
        Column or channel name.
    start_time_s:
        Time of the first sample [s].
    temperature_c:
        Temperature at each sample [°C], or None.
    source:
        File the signal came from ("<array>" for arrays).
    """

    values: np.ndarray
    sampling_rate_hz: float
    name: str = "signal"
    start_time_s: float = 0.0
    temperature_c: np.ndarray | None = None
    source: str = "<array>"

    def __post_init__(self) -> None:
        values = np.asarray(self.values, dtype=float)
        if values.ndim != 1:
            raise SignalError(f"{self.source}: signal '{self.name}' must be one-dimensional, got shape {values.shape}")
        _check_finite(values, self.name, self.source)
        if values.size < 2:
            raise SignalError(f"{self.source}: signal '{self.name}' has {values.size} sample(s); at least 2 needed")
        if not (np.isfinite(self.sampling_rate_hz) and self.sampling_rate_hz > 0):
            raise SignalError(f"{self.source}: sampling rate {self.sampling_rate_hz!r} Hz: allowed > 0")
        object.__setattr__(self, "values", values)
        if self.temperature_c is not None:
            temperature = np.asarray(self.temperature_c, dtype=float)
            if temperature.shape != values.shape:
                raise SignalError(f"{self.source}: temperature has {temperature.size} samples, signal {values.size}")
            _check_finite(temperature, "temperature", self.source)
            _check_temperatures(temperature, self.source)
            object.__setattr__(self, "temperature_c", temperature)

    @property
    def duration_s(self) -> float:
        """Length of the record [s] (number of samples / rate)."""
        return self.values.size / self.sampling_rate_hz

    @property
    def time_s(self) -> np.ndarray:
        """Time of each sample [s]."""
        return self.start_time_s + np.arange(self.values.size) / self.sampling_rate_hz

    def between(self, start_s: float, stop_s: float) -> "Signal":
        """The part of the record with start_s ≤ t < stop_s [s]."""
        time = self.time_s
        mask = (time >= start_s) & (time < stop_s)
        if np.count_nonzero(mask) < 2:
            raise SignalError(f"{self.source}: window {start_s}–{stop_s} s holds fewer than 2 samples "
                              f"(record {self.start_time_s}–{self.start_time_s + self.duration_s} s)")
        first = int(np.argmax(mask))
        return Signal(self.values[mask], self.sampling_rate_hz, self.name, float(time[first]),
                      None if self.temperature_c is None else self.temperature_c[mask], self.source)


def read_signal(path: str | Path, column: str | None = None, rate_hz: float | None = None,
                scale: float = 1.0) -> Signal:
    """Read one signal from a CSV or WAV file (by its suffix). See :func:`read_csv_signal`, :func:`read_wav_signal`."""
    from thermogear.errors import shown_value  # noqa: PLC0415
    from thermogear.text_files import is_existing_file  # noqa: PLC0415

    path = Path(path)
    if not is_existing_file(path):
        raise SignalError(f"{shown_value(str(path))}: no such file")
    if not (np.isfinite(scale) and scale != 0):
        raise SignalError(f"--scale {scale!r}: allowed a finite non-zero number (signal unit per full scale)")
    suffix = path.suffix.lower()
    if suffix == ".wav":
        return read_wav_signal(path, column, scale=scale, rate_hz=rate_hz)
    if suffix in (".csv", ".txt", ".tsv"):
        signal = read_csv_signal(path, column, rate_hz)
        if scale != 1.0:
            with np.errstate(over="ignore"):  # an overflow is an infinite sample, refused by Signal
                scaled = signal.values * scale
            signal = Signal(scaled, signal.sampling_rate_hz, signal.name, signal.start_time_s,
                            signal.temperature_c, signal.source)
        return signal
    raise SignalError(f"{path}: file type '{suffix}' not supported; allowed .csv, .txt, .tsv, .wav")


def read_csv_signal(path: str | Path, column: str | None = None, rate_hz: float | None = None) -> Signal:
    """Read a signal column of a CSV file with a header line.

    Parameters
    ----------
    path:
        The file. Delimiter comma, semicolon or tab (detected); decimal point '.'.
    column:
        Signal column; default the first column that is neither time nor temperature.
    rate_hz:
        Sampling rate [Hz]. Needed when the file has no time column; when both are given they must agree to 0.1 %.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as error:
        raise SignalError(f"{path}: not UTF-8 text (byte {error.start} cannot be decoded; a binary file, or text "
                          "saved as latin-1? save it as UTF-8)") from None
    except OSError as error:
        raise SignalError(f"{path}: cannot be read ({error.strerror or error})") from None
    return parse_csv_signal(text, column, rate_hz, source=str(path))


def parse_csv_signal(text: str, column: str | None = None, rate_hz: float | None = None,
                     source: str = "<text>") -> Signal:
    """:func:`read_csv_signal` on the text of a CSV file."""
    lines = [line for line in text.splitlines() if line.strip()]
    if not lines:
        raise SignalError(f"{source}: the file is empty (a header line and samples are needed)")
    delimiter = _delimiter(lines[0])
    rows = list(csv.reader(io.StringIO("\n".join(lines)), delimiter=delimiter))
    header = [name.strip() for name in rows[0]]
    body = rows[1:]
    if any(unicodedata.category(character) == "Cc" for name in header for character in name):
        # the column names are printed: a terminal would act on an escape sequence (and a binary file is no CSV)
        raise SignalError(f"{source}: the header line holds control characters; a CSV header names its columns "
                          "in printable text (the file's content is not shown)")
    if not body:
        raise SignalError(f"{source}: no samples below the header {header}")
    if len(set(header)) != len(header) or any(not name for name in header):
        raise SignalError(f"{source}: header {header} has empty or repeated column names")
    for index, row in enumerate(body):
        if len(row) != len(header):
            raise SignalError(f"{source}: row {index + 2} has {len(row)} fields, the header has {len(header)}")
    table = np.array(body, dtype=str)
    lower = [name.lower() for name in header]
    time_index = next((i for i, name in enumerate(lower) if name in TIME_COLUMN_NAMES), None)
    temperature_index = next((i for i, name in enumerate(lower) if name in TEMPERATURE_COLUMN_NAMES), None)
    signal_names = [name for i, name in enumerate(header) if i not in (time_index, temperature_index)]
    if column is None:
        if not signal_names:
            raise SignalError(f"{source}: no signal column in {header} (only time/temperature)")
        column = signal_names[0]
    if column not in header:
        raise SignalError(f"{source}: column '{column}' not found; columns are {header}")
    values = _numeric_column(table[:, header.index(column)], column, source)
    temperature = (None if temperature_index is None or header[temperature_index] == column
                   else _numeric_column(table[:, temperature_index], header[temperature_index], source))
    start = 0.0
    if time_index is not None:
        time = _numeric_column(table[:, time_index], header[time_index], source)
        rate_from_time, start = _rate_from_time(time, header[time_index], source)
        if rate_hz is not None and abs(rate_hz - rate_from_time) > UNIFORM_SAMPLING_TOLERANCE * rate_from_time:
            raise SignalError(f"{source}: --rate {rate_hz} Hz disagrees with the time column "
                              f"'{header[time_index]}' ({rate_from_time:.6g} Hz); give one or make them agree")
        rate_hz = rate_from_time
    elif rate_hz is None:
        raise SignalError(f"{source}: no time column (one of {', '.join(TIME_COLUMN_NAMES)}) and no sampling "
                          "rate given: add a time column in seconds or pass the rate (--rate HZ)")
    return Signal(values, float(rate_hz), column, start, temperature, source)


def read_wav_signal(path: str | Path, column: str | None = None, scale: float = 1.0,
                    rate_hz: float | None = None) -> Signal:
    """Read a channel of a WAV file (``column`` = ``channel_N`` or ``N``; default channel 0).

    Integer samples are scaled to ±1 full scale, then multiplied by ``scale`` [signal unit per full scale].
    """
    from scipy.io import wavfile

    path = Path(path)
    try:
        with warnings.catch_warnings():
            # SciPy's own notes (a file cut short, a metadata chunk skipped) are not shown: a short file is said
            # below in thermogear's words, and the skipped chunks hold no samples
            warnings.simplefilter("ignore", wavfile.WavFileWarning)
            file_rate, data = wavfile.read(path)
    except Exception as error:  # noqa: BLE001  (SciPy's reader fails on damaged bytes with UnboundLocalError,
        # struct.error and others, not only ValueError: any failure to parse is "not a readable WAV", issue 25)
        raise SignalError(f"{path}: not a readable WAV file ({type(error).__name__}; a truncated or damaged "
                          "file?)") from None
    if rate_hz is not None and abs(rate_hz - file_rate) > UNIFORM_SAMPLING_TOLERANCE * file_rate:
        raise SignalError(f"{path}: --rate {rate_hz} Hz disagrees with the WAV header ({file_rate} Hz)")
    if data.ndim == 0 or data.shape[0] < 2:
        frames = 0 if data.ndim == 0 else data.shape[0]
        raise SignalError(f"{path}: the WAV file holds {frames} frame(s); at least 2 samples are needed")
    if not file_rate > 0:
        raise SignalError(f"{path}: the WAV header gives a sampling rate of {file_rate} Hz: allowed > 0")
    data = data.reshape(data.shape[0], -1)
    channels = [f"channel_{i}" for i in range(data.shape[1])]
    name = channels[0] if column is None else (f"channel_{column}" if column.isdigit() else column)
    if name not in channels:
        raise SignalError(f"{path}: column '{column}' not found; channels are {channels}")
    if not (np.isfinite(scale) and scale != 0):
        raise SignalError(f"{path}: scale {scale!r}: allowed a finite non-zero number (unit per full scale)")
    with np.errstate(over="ignore"):  # an overflow is an infinite sample, refused by Signal
        values = wav_full_scale(data[:, channels.index(name)]) * scale
    announced = wav_announced_frames(path)
    if announced is not None and announced > data.shape[0]:
        warnings.warn(f"{path}: the WAV file is cut short: its header announces {announced} frames, the file holds "
                      f"{data.shape[0]} ({data.shape[0] / file_rate:.4g} of {announced / file_rate:.4g} s); the "
                      "analysis uses the samples present — copy or export the recording again for the whole record",
                      ModelAssumptionWarning, stacklevel=3)
    return Signal(values, float(file_rate), name, 0.0, None, str(path))


def wav_announced_frames(path: Path) -> int | None:
    """Frames the ``data`` chunk's header of a RIFF/WAVE file announces (its byte size over the ``fmt`` chunk's
    block align), or None when the chunks cannot be read that far (the reader has then refused the file)."""
    with open(path, "rb") as handle:
        head = handle.read(12)
        if len(head) < 12 or head[:4] not in (b"RIFF", b"RIFX") or head[8:12] != b"WAVE":
            return None
        order = "little" if head[:4] == b"RIFF" else "big"
        block_align = None
        while True:
            chunk = handle.read(8)
            if len(chunk) < 8:
                return None
            size = int.from_bytes(chunk[4:8], order)
            if chunk[:4] == b"fmt ":
                body = handle.read(size + size % 2)
                block_align = int.from_bytes(body[12:14], order) if len(body) >= 14 else None
            elif chunk[:4] == b"data":  # 0xFFFFFFFF: a streaming writer's "until the end of the file"
                return size // block_align if block_align and size != 0xFFFFFFFF else None
            else:
                handle.seek(size + size % 2, 1)


def wav_full_scale(samples: np.ndarray) -> np.ndarray:
    """WAV samples as fractions of full scale [–]: int16 / 2¹⁵, int32 / 2³¹, uint8 (x − 128) / 2⁷, floats as is."""
    samples = np.asarray(samples)
    if samples.dtype == np.uint8:
        return (samples.astype(float) - 128.0) / 128.0
    if np.issubdtype(samples.dtype, np.integer):
        return samples.astype(float) / float(-np.iinfo(samples.dtype).min)
    return samples.astype(float)


def _delimiter(header_line: str) -> str:
    counts = {delimiter: header_line.count(delimiter) for delimiter in (",", ";", "\t")}
    best = max(counts, key=counts.get)
    return best if counts[best] else ","


def _numeric_column(strings: np.ndarray, name: str, source: str) -> np.ndarray:
    try:
        values = np.char.strip(strings).astype(float)
    except ValueError:
        bad = next(i for i, text in enumerate(strings) if not _is_number(text))
        raise SignalError(f"{source}: column '{name}' row {bad + 2} is not a number") from None
    _check_finite(values, name, source)
    return values


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _check_finite(values: np.ndarray, name: str, source: str) -> None:
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        raise SignalError(f"{source}: column '{name}' has {bad.size} NaN/infinite value(s), the first at sample "
                          f"{bad[0]} (CSV row {bad[0] + 2}); remove or fill them before the analysis")
    bad = np.flatnonzero(np.abs(values) > LARGEST_SAMPLE)
    if bad.size:
        raise SignalError(f"{source}: column '{name}' has {bad.size} value(s) beyond ±{LARGEST_SAMPLE:g}, the "
                          f"first at sample {bad[0]}: the spectra square the samples, which would overflow; give "
                          "the signal in a unit of sensible size (--scale)")


def _check_temperatures(values: np.ndarray, source: str) -> None:
    low, high = TEMPERATURE_RANGE_C
    bad = np.flatnonzero((values < low) | (values > high))
    if bad.size:
        raise SignalError(f"{source}: column 'temperature' has {bad.size} value(s) outside {low:g} … {high:g} °C "
                          f"(the first at sample {bad[0]}): not a gearbox temperature in °C")


def _rate_from_time(time: np.ndarray, name: str, source: str) -> tuple[float, float]:
    """Sampling rate [Hz] and start [s] from a time column that must rise in uniform steps."""
    if time.size < 2:
        raise SignalError(f"{source}: column '{name}' has fewer than 2 time stamps")
    steps = np.diff(time)
    bad = np.flatnonzero(steps <= 0)
    if bad.size:
        kind = "duplicate" if steps[bad[0]] == 0 else "decreasing (unsorted)"
        raise SignalError(f"{source}: column '{name}' has {kind} time stamps at rows {bad[0] + 2}–{bad[0] + 3} "
                          f"({time[bad[0]]!r}, {time[bad[0] + 1]!r}); time must rise strictly")
    step = (time[-1] - time[0]) / (time.size - 1)
    deviation = np.abs(time - (time[0] + step * np.arange(time.size)))
    if np.max(deviation) > TIME_JITTER_TOLERANCE * step:
        worst = int(np.argmax(deviation))
        raise SignalError(f"{source}: column '{name}' is not uniformly sampled (time stamp at row {worst + 2} is "
                          f"{deviation[worst]:.3g} s off the uniform grid of step {step:.6g} s; allowed "
                          f"{TIME_JITTER_TOLERANCE:.0%} of a step); resample to a uniform rate first")
    return 1.0 / step, float(time[0])
