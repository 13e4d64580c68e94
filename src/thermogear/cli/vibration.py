"""`thermogear vibration FILE`: spectra, amplitudes, peaks, mesh orders and a Table-3-like window table of a
measured acceleration signal (CSV or WAV)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import typer
from rich.table import Table

from thermogear.cli.app import app, console, print_json
from thermogear.errors import CaseError
from thermogear.experiment.signals import SignalError, read_signal
from thermogear.experiment.spectrum import max_amplitude, mean_amplitude, mesh_orders, rms_amplitude, spectrum
from thermogear.experiment.table import parse_windows, window_spectra, window_table
from thermogear.ownership import check_output_folder

DEFINITIONS = {
    "mean_amplitude": "mean of |a - mean(a)| over the record (2A/pi for a sine of amplitude A)",
    "max_amplitude": "max of |a - mean(a)| over the record (A for a sine)",
    "rms_amplitude": "root mean square of a - mean(a) (A/sqrt(2) for a sine)",
    "peaks": "Hann-window spectrum, peaks interpolated between bins (Grandke ratio); amplitude = amplitude of "
             "the sine of that frequency, in the signal's unit",
}


def parse_band(text: str | None) -> tuple[float, float] | None:
    """``"LO:HI"`` [Hz] → (LO, HI)."""
    if text is None:
        return None
    try:
        low, high = (float(part) for part in text.split(":"))
    except ValueError:
        raise SignalError(f"--band {text}: allowed LO:HI in Hz, e.g. 300:400") from None
    if not (math.isfinite(low) and math.isfinite(high) and 0 <= low < high):
        raise SignalError(f"--band {text}: allowed 0 ≤ LO < HI, finite numbers [Hz]")
    return low, high


@app.command()
def vibration(
    file: Path = typer.Argument(..., metavar="FILE", help="CSV (header; a time column in s or --rate) or WAV file"),
    column: str | None = typer.Option(None, "--column", help="signal column (CSV) or channel_N / N (WAV)"),
    rate: float | None = typer.Option(None, "--rate", help="sampling rate [Hz] (CSV without a time column)"),
    scale: float = typer.Option(1.0, "--scale", help="multiply the samples (WAV: signal unit per full scale)"),
    band: str | None = typer.Option(None, "--band", help="frequency band LO:HI [Hz] for the peak search"),
    method: str = typer.Option("welch", "--method", help="spectrum: 'welch' (averaged) or 'fft' (one window)"),
    segment: int | None = typer.Option(None, "--segment", help="Welch segment length [samples]"),
    peaks: int = typer.Option(5, "--peaks", min=1, max=100, help="number of peaks to report"),
    windows: str | None = typer.Option(None, "--windows", help="time windows: a count N or START:STOP,… [s]"),
    mesh_frequency: float | None = typer.Option(None, "--mesh-frequency", help="mesh frequency [Hz] for orders"),
    shaft_frequency: float | None = typer.Option(None, "--shaft-frequency", help="shaft frequency [Hz] for side bands"),
    orders: int = typer.Option(3, "--orders", min=1, max=50, help="mesh orders to report"),
    sidebands: int = typer.Option(2, "--sidebands", min=0, max=20, help="side bands each side of an order"),
    as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
    plot: Path | None = typer.Option(None, "--plot", help="write figures (spectrum, waterfall, table) to this folder"),
) -> None:
    """Vibration analysis of a measured signal (Luo & Li 2020 Table 3 / Fig. 18 style)."""
    if plot is not None:
        plot = check_output_folder(plot)  # before any work: a file of that name is refused, not overwritten
    signal = read_signal(file, column, rate, scale)
    band_hz = parse_band(band)
    result = spectrum(signal, method, segment)
    found = result.peaks(band_hz, max_peaks=peaks)
    payload = {
        "file": str(file), "column": signal.name, "sampling_rate_hz": signal.sampling_rate_hz,
        "samples": int(signal.values.size), "start_time_s": signal.start_time_s, "duration_s": signal.duration_s,
        "method": result.method, "window": "hann", "resolution_hz": result.resolution_hz,
        "segment_length": result.segment_length, "segments": result.segments,
        "mean_amplitude": mean_amplitude(signal.values), "max_amplitude": max_amplitude(signal.values),
        "rms_amplitude": rms_amplitude(signal.values),
        "band_hz": list(band_hz) if band_hz else None,
        "peaks": [peak.as_dict() for peak in found],
        "definitions": DEFINITIONS,
    }
    if signal.temperature_c is not None:
        payload["temperature_c"] = {"mean": float(np.mean(signal.temperature_c)),
                                    "start": float(signal.temperature_c[0]), "end": float(signal.temperature_c[-1])}
    if mesh_frequency is not None:
        payload["mesh_orders"] = mesh_orders(result, mesh_frequency, orders, shaft_frequency, sidebands)
    rows, spans = [], []
    if windows is not None:
        spans = parse_windows(windows, signal)
        rows = window_table(signal, spans, band_hz, method, segment)
        payload["windows"] = [row.as_dict() for row in rows]
    if plot is not None:
        payload["plots"] = _write_plots(plot, signal, result, found, band_hz, spans, rows, method, segment)
    if as_json:
        print_json(payload)
        return
    _print_summary(payload, rows)


def _write_plots(folder: Path, signal, result, found, band_hz, spans, rows, method, segment) -> list[str]:
    from thermogear.experiment.plots import plot_spectrum, plot_waterfall, plot_window_table

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise CaseError("--plot", str(folder), "a folder thermogear can create and write",
                        f"cannot write there: {error.strerror or error}") from None
    written = []
    figure = plot_spectrum(result, band=band_hz, peaks=found)
    written.append(_save(figure, folder / "spectrum.png"))
    if rows:
        spectra = window_spectra(signal, spans, method, segment)
        centres = [0.5 * (a + b) for a, b in spans]
        written.append(_save(plot_waterfall(spectra, centres, band=band_hz), folder / "waterfall.png"))
        written.append(_save(plot_window_table(rows), folder / "windows.png"))
    return written


def _save(figure, path: Path) -> str:
    import matplotlib.pyplot as plt

    figure.savefig(path, dpi=130)
    plt.close(figure)
    return str(path)


def _print_summary(payload: dict, rows) -> None:
    console.print(f"{payload['file']} column {payload['column']}: {payload['samples']} samples at "
                  f"{payload['sampling_rate_hz']:.6g} Hz ({payload['duration_s']:.4g} s); {payload['method']} "
                  f"spectrum, Hann, Δf = {payload['resolution_hz']:.4g} Hz, {payload['segments']} segment(s)")
    console.print(f"mean |a−ā| = {payload['mean_amplitude']:.4g}, max |a−ā| = {payload['max_amplitude']:.4g}, "
                  f"RMS = {payload['rms_amplitude']:.4g}")
    table = Table(title="spectral peaks (strongest first)")
    table.add_column("frequency [Hz]", justify="right")
    table.add_column("amplitude", justify="right")
    for peak in payload["peaks"]:
        table.add_row(f"{peak['frequency_hz']:.3f}", f"{peak['amplitude']:.4g}")
    console.print(table)
    if "mesh_orders" in payload:
        orders = Table(title="mesh orders and side bands")
        for name in ("order", "sideband", "nominal [Hz]", "found at [Hz]", "amplitude"):
            orders.add_column(name, justify="right")
        for row in payload["mesh_orders"]:
            orders.add_row(str(row["order"]), f"{row['sideband']:+d}", f"{row['nominal_hz']:.2f}",
                           f"{row['frequency_hz']:.2f}" if row["found"] else "—", f"{row['amplitude']:.4g}")
        console.print(orders)
    if rows:
        windows = Table(title="windows (Table 3 style)")
        for name in ("start [s]", "stop [s]", "T [°C]", "mean", "max", "RMS", "peak [Hz]", "peak amplitude"):
            windows.add_column(name, justify="right")
        for row in rows:
            windows.add_row(f"{row.start_s:.4g}", f"{row.stop_s:.4g}",
                            "—" if row.temperature_c is None else f"{row.temperature_c:.1f}",
                            f"{row.mean_amplitude:.4g}", f"{row.max_amplitude:.4g}", f"{row.rms_amplitude:.4g}",
                            f"{row.peak_frequency_hz:.3f}", f"{row.peak_amplitude:.4g}")
        console.print(windows)
    for path in payload.get("plots", []):
        console.print(f"figure written to {path}")
