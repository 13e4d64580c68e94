"""Figures of the test-rig workflow: spectra, waterfall over time windows, amplitude and resonance frequency
versus temperature (model beside measurement), warm-up histories. Every function returns the figure."""

from __future__ import annotations

from typing import Any

import numpy as np


def _axes(ax: Any = None):
    import matplotlib.pyplot as plt

    if ax is None:
        figure, ax = plt.subplots(figsize=(7, 4.2), layout="constrained")
        return figure, ax
    return ax.figure, ax


def plot_spectrum(spectrum, ax: Any = None, label: str | None = None, band: tuple[float, float] | None = None,
                  peaks: list | None = None, unit: str = "m/s²"):
    """Amplitude spectrum √(2P) with the interpolated peaks marked."""
    figure, ax = _axes(ax)
    ax.plot(spectrum.frequency_hz, spectrum.amplitude, lw=0.8, label=label or f"{spectrum.method} "
            f"(Δf = {spectrum.resolution_hz:.3g} Hz, {spectrum.segments} segment(s))")
    for peak in peaks or []:
        ax.plot(peak.frequency_hz, peak.amplitude, "v", color="C3", ms=5)
        ax.annotate(f"{peak.frequency_hz:.2f} Hz", (peak.frequency_hz, peak.amplitude), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    if band is not None:
        ax.set_xlim(*band)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel(f"amplitude [{unit}]")
    ax.legend(fontsize=8)
    return figure


def plot_waterfall(spectra: list, times_s: list[float], ax: Any = None, band: tuple[float, float] | None = None,
                   unit: str = "m/s²"):
    """Spectra over time windows, stacked with a vertical offset (a waterfall), labelled by window centre time."""
    figure, ax = _axes(ax)
    top = max(float(np.max(s.amplitude)) for s in spectra) if spectra else 1.0
    if band is not None:
        top = max(float(np.max(s.amplitude[(s.frequency_hz >= band[0]) & (s.frequency_hz <= band[1])], initial=0))
                  for s in spectra) or top
    step = 0.6 * top
    for index, (spectrum, time) in enumerate(zip(spectra, times_s)):
        offset = index * step
        ax.plot(spectrum.frequency_hz, spectrum.amplitude + offset, lw=0.7, color=f"C{index % 10}")
        ax.text(1.0, offset, f" {time:.4g} s", transform=ax.get_yaxis_transform(), fontsize=7, va="bottom")
    if band is not None:
        ax.set_xlim(*band)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel(f"amplitude [{unit}] + offset per window")
    ax.set_title("spectra over time (waterfall)")
    return figure


def plot_window_table(rows: list, ax: Any = None, unit: str = "m/s²"):
    """Mean and maximum amplitude and the band peak of each window, versus temperature (or time without one)."""
    figure, ax = _axes(ax)
    use_temperature = all(row.temperature_c is not None for row in rows)
    x = [row.temperature_c if use_temperature else 0.5 * (row.start_s + row.stop_s) for row in rows]
    ax.plot(x, [row.mean_amplitude for row in rows], "o-", label="mean |a − ā|")
    ax.plot(x, [row.max_amplitude for row in rows], "s-", label="max |a − ā|")
    ax.plot(x, [row.peak_amplitude for row in rows], "^-", label="spectral peak in band")
    ax.set_xlabel("temperature [°C]" if use_temperature else "time [s]")
    ax.set_ylabel(f"amplitude [{unit}]")
    twin = ax.twinx()
    twin.plot(x, [row.peak_frequency_hz for row in rows], "k--", lw=0.8, label="peak frequency")
    twin.set_ylabel("peak frequency [Hz]")
    ax.legend(fontsize=8, loc="upper left")
    return figure


def plot_rig_amplitudes(measurements: list, ax: Any = None):
    """The paper's Table 3: mean and maximum acceleration versus temperature, one line per speed."""
    figure, ax = _axes(ax)
    speeds = sorted({row.speed_rpm for row in measurements})
    for index, speed in enumerate(speeds):
        rows = [row for row in measurements if row.speed_rpm == speed]
        temperature = [row.temperature_c for row in rows]
        ax.plot(temperature, [row.mean_acceleration_m_s2 for row in rows], "o-", color=f"C{index}",
                label=f"{speed:.0f} rpm mean")
        ax.plot(temperature, [row.max_acceleration_m_s2 for row in rows], "s--", color=f"C{index}",
                label=f"{speed:.0f} rpm max")
    ax.set_xlabel("temperature [°C]")
    ax.set_ylabel("acceleration [m/s²]")
    ax.set_title("Luo & Li (2020) Table 3 (measured)")
    ax.legend(fontsize=7, ncol=2)
    return figure


def plot_resonance_comparison(comparison, ax: Any = None):
    """Measured resonance frequency (Fig. 18, 900 rpm) versus temperature beside the model's natural frequency
    scaled to the first measured point (the model predicts the relative change, not the rig's resonance)."""
    figure, ax = _axes(ax)
    measured = comparison.measured_points
    temperature = [point[0] for point in measured]
    frequency = [point[1] for point in measured]
    ax.plot(temperature, frequency, "o-", label="measured resonance (Fig. 18)")
    rows = [row for row in comparison.rows if row.speed_rpm == comparison.measured_speed_rpm]
    base = rows[0].natural_frequency_hz
    ax.plot([row.temperature_c for row in rows], [frequency[0] * row.natural_frequency_hz / base for row in rows],
            "s--", label=f"model f_n × {frequency[0]:.2f} Hz / f_n({rows[0].temperature_c:.1f} °C)")
    ax.set_xlabel("temperature [°C]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"{comparison.case_name}, {comparison.measured_speed_rpm:.0f} rpm: relative shift")
    ax.legend(fontsize=8)
    return figure


def plot_warmup(result, ax: Any = None):
    """Warm-up: temperature and the natural frequency of the mesh over time."""
    figure, ax = _axes(ax)
    time_min = np.asarray(result.time_s) / 60.0
    ax.plot(time_min, result.temperature_c, "o-", color="C3", label="temperature")
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature [°C]", color="C3")
    twin = ax.twinx()
    twin.plot(time_min, result.natural_frequency_hz, "s-", color="C0", label="natural frequency")
    twin.set_ylabel("natural frequency of the mesh [Hz]", color="C0")
    ax.set_title(f"warm-up of {result.case_name} ({result.model} model)")
    return figure
