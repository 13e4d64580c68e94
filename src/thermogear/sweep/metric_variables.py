"""The store variables of the metrics every study writes alike (the point studies of the linear mesh and the branch
studies of the backlash mesh): name → (units, long name), each written once here."""

from __future__ import annotations

__all__ = ["DTE_VARIABLES"]

#: The DTE statistics of :func:`thermogear.dynamics.results.period_metrics.dte_statistics`.
DTE_VARIABLES: dict[str, tuple[str, str]] = {
    "dte_mean": ("m", "mean dynamic transmission error"),
    "dte_rms": ("m", "RMS of the dynamic transmission error about its mean"),
    "dte_peak_to_peak": ("m", "peak-to-peak dynamic transmission error"),
}
