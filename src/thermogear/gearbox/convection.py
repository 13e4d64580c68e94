"""Heat-transfer correlations for the gearbox network (dimensionless groups in, Nusselt numbers or W/(m²·K) out).

Each function states its primary source and range of validity; docs/gearbox-temperature.md lists them with worked
values and the measurements that would validate them. Properties of air: :func:`air_properties`.

* Vertical wall, natural convection, any Rayleigh number: Churchill & Chu (1975), Int. J. Heat Mass Transfer
  18(11):1323 — Nu_H = [0.825 + 0.387·Ra^(1/6)/(1 + (0.492/Pr)^(9/16))^(8/27)]², 1e-1 ≤ Ra ≤ 1e12.
* Horizontal plate (length A/P): hot face up Nu = 0.54·Ra^(1/4) (1e4 ≤ Ra ≤ 1e7), 0.15·Ra^(1/3) (1e7 ≤ Ra ≤ 1e11);
  hot face down Nu = 0.27·Ra^(1/4) (1e5 ≤ Ra ≤ 1e10) (McAdams 1954, Heat Transmission, 3rd ed.; with L = A/P as
  Lloyd & Moran (1974) ASME 74-WA/HT-66; as tabulated in Incropera et al., Fundamentals of Heat and Mass
  Transfer, ch. 9). The two hot-up branches differ by 6.4 % at Ra = 1e7 (the correlations are not continuous
  there).
* Plate in parallel flow, average: laminar Nu = 0.664·Re^(1/2)·Pr^(1/3) (Re ≤ 5e5, Pr ≥ 0.6, Pohlhausen);
  mixed laminar–turbulent Nu = (0.037·Re^(4/5) − 871)·Pr^(1/3) (5e5 < Re ≤ 1e8, 0.6 ≤ Pr ≤ 60;
  Incropera et al., ch. 7). The two meet at Re = 5e5 to 0.1 %.
* Natural and forced together: Nu = (Nu_N³ + Nu_F³)^(1/3) (Churchill 1977, AIChE J. 23(1):10, assisting flows) —
  recalled, unverified here.
* Radiation of a grey surface to large surroundings: h_r = ε·σ·(T_s² + T_∞²)(T_s + T_∞) [W/(m²K)], so that
  h_r·(T_s − T_∞) = ε·σ·(T_s⁴ − T_∞⁴) exactly (kelvin).
* Free rotating disc, average over a face of radius R, Re = ω·R²/ν: laminar Nu = 0.36·Re^(1/2)
  (Re < 2.4e5), turbulent Nu = 0.015·Re^(4/5) − 100 (Cobb & Saunders 1956, Proc. R. Soc. A 236:343, air) — the
  constants are recalled, not read: unverified, and for air (Pr ≈ 0.7) only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.errors import CaseError

STEFAN_BOLTZMANN = 5.670374419e-8  # [W/(m²·K⁴)] (CODATA 2018, exact)
GRAVITY = 9.80665  # [m/s²]
KELVIN = 273.15


def _check(key: str, value: float, low: float = 0.0) -> float:
    value = float(value)
    if not (math.isfinite(value) and value > low):
        raise CaseError(key, value, f"> {low:g}", "a dimensionless group or property of the flow")
    return value


def churchill_chu_vertical(rayleigh: float, prandtl: float) -> float:
    """Average Nusselt number Nu_H of a vertical wall of height H, any Ra (Churchill & Chu 1975) [–]."""
    rayleigh = max(float(rayleigh), 0.0)
    _check("prandtl", prandtl)
    return (0.825 + 0.387 * rayleigh**(1.0 / 6.0) / (1.0 + (0.492 / prandtl)**(9.0 / 16.0))**(8.0 / 27.0))**2


def horizontal_plate(rayleigh: float, hot_face_up: bool) -> float:
    """Average Nusselt number of a horizontal plate, length L = A/P (McAdams; Lloyd & Moran) [–].

    ``hot_face_up``: a hot top face (or a cold bottom face); False: a hot bottom face. Below the correlations'
    lower Ra limit the branch is extrapolated (small ΔT: its heat flow is small anyway)."""
    rayleigh = max(float(rayleigh), 0.0)
    if not hot_face_up:
        return 0.27 * rayleigh**0.25
    return 0.54 * rayleigh**0.25 if rayleigh <= 1e7 else 0.15 * rayleigh**(1.0 / 3.0)


def flat_plate_forced(reynolds: float, prandtl: float) -> float:
    """Average Nusselt number Nu_L of a plate in parallel flow, laminar or mixed (Incropera et al., ch. 7) [–]."""
    reynolds = max(float(reynolds), 0.0)
    _check("prandtl", prandtl)
    if reynolds <= 5e5:
        return 0.664 * reynolds**0.5 * prandtl**(1.0 / 3.0)
    return (0.037 * reynolds**0.8 - 871.0) * prandtl**(1.0 / 3.0)


def combined_nusselt(natural: float, forced: float) -> float:
    """(Nu_N³ + Nu_F³)^(1/3) [–] (Churchill 1977; unverified)."""
    return (natural**3 + forced**3)**(1.0 / 3.0)


def radiation_coefficient(emissivity: float, surface_c: float, surroundings_c: float) -> float:
    """Linearised radiation coefficient h_r = εσ(T_s² + T_∞²)(T_s + T_∞) [W/(m²K)] (temperatures in °C)."""
    if not 0.0 <= emissivity <= 1.0:
        raise CaseError("housing.emissivity", emissivity, "[0, 1]", "a grey-body emissivity")
    surface, surroundings = surface_c + KELVIN, surroundings_c + KELVIN
    return emissivity * STEFAN_BOLTZMANN * (surface**2 + surroundings**2) * (surface + surroundings)


def rotating_disc(reynolds: float) -> float:
    """Average Nusselt number hR/k of a free rotating disc face, Re = ωR²/ν (Cobb & Saunders 1956; unverified)."""
    reynolds = max(float(reynolds), 0.0)
    return 0.36 * reynolds**0.5 if reynolds < 2.4e5 else 0.015 * reynolds**0.8 - 100.0


@dataclass(frozen=True)
class AirProperties:
    """Dry air at a film temperature and 1 atm: conductivity [W/(m·K)], kinematic viscosity [m²/s], Prandtl
    number [–] and expansion coefficient 1/T [1/K]."""

    conductivity: float
    kinematic_viscosity: float
    prandtl: float
    expansion: float

    def rayleigh(self, temperature_difference: float, length: float) -> float:
        """Ra = g·β·|ΔT|·L³/(ν·α), α = ν/Pr [–]."""
        diffusivity = self.kinematic_viscosity / self.prandtl
        return GRAVITY * self.expansion * abs(temperature_difference) * length**3 / (self.kinematic_viscosity
                                                                                       * diffusivity)


def air_properties(film_c: float) -> AirProperties:
    """Air at 1 atm from Sutherland's laws (White, Viscous Fluid Flow, 3rd ed. 2006, ch. 1: μ0 = 1.716e-5 Pa·s,
    k0 = 0.0241 W/(m·K) at 273 K, S = 194 K for k; S = 110.4 K for μ as in the U.S. Standard Atmosphere), ideal gas
    (R = 287.05 J/(kg·K)) and c_p = 1006 J/(kg·K); within about 3 % of tabulated air for −40…200 °C (k at
    20 °C 0.0257 against 0.0251 W/(m·K) tabulated)."""
    temperature = film_c + KELVIN
    if not 150.0 < temperature < 1000.0:
        raise CaseError("air film temperature", film_c, "(−123, 727) °C", "Sutherland's laws for air")
    ratio = temperature / KELVIN
    viscosity = 1.716e-5 * ratio**1.5 * (KELVIN + 110.4) / (temperature + 110.4)
    conductivity = 0.0241 * ratio**1.5 * (KELVIN + 194.0) / (temperature + 194.0)
    density = 101_325.0 / (287.05 * temperature)
    return AirProperties(conductivity, viscosity / density, viscosity * 1006.0 / conductivity, 1.0 / temperature)
