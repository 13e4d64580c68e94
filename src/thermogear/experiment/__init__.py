"""Test-rig workflow: measured vibration signals, their spectra and Table-3-like summaries, the warm-up sequence of
operating states and the model-versus-measurement comparison (as Luo & Li 2020 §5.2 do on their rig, whose data
are in :mod:`thermogear.luo2020.rig`).

The signal analysis (``signals``, ``spectrum``, ``table``) needs only NumPy/SciPy; ``warmup`` and ``comparison``
run the simulation chain and are imported from their modules.
"""

from thermogear.experiment.signals import Signal, SignalError, read_csv_signal, read_signal, read_wav_signal
from thermogear.experiment.spectrum import (Peak, Spectrum, interpolate_peak, max_amplitude, mean_amplitude,
                                            mesh_orders, rms_amplitude, spectrum)
from thermogear.experiment.table import WindowRow, parse_windows, window_table

__all__ = [
    "Peak", "Signal", "SignalError", "Spectrum", "WindowRow", "interpolate_peak", "max_amplitude", "mean_amplitude",
    "mesh_orders", "parse_windows", "read_csv_signal", "read_signal", "read_wav_signal", "rms_amplitude", "spectrum",
    "window_table",
]
