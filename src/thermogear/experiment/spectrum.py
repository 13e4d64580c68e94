"""Amplitude spectra of measured signals, interpolated spectral peaks, mesh orders and side bands.

Spectra come from :func:`scipy.signal.welch` (averaged over Hann-windowed segments) or
:func:`scipy.signal.periodogram` (one Hann-windowed FFT of the whole record), both with ``scaling="spectrum"``
and the mean removed. The one-sided power spectrum P [unit²] they return is turned into the **amplitude
spectrum** A = √(2 P): the amplitude of a sine whose frequency falls on the bin centre.

Peaks between bins. With the (periodic) Hann window a sine of amplitude a at ``k + δ`` bins gives
|X(k + m)| ∝ a · D(m − δ) with D(ν) = sinc(ν) / (1 − ν²) (sinc(ν) = sin πν / πν). For the largest bin k and the
larger neighbour k ± 1 the magnitude ratio α = |X(k ± 1)| / |X(k)| ∈ [1/2, 1] fixes the offset exactly,
δ = ±(2α − 1)/(α + 1) (Grandke 1983, "Interpolation algorithms for discrete Fourier transforms of weighted
signals", IEEE Trans. Instrum. Meas. 32(2):350–355), and the amplitude follows as a = A(k) / D(δ). Both are
exact for one tone in the limit of a long window; the residual errors (the tone's own negative-frequency image,
the finite window length, other tones' leakage and noise) are measured in ``tests/unit/test_spectrum.py``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

# scipy.signal (0.4 s to import) is imported where a spectrum is taken: the rig data of this package are read by
# the report, which takes no spectrum
from thermogear.experiment.signals import Signal, SignalError

WINDOW = "hann"


@dataclass(frozen=True)
class Peak:
    """A spectral peak: frequency [Hz] and amplitude of the sine it stands for [signal unit]."""

    frequency_hz: float
    amplitude: float

    def as_dict(self) -> dict[str, float]:
        return {"frequency_hz": self.frequency_hz, "amplitude": self.amplitude}


@dataclass(frozen=True)
class Spectrum:
    """One-sided Hann-window spectrum of a signal.

    Attributes
    ----------
    frequency_hz:
        Bin centres [Hz].
    power:
        Power spectrum ("spectrum" scaling) [unit²]: the mean square of a sine on a bin centre.
    method:
        "welch" (averaged segments) or "fft" (one window over the record).
    segment_length:
        Samples per FFT window.
    segments:
        Number of averaged windows (1 for "fft").
    """

    frequency_hz: np.ndarray
    power: np.ndarray
    method: str
    segment_length: int
    segments: int
    sampling_rate_hz: float = field(default=float("nan"))

    @property
    def resolution_hz(self) -> float:
        """Bin width [Hz] = sampling rate / segment length."""
        return float(self.frequency_hz[1] - self.frequency_hz[0])

    @property
    def amplitude(self) -> np.ndarray:
        """Amplitude spectrum √(2 P) [signal unit]: the amplitude of a sine on each bin centre."""
        return np.sqrt(2.0 * self.power)

    def peaks(self, band: tuple[float, float] | None = None, max_peaks: int = 10,
              relative_threshold: float = 0.01) -> list[Peak]:
        """Interpolated local maxima in ``band`` [Hz], strongest first.

        Only peaks of at least ``relative_threshold`` × the strongest one in the band are kept, at most
        ``max_peaks`` of them.
        """
        indices = _local_maxima(self.power, self._band_mask(band))
        if indices.size == 0:
            return []
        frequency, amplitude = interpolate_peaks(self.power, indices, self.resolution_hz, self.frequency_hz[0])
        order = np.argsort(-amplitude, kind="stable")
        keep = order[amplitude[order] >= relative_threshold * amplitude[order[0]]][:max_peaks]
        return [Peak(float(frequency[i]), float(amplitude[i])) for i in keep]

    def peak_in_band(self, band: tuple[float, float] | None = None) -> Peak:
        """The strongest interpolated peak in ``band`` [Hz] (the largest bin where the band holds no local maximum)."""
        mask = self._band_mask(band)
        found = self.peaks(band, max_peaks=1, relative_threshold=0.0)
        if found:
            return found[0]
        index = int(np.flatnonzero(mask)[np.argmax(self.power[mask])])
        return Peak(float(self.frequency_hz[index]), float(self.amplitude[index]))

    def nearest_peak(self, frequency_hz: float, search_bins: float = 2.0) -> tuple[Peak, bool]:
        """The strongest interpolated peak within ± ``search_bins`` bins of ``frequency_hz``.

        Returns the peak and True, or (the bin value at ``frequency_hz``, False) when no local maximum is there.
        """
        half = search_bins * self.resolution_hz
        mask = (self.frequency_hz >= frequency_hz - half) & (self.frequency_hz <= frequency_hz + half)
        indices = _local_maxima(self.power, mask)
        if indices.size:
            frequency, amplitude = interpolate_peaks(self.power, indices, self.resolution_hz, self.frequency_hz[0])
            best = int(np.argmax(amplitude))
            return Peak(float(frequency[best]), float(amplitude[best])), True
        index = int(np.argmin(np.abs(self.frequency_hz - frequency_hz)))
        return Peak(float(frequency_hz), float(self.amplitude[index])), False

    def _band_mask(self, band: tuple[float, float] | None) -> np.ndarray:
        if band is None:
            return np.ones(self.frequency_hz.size, dtype=bool)
        low, high = band
        if not (0 <= low < high):
            raise SignalError(f"band {low}:{high} Hz: allowed 0 ≤ LO < HI")
        mask = (self.frequency_hz >= low) & (self.frequency_hz <= high)
        if not mask.any():
            raise SignalError(f"band {low}:{high} Hz holds no spectral line (lines {self.frequency_hz[0]:.6g}–"
                              f"{self.frequency_hz[-1]:.6g} Hz every {self.resolution_hz:.6g} Hz)")
        return mask

    def plot(self, ax=None, label: str | None = None):
        """Amplitude spectrum; returns the figure."""
        from thermogear.experiment.plots import plot_spectrum

        return plot_spectrum(self, ax=ax, label=label)


def hann_kernel(offset_bins: np.ndarray | float) -> np.ndarray:
    """Normalised magnitude of the Hann window's transform at ``offset_bins`` from a tone [–]:
    D(ν) = |sinc(ν) / (1 − ν²)|, D(0) = 1, D(±1) = 1/2 (Grandke 1983)."""
    nu = np.asarray(offset_bins, dtype=float)
    near_one = np.isclose(np.abs(nu), 1.0)
    safe = np.where(near_one, 0.0, nu)
    value = np.abs(np.sinc(safe) / (1.0 - safe**2))
    return np.where(near_one, 0.5, value)


def interpolate_peak(power: np.ndarray, index: int, resolution_hz: float, first_frequency_hz: float = 0.0) -> Peak:
    """Frequency [Hz] and sine amplitude of a Hann-window peak at bin ``index`` (Grandke's ratio, module doc)."""
    frequency, amplitude = interpolate_peaks(power, np.array([index]), resolution_hz, first_frequency_hz)
    return Peak(float(frequency[0]), float(amplitude[0]))


def interpolate_peaks(power: np.ndarray, indices: np.ndarray, resolution_hz: float,
                      first_frequency_hz: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised :func:`interpolate_peak`: frequencies [Hz] and sine amplitudes of the peaks at bins ``indices``.

    Bins at the ends of the spectrum are not interpolated (frequency of the bin, amplitude √(2 P)).
    """
    magnitude = np.sqrt(np.maximum(np.asarray(power, dtype=float), 0.0))
    indices = np.asarray(indices, dtype=int)
    centre = magnitude[indices]
    interior = (indices > 0) & (indices < magnitude.size - 1) & (centre > 0)
    left = magnitude[np.clip(indices - 1, 0, magnitude.size - 1)]
    right = magnitude[np.clip(indices + 1, 0, magnitude.size - 1)]
    sign = np.where(right >= left, 1.0, -1.0)
    ratio = np.clip(np.maximum(left, right) / np.where(centre > 0, centre, 1.0), 0.0, 1.0)
    offset = np.where(interior, np.clip(sign * (2.0 * ratio - 1.0) / (ratio + 1.0), -0.5, 0.5), 0.0)
    amplitude = np.sqrt(2.0) * centre / hann_kernel(offset)
    return first_frequency_hz + (indices + offset) * resolution_hz, amplitude


def spectrum(signal: Signal, method: str = "welch", segment_length: int | None = None,
             overlap: float = 0.5) -> Spectrum:
    """Hann-window amplitude spectrum of a signal by Welch's method or one FFT over the whole record.

    Parameters
    ----------
    method:
        "welch" (default segment length: a quarter of the record, 50 % overlap, 7 averages) or "fft".
    segment_length:
        Samples per segment for Welch (≥ 16, ≤ the record).
    overlap:
        Fraction of a segment shared with the next, in [0, 1).
    """
    estimate = SPECTRUM_METHODS.get(method)
    if estimate is None:
        raise SignalError(f"spectrum method '{method}': allowed 'welch' or 'fft'")
    return estimate(signal.values, signal.sampling_rate_hz, segment_length, overlap)


def _periodogram(values: np.ndarray, rate: float, segment_length: int | None, overlap: float) -> Spectrum:
    """One Hann-windowed FFT over the whole record (``"fft"``; the segment options do not apply)."""
    from scipy import signal as scipy_signal  # noqa: PLC0415
    frequency, power = scipy_signal.periodogram(values, fs=rate, window=WINDOW, detrend="constant",
                                                scaling="spectrum")
    return Spectrum(frequency, power, "fft", values.size, 1, rate)


def _welch(values: np.ndarray, rate: float, segment_length: int | None, overlap: float) -> Spectrum:
    """Welch's average of Hann-windowed segments (``"welch"``)."""
    length = max(16, values.size // 4) if segment_length is None else int(segment_length)
    if not 16 <= length <= values.size:
        raise SignalError(f"segment length {length}: allowed 16 … {values.size} samples (the record)")
    if not 0 <= overlap < 1:
        raise SignalError(f"overlap {overlap}: allowed [0, 1)")
    step = length - int(round(overlap * length))
    from scipy import signal as scipy_signal  # noqa: PLC0415
    frequency, power = scipy_signal.welch(values, fs=rate, window=WINDOW, nperseg=length,
                                          noverlap=length - step, detrend="constant", scaling="spectrum")
    segments = 1 + (values.size - length) // step
    return Spectrum(frequency, power, "welch", length, segments, rate)


#: The spectrum estimates by ``method`` name: the one place the names are compared.
SPECTRUM_METHODS = {"welch": _welch, "fft": _periodogram}


def mean_amplitude(values: np.ndarray) -> float:
    """Mean absolute value of the signal about its mean, mean |a − ā| [signal unit] (2a/π for a sine of amplitude a)."""
    values = np.asarray(values, dtype=float)
    return float(np.mean(np.abs(values - values.mean())))


def max_amplitude(values: np.ndarray) -> float:
    """Largest absolute value of the signal about its mean, max |a − ā| [signal unit] (a for a sine)."""
    values = np.asarray(values, dtype=float)
    return float(np.max(np.abs(values - values.mean())))


def rms_amplitude(values: np.ndarray) -> float:
    """Root mean square of the signal about its mean [signal unit] (a/√2 for a sine)."""
    values = np.asarray(values, dtype=float)
    return float(np.sqrt(np.mean((values - values.mean()) ** 2)))


def mesh_orders(spectrum_: Spectrum, mesh_frequency_hz: float, orders: int = 3,
                shaft_frequency_hz: float | None = None, sidebands: int = 2,
                search_bins: float = 2.0) -> list[dict]:
    """Amplitude at the mesh-frequency orders n·f_mesh and at their side bands n·f_mesh ± j·f_shaft.

    Each line is searched within ± ``search_bins`` bins of its nominal frequency; a row has ``order``,
    ``sideband`` (j, signed; 0 for the order itself), ``nominal_hz``, ``frequency_hz``, ``amplitude`` and
    ``found`` (False: no local maximum there, the amplitude is the bin value at the nominal frequency).
    Lines beyond the Nyquist frequency are left out.
    """
    if not (np.isfinite(mesh_frequency_hz) and mesh_frequency_hz > 0):
        raise SignalError(f"mesh frequency {mesh_frequency_hz!r} Hz: allowed > 0")
    if shaft_frequency_hz is not None and not (np.isfinite(shaft_frequency_hz) and shaft_frequency_hz > 0):
        raise SignalError(f"shaft frequency {shaft_frequency_hz!r} Hz: allowed > 0")
    rows = []
    top = spectrum_.frequency_hz[-1]
    side = range(-sidebands, sidebands + 1) if shaft_frequency_hz else range(0, 1)
    for order in range(1, orders + 1):
        for j in side:
            nominal = order * mesh_frequency_hz + j * (shaft_frequency_hz or 0.0)
            if not 0 < nominal < top:
                continue
            peak, found = spectrum_.nearest_peak(nominal, search_bins)
            rows.append({"order": order, "sideband": j, "nominal_hz": nominal,
                         "frequency_hz": peak.frequency_hz, "amplitude": peak.amplitude, "found": found})
    return rows


def _local_maxima(power: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Indices of interior local maxima of ``power`` that lie in ``mask``."""
    from scipy import signal as scipy_signal  # noqa: PLC0415
    indices, _ = scipy_signal.find_peaks(power)
    return indices[mask[indices]]
