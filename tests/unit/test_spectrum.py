"""Spectral analysis on synthetic signals with known content.

Acceptance (issue 8): recovered frequency within a tenth of the bin width, amplitude within 1 %, over a range of
sampling rates and record lengths; noise, several tones, beating and a slowly drifting resonance.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from thermogear.experiment.signals import Signal, SignalError
from thermogear.experiment.spectrum import (hann_kernel, interpolate_peak, max_amplitude, mean_amplitude,
                                            mesh_orders, rms_amplitude, spectrum)
from thermogear.experiment.table import parse_windows, window_table

FREQUENCY_TOLERANCE_BINS = 0.1
AMPLITUDE_TOLERANCE = 0.01

RATES = [1000.0, 5120.0, 25600.0, 51200.0]
LENGTHS = [512, 4096, 30000]
METHODS = ["fft", "welch"]


def tone(amplitude, frequency, rate, n, phase=0.3):
    return amplitude * np.sin(2 * np.pi * frequency * np.arange(n) / rate + phase)


def bin_width(rate, n, method):
    return rate / (n if method == "fft" else max(16, n // 4))


@pytest.mark.parametrize("rate, n, method", list(itertools.product(RATES, LENGTHS, METHODS)))
def test_single_tone_frequency_and_amplitude(rate, n, method):
    rng = np.random.default_rng(int(rate) + n)
    width = bin_width(rate, n, method)
    for _ in range(8):
        frequency = rng.uniform(6 * width, rate / 2 - 6 * width)
        amplitude = rng.uniform(0.05, 5.0)
        result = spectrum(Signal(tone(amplitude, frequency, rate, n, rng.uniform(0, 2 * np.pi)), rate), method)
        assert result.resolution_hz == pytest.approx(width)
        peak = result.peaks()[0]
        assert abs(peak.frequency_hz - frequency) <= FREQUENCY_TOLERANCE_BINS * width
        assert peak.amplitude == pytest.approx(amplitude, rel=AMPLITUDE_TOLERANCE)


@pytest.mark.parametrize("offset", [0.0, 0.1, 0.25, 0.4, 0.5, -0.3])
def test_tone_between_bins_at_every_offset(offset):
    rate, n = 10000.0, 2048
    width = rate / n
    frequency = (200 + offset) * width
    peak = spectrum(Signal(tone(1.7, frequency, rate, n), rate), "fft").peaks()[0]
    assert abs(peak.frequency_hz - frequency) <= 0.01 * width  # exact estimator: far inside the 0.1-bin target
    assert peak.amplitude == pytest.approx(1.7, rel=1e-3)


@pytest.mark.parametrize("rate, n", [(5120.0, 8192), (25600.0, 65536)])
@pytest.mark.parametrize("method", METHODS)
def test_tones_in_white_noise(rate, n, method):
    """Three tones of unequal amplitude in white noise of 10 % of the weakest tone's amplitude (std)."""
    rng = np.random.default_rng(7)
    width = bin_width(rate, n, method)
    frequencies = np.array([0.11, 0.23, 0.37]) * rate + rng.uniform(0, 1, 3) * width
    amplitudes = np.array([1.0, 0.4, 2.5])
    values = sum(tone(a, f, rate, n, rng.uniform(0, 6)) for a, f in zip(amplitudes, frequencies))
    values = values + rng.normal(0.0, 0.1 * amplitudes.min(), n)
    peaks = spectrum(Signal(values, rate), method).peaks(max_peaks=3)
    order = np.argsort(-amplitudes)  # strongest first
    for peak, frequency, amplitude in zip(peaks, frequencies[order], amplitudes[order]):
        assert abs(peak.frequency_hz - frequency) <= FREQUENCY_TOLERANCE_BINS * width
        assert peak.amplitude == pytest.approx(amplitude, rel=AMPLITUDE_TOLERANCE)


def test_band_picks_the_peak_inside_it():
    rate, n = 2000.0, 8000
    values = tone(3.0, 120.0, rate, n) + tone(0.5, 349.3, rate, n)
    result = spectrum(Signal(values, rate), "fft")
    assert result.peaks()[0].frequency_hz == pytest.approx(120.0, abs=0.025)
    peak = result.peak_in_band((300.0, 400.0))
    assert peak.frequency_hz == pytest.approx(349.3, abs=0.1 * result.resolution_hz)
    assert peak.amplitude == pytest.approx(0.5, rel=AMPLITUDE_TOLERANCE)
    with pytest.raises(SignalError, match="LO < HI"):
        result.peaks((400.0, 300.0))
    with pytest.raises(SignalError, match="no spectral line"):
        result.peaks((1200.0, 1300.0))


