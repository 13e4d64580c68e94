"""Test-rig workflow: measured vibration signals, their spectra and Table-3-like summaries, the paper's rig data,
the warm-up sequence of operating states and the model-versus-measurement comparison (Luo & Li 2020 §5.2).

The signal analysis (``signals``, ``spectrum``, ``table``) and the dataset (``rig_data``) need only NumPy/SciPy;
``warmup`` and ``comparison`` run the simulation chain and are imported from their modules.
"""

from thermogear.experiment.rig_data import (CITATION, RigMeasurement, measured_resonance_shift, measurements_at,
                                            rig_measurements)
from thermogear.experiment.signals import Signal, SignalError, read_csv_signal, read_signal, read_wav_signal
from thermogear.experiment.spectrum import (Peak, Spectrum, interpolate_peak, max_amplitude, mean_amplitude,
                                            mesh_orders, rms_amplitude, spectrum)
from thermogear.experiment.table import WindowRow, parse_windows, window_table

__all__ = [
    "CITATION", "Peak", "RigMeasurement", "Signal", "SignalError", "Spectrum", "WindowRow", "interpolate_peak",
    "max_amplitude", "mean_amplitude", "measured_resonance_shift", "measurements_at", "mesh_orders",
    "parse_windows", "read_csv_signal", "read_signal", "read_wav_signal", "rig_measurements", "rms_amplitude",
    "spectrum", "window_table",
]
