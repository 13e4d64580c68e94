"""Amplitude spectra of mesh-cycle signals (transmission error, velocity, loads).

A periodic steady state is a Fourier series in the mesh frequency f_m = 1/T: :func:`harmonic_spectrum`
resamples one period uniformly and returns the one-sided amplitudes of the harmonics 0, f_m, 2 f_m, … (the
0-th is the mean). For a record that is not periodic (a transient) :func:`signal_spectrum` uses a Hann window.
"""

from __future__ import annotations

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["harmonic_spectrum", "one_sided_amplitudes", "signal_spectrum", "uniform_period_grid"]


def uniform_period_grid(period: float, points: int) -> np.ndarray:
    """``points`` equally spaced times [s] on [0, T) (the end point, equal to the start, left out)."""
    if int(points) != points or points < 4:
        raise ProblemError("points", points, "integer >= 4", "samples per period for the Fourier transform")
    return np.arange(int(points)) * (period / int(points))


def one_sided_amplitudes(values: np.ndarray) -> np.ndarray:
    """One-sided amplitudes of uniformly sampled values over whole periods: mean, then 2|X_j|/N [same unit]."""
    count = values.shape[-1]
    transform = np.fft.rfft(values, axis=-1) / count
    amplitude = np.abs(transform)
    amplitude[..., 1:] *= 2.0
    if count % 2 == 0:
        amplitude[..., -1] *= 0.5  # the Nyquist bin has no negative-frequency twin
    return amplitude


def harmonic_spectrum(time: np.ndarray, values: np.ndarray, period: float, points: int = 1024
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Harmonic amplitudes of a periodic signal sampled on one period.

    ``time`` [s] on [0, T] (increasing); ``values`` of the same length (or (…, len)); linear interpolation onto
    ``points`` uniform samples. Returns (frequencies [Hz] = j/T, amplitudes), j = 0 … points/2.
    """
    grid = uniform_period_grid(period, points)
    resampled = np.interp(grid, np.asarray(time, dtype=float), np.asarray(values, dtype=float))
    return np.arange(grid.size // 2 + 1) / period, one_sided_amplitudes(resampled)


def signal_spectrum(time: np.ndarray, values: np.ndarray, points: int | None = None
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Hann-windowed amplitude spectrum of a non-periodic record (e.g. a transient from rest).

    The record is resampled uniformly (``points`` samples, default its own length); the mean is removed and the
    window's coherent gain (0.5) corrected, so a steady sine of amplitude a shows a peak near a.
    """
    time = np.asarray(time, dtype=float)
    values = np.asarray(values, dtype=float)
    count = int(points) if points is not None else time.size
    if count < 4:
        raise ProblemError("points", count, ">= 4", "samples for the Fourier transform")
    grid = np.linspace(time[0], time[-1], count)
    resampled = np.interp(grid, time, values)
    resampled = resampled - resampled.mean()
    window = np.hanning(count)
    amplitude = 2.0 * np.abs(np.fft.rfft(resampled * window)) / window.sum()
    step = (time[-1] - time[0]) / (count - 1)
    return np.fft.rfftfreq(count, d=step), amplitude