def test_beating_tones_are_both_resolved_and_the_envelope_adds():
    """Two tones 2 Hz apart (beating at 2 Hz, as the rig at 900 rpm) over 10 s: 20 bins apart with the FFT."""
    rate, n = 2048.0, 20480
    values = tone(1.0, 349.25, rate, n, 0.0) + tone(0.6, 347.25, rate, n, 0.0)
    result = spectrum(Signal(values, rate), "fft")
    first, second = result.peaks(band=(300, 400), max_peaks=2)
    assert first.frequency_hz == pytest.approx(349.25, abs=0.1 * result.resolution_hz)
    assert second.frequency_hz == pytest.approx(347.25, abs=0.1 * result.resolution_hz)
    assert first.amplitude == pytest.approx(1.0, rel=AMPLITUDE_TOLERANCE)
    assert second.amplitude == pytest.approx(0.6, rel=AMPLITUDE_TOLERANCE)
    assert max_amplitude(values) == pytest.approx(1.6, rel=1e-3)  # the beat envelope peaks at the sum
    # windows of 0.1 s (a fifth of the 0.5-s beat period) see the envelope swing between 1.6 and 0.4
    rows = window_table(Signal(values, rate), parse_windows("100", Signal(values, rate)))
    means = np.array([row.mean_amplitude for row in rows])
    assert means.max() / means.min() > 2.0


def test_slowly_drifting_resonance_is_tracked_over_windows():
    """Frequency falling linearly 349.25 → 347.25 Hz over 60 s (Fig. 18's shift); 10-s windows."""
    rate, duration = 2000.0, 60.0
    time = np.arange(int(rate * duration)) / rate
    start, end = 349.25, 347.25
    phase = 2 * np.pi * (start * time + 0.5 * (end - start) / duration * time**2)
    rng = np.random.default_rng(3)
    values = 0.7 * np.sin(phase) + rng.normal(0, 0.05, time.size)
    signal = Signal(values, rate)
    windows = parse_windows("6", signal)
    rows = window_table(signal, windows, band=(300.0, 400.0), method="fft")
    width = rate / (time.size // 6)
    for row in rows:
        centre = 0.5 * (row.start_s + row.stop_s)
        expected = start + (end - start) * centre / duration
        # the chirp moves 0.33 Hz (3.3 bins) within a window; its spectral centroid is the mid-window frequency
        assert abs(row.peak_frequency_hz - expected) <= FREQUENCY_TOLERANCE_BINS * width
    frequencies = [row.peak_frequency_hz for row in rows]
    assert all(np.diff(frequencies) < 0)


def test_time_domain_amplitudes_of_a_sine():
    rate, n = 100000.0, 100000  # whole number of periods, 2000 samples each
    values = tone(2.0, 50.0, rate, n) + 5.0  # offset removed
    assert max_amplitude(values) == pytest.approx(2.0, rel=1e-3)
    assert mean_amplitude(values) == pytest.approx(2 * 2.0 / np.pi, rel=1e-3)
    assert rms_amplitude(values) == pytest.approx(2.0 / np.sqrt(2), rel=1e-6)


def test_hann_kernel_values():
    np.testing.assert_allclose(hann_kernel([0.0, 0.5, 1.0, -1.0, 2.0]),
                               [1.0, (2 / np.pi) / 0.75, 0.5, 0.5, 0.0], atol=1e-12)


def test_interpolation_at_the_edge_falls_back_to_the_bin():
    peak = interpolate_peak(np.array([2.0, 1.0, 0.5]), 0, 10.0)
    assert peak.frequency_hz == 0.0 and peak.amplitude == pytest.approx(2.0)


def test_mesh_orders_and_side_bands():
    """Amplitude-modulated mesh tone: (1 + m cos 2π fs t) · A cos 2π fm t gives side bands of m·A/2 at fm ± fs."""
    rate, n = 10240.0, 102400
    mesh, shaft, modulation = 240.0, 15.0, 0.4
    time = np.arange(n) / rate
    values = (1 + modulation * np.cos(2 * np.pi * shaft * time)) * 2.0 * np.cos(2 * np.pi * mesh * time) \
        + 0.8 * np.cos(2 * np.pi * 2 * mesh * time)
    result = spectrum(Signal(values, rate), "fft")
    rows = mesh_orders(result, mesh, orders=3, shaft_frequency_hz=shaft, sidebands=2)
    by_key = {(row["order"], row["sideband"]): row for row in rows}
    assert by_key[(1, 0)]["amplitude"] == pytest.approx(2.0, rel=AMPLITUDE_TOLERANCE)
    assert by_key[(1, 1)]["amplitude"] == pytest.approx(0.4, rel=AMPLITUDE_TOLERANCE)
    assert by_key[(1, -1)]["amplitude"] == pytest.approx(0.4, rel=AMPLITUDE_TOLERANCE)
    assert by_key[(2, 0)]["amplitude"] == pytest.approx(0.8, rel=AMPLITUDE_TOLERANCE)
    assert by_key[(1, 1)]["frequency_hz"] == pytest.approx(mesh + shaft, abs=0.1 * result.resolution_hz)
    assert by_key[(1, 0)]["found"]
    assert by_key[(3, 0)]["amplitude"] < 1e-6  # no third order in the signal (rounding noise only)
    with pytest.raises(SignalError, match="mesh frequency"):
        mesh_orders(result, 0.0)


def test_spectrum_argument_checks():
    signal = Signal(np.random.default_rng(0).normal(size=100), 100.0)
    with pytest.raises(SignalError, match="method"):
        spectrum(signal, "multitaper")
    with pytest.raises(SignalError, match="segment length"):
        spectrum(signal, "welch", segment_length=500)
    with pytest.raises(SignalError, match="overlap"):
        spectrum(signal, "welch", overlap=1.0)
    with pytest.raises(SignalError, match="START:STOP"):
        parse_windows("1-2", signal)
