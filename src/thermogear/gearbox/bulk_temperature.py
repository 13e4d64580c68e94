"""Quick estimate of the gear bulk (mass) temperature from the oil temperature, where no housing is described.

* ISO/TR 15144-1:2014 (micropitting), bulk temperature from the oil temperature and the tooth friction loss:

      θ_M = θ_oil + 7400·(P·μ_m·H_V/(a·b))^0.72·X_S/(1.2·X_Ca)          P kW per mesh, a and b mm, θ °C

  The formula is recalled, not read in the standard (unverified); it reproduces the bulk temperatures printed by
  KISSsoft (Release 03/2017) for the NREL 5 MW gearbox stages (e.g. stage 3: P 5000 kW, μ_m 0.030, H_V 0.106,
  a 861 mm, b 360 mm, θ_oil 80 °C → θ_M 85.0 °C; tests/validation), which pins down its constants.
* ISO/TR 13989-1:2000 (flash-temperature method): θ_M = θ_oil + 0.47·X_S·X_mp·θ_flm, θ_flm the mean flash
  temperature along the path of contact; ISO/TR 13989-2:2000 (integral method): θ_M = θ_oil + 0.7·X_S·θ_fla,int.
  Both relations are printed with their values in the same KISSsoft reports (stage 3: 80 + 0.47·30.20 = 94.19;
  80 + 0.7·16.25 = 91.37 °C). ISO/TS 6336-20/-21 (2017/2022) took these methods over; not read here.
* Blok's flash temperature (Blok 1937) for a semi-elliptic (Hertzian) heat source at high Péclet number, with
  Blok's partition of equal surface temperatures: θ_fl,max = 0.786·μ·w·|√v1 − √v2|/(B_M·√b_H) [K], w the normal
  load per unit length [N/m], b_H the Hertzian half-width [m], B_M = √(λρc) [W·s^0.5/(m²K)] of both gears.
  0.786 = 2·J_max/π^1.5 with J(X) = ∫_{−1}^{X} √(1 − s²)/√(X − s) ds (the 1-D moving-source solution), J_max =
  2.1883 at X = 0.652 (tests compute it by quadrature; a uniform source of the same width gives √(2/π) = 0.798).

X_S lubrication factor (1.0 dip lubrication as printed by KISSsoft for an oil bath; 1.2 injection, recalled),
X_Ca tip-relief factor (1 without relief), X_mp multiple-mesh factor (1 for one mesh).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.errors import CaseError
from thermogear.gearbox.mesh_loss import pair_gear_loss_factor, rigid_load_share
from thermogear.geometry import GearPair

#: Peak factor of Blok's flash temperature for a semi-elliptic source (module docstring).
BLOK_SEMI_ELLIPTIC = 0.786


def iso_15144_bulk_temperature(oil_c: float, power: float, friction: float, loss_factor: float,
                               centre_distance: float, face_width: float, lubrication_factor: float = 1.0,
                               tip_relief_factor: float = 1.0) -> float:
    """θ_M [°C] of ISO/TR 15144-1 (module docstring): ``power`` per mesh [W], ``centre_distance`` and
    ``face_width`` [m]."""
    for key, value in (("power", power), ("friction", friction), ("loss_factor", loss_factor)):
        if not (math.isfinite(value) and value >= 0.0):
            raise CaseError(key, value, ">= 0", "a power, friction coefficient or loss factor")
    for key, value in (("centre_distance", centre_distance), ("face_width", face_width),
                       ("lubrication_factor", lubrication_factor), ("tip_relief_factor", tip_relief_factor)):
        if not (math.isfinite(value) and value > 0.0):
            raise CaseError(key, value, "> 0", "a size or factor of the bulk-temperature formula")
    group = power * 1e-3 * friction * loss_factor / (centre_distance * 1e3 * face_width * 1e3)
    return oil_c + 7400.0 * group**0.72 * lubrication_factor / (1.2 * tip_relief_factor)


def flash_method_bulk_temperature(oil_c: float, mean_flash_temperature: float, lubrication_factor: float = 1.0,
                                  multiple_mesh_factor: float = 1.0) -> float:
    """θ_M = θ_oil + 0.47·X_S·X_mp·θ_flm [°C] (ISO/TR 13989-1)."""
    return oil_c + 0.47 * lubrication_factor * multiple_mesh_factor * mean_flash_temperature


def integral_method_bulk_temperature(oil_c: float, mean_flash_integral: float,
                                     lubrication_factor: float = 1.0) -> float:
    """θ_M = θ_oil + 0.7·X_S·θ_fla,int [°C] (ISO/TR 13989-2)."""
    return oil_c + 0.7 * lubrication_factor * mean_flash_integral


def blok_flash_temperature(friction, unit_load, speeds, relative_radius, contact_modulus: float,
                           effusivity: float):
    """Peak flash temperature θ_fl,max [K] of a Hertzian line contact (module docstring), arrays broadcast.

    ``unit_load`` w [N/m], ``speeds`` (v1, v2) rolling speeds [m/s], ``relative_radius`` R [m],
    ``contact_modulus`` E* = 1/Σ(1 − ν_i²)/E_i [Pa], ``effusivity`` B_M [W·s^0.5/(m²K)] of both gears."""
    load = np.maximum(np.asarray(unit_load, dtype=float), 0.0)
    half_width = 2.0 * np.sqrt(load * np.asarray(relative_radius, dtype=float) / (math.pi * contact_modulus))
    speed_1, speed_2 = (np.asarray(v, dtype=float) for v in speeds)
    difference = np.abs(np.sqrt(speed_1) - np.sqrt(speed_2))
    with np.errstate(divide="ignore", invalid="ignore"):
        value = BLOK_SEMI_ELLIPTIC * np.asarray(friction, float) * load * difference / (effusivity
                                                                                       * np.sqrt(half_width))
    return np.where(load > 0.0, value, 0.0)


@dataclass(frozen=True)
class BulkTemperatureEstimate:
    """The quick estimate [°C] by both methods, with the mean flash temperature [K] and H_V used."""

    oil_c: float
    iso_15144_c: float
    flash_method_c: float
    mean_flash_temperature: float
    loss_factor: float


def quick_bulk_temperature(pair: GearPair, speed_rpm: float, torque: float, oil_c: float, friction: float,
                           contact_modulus: float = 2.0 * 206e9 / (2.0 * (1.0 - 0.3**2)),
                           effusivity: float = 12_940.0, lubrication_factor: float = 1.0,
                           points: int = 401) -> BulkTemperatureEstimate:
    """Bulk temperature of a spur pair from the oil temperature [°C] at a pinion speed [rpm] and torque [N·m]
    with a mean friction coefficient μ_m (e.g. the project's DIN 3990-4 value at the oil temperature). The mean
    flash temperature is the average of Blok's θ_fl,max along the path with rigid load sharing; steel defaults
    for E* (E 206 GPa, ν 0.3) and B_M."""
    if not (speed_rpm > 0.0 and torque > 0.0):
        raise CaseError("operating", (speed_rpm, torque), "speed > 0 rpm and torque > 0 N·m", "a loaded mesh")
    roll = pair.roll_grid(points)
    load = rigid_load_share(pair, roll) * torque / pair.pinion.base_radius / pair.face_width
    flash = blok_flash_temperature(friction, load, pair.rolling_speeds(roll, speed_rpm),
                                   pair.relative_radius_of_curvature(roll), contact_modulus, effusivity)
    mean_flash = float(np.sum(0.5 * (flash[1:] + flash[:-1]) * np.diff(roll)) / (roll[-1] - roll[0]))
    loss_factor = pair_gear_loss_factor(pair)
    power = torque * speed_rpm * math.pi / 30.0
    return BulkTemperatureEstimate(
        oil_c, iso_15144_bulk_temperature(oil_c, power, friction, loss_factor, pair.centre_distance,
                                          pair.face_width, lubrication_factor),
        flash_method_bulk_temperature(oil_c, mean_flash, lubrication_factor), mean_flash, loss_factor)
