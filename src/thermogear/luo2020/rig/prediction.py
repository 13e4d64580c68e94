"""The paper's rig runs predicted by the gearbox thermal model, beside the measured temperatures of Luo & Li (2020)
Table 3. Predictions, not fits: nothing here is adjusted to the measurements.

The rig (Luo & Li 2020 §5.2) is an FZG-type back-to-back rig heated only by its own losses; the paper identifies
neither the test gears nor the gearbox, nor what its temperature sensor measures. Stated assumptions
(:data:`RIG_ASSUMPTIONS`):

* gears: FZG type C (ISO 14635-1) as a stand-in (the case ``fzg_type_c``), 138 N·m on the pinion as the paper
  states, pinion speeds 400 / 900 / 1400 rpm;
* oil: 1.25 L (the FZG test gearbox's fill, ASTM D5182 §9.4, technically equivalent to ISO 14635-1) of ISO VG 100
  mineral oil, dip lubrication, the wheel dipped to its centre;
* housing, bearings, seals and internal coefficients: the illustrative gearbox of
  :mod:`thermogear.gearbox.fzg_example` (0.45 × 0.30 × 0.40 m, 40 kg cast iron, air 1 m/s, four NJ 406, two lip
  seals), none of it verified for the paper's rig;
* the measured temperature is compared with the predicted oil (sump) temperature: the FZG test method controls
  the oil temperature with a sensor in the side of the test gearbox (ASTM D5182 §6.1.3); whether the paper's
  sensor did the same is not said; the pinion bulk temperature is reported beside it;
* ambient 20 °C; two starts, both without measurements: every run from a cold gearbox at the ambient, or the runs
  in the paper's order 400 → 900 → 1400 rpm, each starting where the previous 20-minute run ended.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.luo2020.rig.data import CITATION, STATED_TORQUE_NM, measurements_at, rig_speeds_rpm

RIG_AMBIENT_C = 20.0
RUN_DURATION_S = 1200.0
#: Output step of the predicted runs [s]: the measured minutes 3, 5, 10 fall on it. The integrator's steps do not
#: depend on it (the outputs are read from its dense output), so the values at the measured minutes do not either.
OUTPUT_STEP_S = 60.0
RIG_ASSUMPTIONS = (
    "gears: FZG type C (ISO 14635-1) as a stand-in for the paper's unidentified test gears; "
    f"{STATED_TORQUE_NM:g} N·m pinion torque",
    "oil: 1.25 L ISO VG 100 mineral, dip lubrication, wheel dipped to its centre (FZG fill: ASTM D5182 §9.4)",
    "housing, bearings, seals, internal coefficients: the illustrative FZG-type gearbox (assumed, not the rig's)",
    "measured temperature compared with the predicted oil temperature (FZG method: the oil temperature sensed in "
    "the side of the test gearbox, ASTM D5182 §6.1.3); the pinion bulk temperature is given beside it",
    f"ambient {RIG_AMBIENT_C:g} °C; cold start at the ambient, or the runs chained in the paper's order",
)


@dataclass(frozen=True)
class RigPrediction:
    """One Table 3 row beside its prediction [°C]: measured, predicted oil, pinion, wheel and housing."""

    speed_rpm: float
    minute: float
    start: str  # "cold" or "chained"
    measured_c: float
    oil_c: float
    pinion_c: float
    wheel_c: float
    housing_c: float

    @property
    def deviation(self) -> float:
        """Predicted oil − measured [K]."""
        return self.oil_c - self.measured_c


def rig_gearbox_description():
    """The gearbox description of the assumptions (module docstring)."""
    from thermogear.friction.models import FRICTION_MODELS  # noqa: PLC0415
    from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox  # noqa: PLC0415

    # the paper's friction law (Luo & Li Eq. 27) for its tooth loss too: the reproduction of the paper keeps one
    # friction law throughout and its numbers unchanged (the loss model's default is Schlenk's)
    return illustrative_fzg_gearbox(friction=FRICTION_MODELS["paper"])


def predict_table3(chained: bool = False) -> list[RigPrediction]:
    """Predicted temperatures at the measured minutes of every run of Table 3 (module docstring), in the
    paper's order of speeds. ``chained``: each run starts from the previous run's end state."""
    cold, chain = predicted_runs(chained=chained, cold=not chained)
    return chain if chained else cold


def predicted_runs(chained: bool = True, cold: bool = True) -> tuple[list[RigPrediction], list[RigPrediction]]:
    """(cold-start rows, chained rows) of :func:`predict_table3`; the first run, the same in both, is integrated
    once. A list not asked for is empty."""
    from thermogear.gearbox.description import GearboxOperatingPoint  # noqa: PLC0415
    from thermogear.gearbox.losses import NODES  # noqa: PLC0415
    from thermogear.gearbox.model import GearboxThermalModel  # noqa: PLC0415

    model = GearboxThermalModel(rig_gearbox_description())
    points = int(round(RUN_DURATION_S / OUTPUT_STEP_S)) + 1
    ambient = np.full(len(NODES), RIG_AMBIENT_C)
    rows: dict[str, list[RigPrediction]] = {"cold": [], "chained": []}
    start = ambient
    for order, speed in enumerate(rig_speeds_rpm()):
        operating = GearboxOperatingPoint(speed, STATED_TORQUE_NM, RIG_AMBIENT_C)
        from_ambient = model.warm_up(operating, RUN_DURATION_S, points=points, initial_c=ambient) \
            if cold or order == 0 else None
        if cold:
            rows["cold"] += _rows_of_run(from_ambient, speed, "cold")
        if chained:
            run = from_ambient if order == 0 else model.warm_up(operating, RUN_DURATION_S, points=points,
                                                                initial_c=start)
            rows["chained"] += _rows_of_run(run, speed, "chained")
            start = run.temperatures_c[:, -1].copy()
    return rows["cold"], rows["chained"]


def _rows_of_run(history, speed: float, start: str) -> list[RigPrediction]:
    rows = []
    for measured in measurements_at(speed):
        index = int(round(measured.minute * 60.0 / OUTPUT_STEP_S))
        pinion, wheel, oil, housing = (history.node(name)[index] for name in ("pinion", "wheel", "oil", "housing"))
        rows.append(RigPrediction(speed, measured.minute, start, measured.temperature_c, float(oil), float(pinion),
                                  float(wheel), float(housing)))
    return rows


def table3_markdown(rows: list[RigPrediction]) -> str:
    """A Markdown table of predictions beside measurements (0.1 K: the paper prints 0.1 °C)."""
    lines = ["| rpm | minute | start | measured [°C] | predicted oil [°C] | oil − measured [K] | pinion [°C] |",
             "|---|---|---|---|---|---|---|"]
    for row in rows:
        lines.append(f"| {row.speed_rpm:g} | {row.minute:g} | {row.start} | {row.measured_c:.1f} | {row.oil_c:.1f} | "
                     f"{row.deviation:+.1f} | {row.pinion_c:.1f} |")
    return "\n".join(lines) + f"\n\nMeasured: {CITATION}. Predictions, not fitted to the measurements.\n"
