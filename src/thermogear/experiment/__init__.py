"""Test-rig workflow: measured vibration signals, their spectra and Table-3-like summaries, the paper's rig data,
the warm-up sequence of operating states and the model-versus-measurement comparison (Luo & Li 2020 §5.2).

The signal analysis (``signals``, ``spectrum``, ``table``) and the dataset (``rig_data``) need only NumPy/SciPy;
``warmup`` and ``comparison`` run the simulation chain and are imported from their modules.
"""

import importlib

# The names load on first use (PEP 562): `from thermogear.experiment.rig_data import ...` (the report's rig
# trend) must not pay for SciPy's signal package, which the spectra need (name → module that defines it).
_LAZY = {
    **dict.fromkeys(("CITATION", "RigMeasurement", "measured_resonance_shift", "measurements_at", "rig_measurements"),
                    "rig_data"),
    **dict.fromkeys(("Signal", "SignalError", "read_csv_signal", "read_signal", "read_wav_signal"), "signals"),
    **dict.fromkeys(("Peak", "Spectrum", "interpolate_peak", "max_amplitude", "mean_amplitude", "mesh_orders",
                     "rms_amplitude", "spectrum"), "spectrum"),
    **dict.fromkeys(("WindowRow", "parse_windows", "window_table"), "table"),
}


def __getattr__(name: str):
    if name not in _LAZY:
        raise AttributeError(f"module 'thermogear.experiment' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"thermogear.experiment.{_LAZY[name]}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


__all__ = [
    "CITATION", "Peak", "RigMeasurement", "Signal", "SignalError", "Spectrum", "WindowRow", "interpolate_peak",
    "max_amplitude", "mean_amplitude", "measured_resonance_shift", "measurements_at", "mesh_orders",
    "parse_windows", "read_csv_signal", "read_signal", "read_wav_signal", "rig_measurements", "rms_amplitude",
    "spectrum", "window_table",
]
