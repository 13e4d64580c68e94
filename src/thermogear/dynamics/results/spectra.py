"""Amplitude spectra of mesh-cycle signals (transmission error, velocity, loads).

A periodic steady state is a Fourier series in the mesh frequency f_m = 1/T: :func:`harmonic_spectrum`
resamples one period uniformly and returns the one-sided amplitudes of the harmonics 0, f_m, 2 f_m, … (the
0-th is the mean). For a record that is not periodic (a transient) :func:`signal_spectrum` uses a Hann window.
"""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.results.metric_formulas import mean_and_rms
from thermogear.errors import ProblemError

__all__ = ["harmonic_spectrum", "one_sided_amplitudes", "right_continuous", "signal_spectrum", "time_mean_and_rms",
           "uniform_period_grid"]


def right_continuous(time: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The samples of a piecewise-smooth signal with strictly increasing times, ready for ``np.interp``.

    The solvers sample both sides of every jump of the mesh stiffness at the same time (the value before and the
    value after). ``np.interp`` is only defined for increasing abscissae; with repeated ones its result depends on
    how ties are ordered, which is not part of NumPy's contract (and ``period=`` sorts them with an unstable
    sort). Of each group of equal times only the last sample (the value after the jump) is kept, so the signal
    is read right-continuously, the same on every NumPy version and CPU. ``values`` may be (…, len(time)).
    """
    time = np.asarray(time, dtype=float)
    values = np.asarray(values, dtype=float)
    if time.size < 2:
        return time, values
    keep = np.append(np.diff(time) > 0.0, True)
    return time[keep], values[..., keep]


def time_mean_and_rms(time: np.ndarray, values: np.ndarray, span: float | None = None) -> tuple[float, float]:
    """Time mean and RMS about it [unit of ``values``] of a signal sampled on increasing ``time`` [s], over ``span``
    [s]: the record's, time[-1] − time[0], unless given (the nominal period of a record of one period).

    Trapezoidal rule on the samples as they are: a jump sampled twice at one time is a segment of zero width and
    carries no weight, so the integral of a piecewise-smooth signal converges as O(h²) whatever the jumps. The RMS
    is :func:`~thermogear.dynamics.results.metric_formulas.mean_and_rms` (the compiled sweep kernel's formula) about
    the trapezoidal mean, where the first moment is zero: two passes, no cancellation."""
    time = np.asarray(time, dtype=float)
    values = np.asarray(values, dtype=float)
    if span is None:
        span = time[-1] - time[0]
    mean = float(np.trapezoid(values, time) / span)
    return mean_and_rms(mean, 0.0, float(np.trapezoid((values - mean) ** 2, time)), span)


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
    time, values = right_continuous(time, values)
    resampled = np.interp(grid, time, values)
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
    resampled = np.interp(grid, *right_continuous(time, values))
    resampled = resampled - resampled.mean()
    window = np.hanning(count)
    amplitude = 2.0 * np.abs(np.fft.rfft(resampled * window)) / window.sum()
    step = (time[-1] - time[0]) / (count - 1)
    return np.fft.rfftfreq(count, d=step), amplitude
