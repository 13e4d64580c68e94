"""The test-rig measurements of Luo & Li (2020), Table 3 and Fig. 18, as a dataset.

Source: B. Luo, W. Li, "Investigation on the influence of heat on the dynamic characteristics of a gear
transmission system", Engineering Failure Analysis (2020) 104724, DOI 10.1016/j.engfailanal.2020.104724, §5.2:
FZG-type back-to-back rig, heat from tooth friction only, 20-minute runs at pinion speeds 400 / 900 / 1400 rpm,
load stage 6 ("138 N m"; ISO 14635-1 stage 6 is 135.3 N m). Temperatures, mean and maximum acceleration at the
3rd, 5th and 10th minute (Table 3); at 900 rpm also the FFT peak acceleration and the resonance frequency
(Fig. 18). The paper does not identify the test gear (geometry, tooth numbers) nor how "mean" acceleration is
defined, nor the sensor position, the sampling rate or the FFT settings.

The file is ``thermogear/data/luo2019_fzg_table3.csv`` (package data), one row per (speed, minute); the two
Fig. 18 columns are empty where the paper gives nothing.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from importlib import resources

CITATION = ("B. Luo, W. Li, Investigation on the influence of heat on the dynamic characteristics of a gear "
            "transmission system, Engineering Failure Analysis (2020) 104724, doi:10.1016/j.engfailanal.2020.104724, "
            "Table 3 and Fig. 18")
DATA_FILE = "luo2019_fzg_table3.csv"
#: Load stage and torque the paper states for the runs, and the ISO 14635-1 torque of that stage [N m].
LOAD_STAGE = 6
STATED_TORQUE_NM = 138.0


@dataclass(frozen=True)
class RigMeasurement:
    """One Table 3 row: pinion speed [rpm], minute of the run, temperature [°C], mean and max acceleration
    [m/s²], and (900 rpm only) the FFT spectrum peak [m/s²] and resonance frequency [Hz] of Fig. 18."""

    speed_rpm: float
    minute: float
    temperature_c: float
    mean_acceleration_m_s2: float
    max_acceleration_m_s2: float
    spectrum_peak_m_s2: float | None
    resonance_frequency_hz: float | None


def rig_measurements() -> list[RigMeasurement]:
    """All rows of the paper's Table 3 (+ Fig. 18), in file order."""
    text = (resources.files("thermogear") / "data" / DATA_FILE).read_text(encoding="utf-8")
    rows = csv.DictReader(text.splitlines())
    return [RigMeasurement(float(row["speed_rpm"]), float(row["minute"]), float(row["temperature_c"]),
                           float(row["mean_acceleration_m_s2"]), float(row["max_acceleration_m_s2"]),
                           _optional(row["spectrum_peak_m_s2"]), _optional(row["resonance_frequency_hz"]))
            for row in rows]


def rig_speeds_rpm() -> list[float]:
    """The pinion speeds of the runs [rpm]."""
    return sorted({row.speed_rpm for row in rig_measurements()})


def measurements_at(speed_rpm: float) -> list[RigMeasurement]:
    """The rows of one run, in time order."""
    return sorted((row for row in rig_measurements() if row.speed_rpm == speed_rpm), key=lambda row: row.minute)


def measured_resonance_shift() -> dict[str, float]:
    """The measured resonance shift of Fig. 18 (900 rpm) between the first and last temperature.

    Returns the temperatures [°C], the frequencies [Hz] and the relative change Δf/f [–].
    """
    rows = [row for row in measurements_at(900.0) if row.resonance_frequency_hz is not None]
    first, last = rows[0], rows[-1]
    return {"speed_rpm": 900.0, "temperature_start_c": first.temperature_c, "temperature_end_c": last.temperature_c,
            "frequency_start_hz": first.resonance_frequency_hz, "frequency_end_hz": last.resonance_frequency_hz,
            "relative_change": last.resonance_frequency_hz / first.resonance_frequency_hz - 1.0}


def _optional(text: str) -> float | None:
    text = text.strip()
    if not text:
        return None
    value = float(text)
    return None if math.isnan(value) else value
