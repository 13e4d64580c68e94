"""Table-3-like summaries of a measured signal over time windows (Luo & Li 2020 Table 3 and Fig. 18).

For each window: mean temperature (when the record has one), mean and maximum amplitude of the time signal
(:func:`~thermogear.experiment.spectrum.mean_amplitude`, :func:`~thermogear.experiment.spectrum.max_amplitude`),
RMS, and the strongest interpolated spectral peak in a band (its frequency is the "resonance frequency" and its
amplitude the "spectrum peak" of the paper's Fig. 18).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.experiment.signals import Signal, SignalError
from thermogear.experiment.spectrum import (Spectrum, max_amplitude, mean_amplitude, rms_amplitude, spectrum)


@dataclass(frozen=True)
class WindowRow:
    """One row of the window table (time [s], temperature [°C], amplitudes [signal unit], frequency [Hz])."""

    start_s: float
    stop_s: float
    temperature_c: float | None
    mean_amplitude: float
    max_amplitude: float
    rms_amplitude: float
    peak_frequency_hz: float
    peak_amplitude: float

    def as_dict(self) -> dict:
        return dict(self.__dict__)


def parse_windows(spec: str, signal: Signal) -> list[tuple[float, float]]:
    """Time windows [s] from a specification.

    ``"N"``: N equal consecutive windows over the record; ``"A:B,C:D"``: windows from A to B s, C to D s, …
    (times on the record's time axis).
    """
    text = spec.strip()
    start, stop = signal.start_time_s, signal.start_time_s + signal.duration_s
    if text.isdigit():
        count = int(text)
        if not 1 <= count <= signal.values.size // 16:
            raise SignalError(f"--windows {spec}: allowed 1 … {signal.values.size // 16} windows (≥ 16 samples each)")
        edges = np.linspace(start, stop, count + 1)
        return [(float(a), float(b)) for a, b in zip(edges[:-1], edges[1:])]
    windows = []
    for part in text.split(","):
        pieces = part.split(":")
        try:
            low, high = (float(piece) for piece in pieces)
        except ValueError:
            raise SignalError(f"--windows {spec}: '{part}' is not START:STOP in seconds (or give a count N)") from None
        if not low < high:
            raise SignalError(f"--windows {spec}: window {part} must have START < STOP")
        windows.append((low, high))
    return windows


def window_table(signal: Signal, windows: list[tuple[float, float]], band: tuple[float, float] | None = None,
                 method: str = "fft", segment_length: int | None = None) -> list[WindowRow]:
    """The Table-3-like summary of ``signal`` over ``windows`` [s]; the spectral peak is searched in ``band`` [Hz]."""
    rows = []
    for low, high in windows:
        part = signal.between(low, high)
        spectrum_ = window_spectrum(part, method, segment_length)
        peak = spectrum_.peak_in_band(band)
        temperature = None if part.temperature_c is None else float(np.mean(part.temperature_c))
        rows.append(WindowRow(low, high, temperature, mean_amplitude(part.values), max_amplitude(part.values),
                              rms_amplitude(part.values), peak.frequency_hz, peak.amplitude))
    return rows


def window_spectrum(part: Signal, method: str, segment_length: int | None) -> Spectrum:
    """Spectrum of one window (Welch segments no longer than the window)."""
    length = None if segment_length is None else min(segment_length, part.values.size)
    return spectrum(part, method, length)


def window_spectra(signal: Signal, windows: list[tuple[float, float]], method: str = "fft",
                   segment_length: int | None = None) -> list[Spectrum]:
    """The spectrum of each window [s] (for a waterfall plot)."""
    return [window_spectrum(signal.between(low, high), method, segment_length) for low, high in windows]
