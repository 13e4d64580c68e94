"""Shaft material and annular cross-section: area, second moments and the Timoshenko shear coefficient.

Shear coefficients κ of a hollow circular section, m = inner/outer diameter:

* Cowper, "The shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33 (1966) 335–340, Table 1
  (hollow circle): κ = 6(1+ν)(1+m²)² / [(7+6ν)(1+m²)² + (20+12ν)m²]; solid: 6(1+ν)/(7+6ν).
* Hutchinson, "Shear coefficients for Timoshenko beam theory", J. Appl. Mech. 68 (2001) 87–92, hollow circle:
  κ = 6(1+ν)²(1+m²)² / [(7+12ν+4ν²)(1+m²)² + 4m²(5+6ν+2ν²)]; solid: 6(1+ν)²/(7+12ν+4ν²), the value Stephen's
  discussion (J. Appl. Mech. 68 (2001) 959) calls the widely accepted best one. The hollow form is as we read it
  from Hutchinson's paper and was checked here only through its solid limit (unverified for m > 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.errors import CaseError

__all__ = ["Material", "CrossSection", "cowper_shear_coefficient", "hutchinson_shear_coefficient"]


def _positive(key: str, value: float, reason: str) -> float:
    number = float(value)
    if not math.isfinite(number) or number <= 0.0:
        raise CaseError(key, value, "> 0, finite", reason)
    return number


def cowper_shear_coefficient(poisson_ratio: float, diameter_ratio: float) -> float:
    """Cowper (1966) shear coefficient κ [-] of a hollow circle, diameter_ratio m = d_i/d_o in [0, 1)."""
    nu, m2 = poisson_ratio, diameter_ratio**2
    square = (1.0 + m2) ** 2
    return 6.0 * (1.0 + nu) * square / ((7.0 + 6.0 * nu) * square + (20.0 + 12.0 * nu) * m2)


def hutchinson_shear_coefficient(poisson_ratio: float, diameter_ratio: float) -> float:
    """Hutchinson (2001) shear coefficient κ [-] of a hollow circle, diameter_ratio m = d_i/d_o in [0, 1)."""
    nu, m2 = poisson_ratio, diameter_ratio**2
    square = (1.0 + m2) ** 2
    return (6.0 * (1.0 + nu) ** 2 * square
            / ((7.0 + 12.0 * nu + 4.0 * nu**2) * square + 4.0 * m2 * (5.0 + 6.0 * nu + 2.0 * nu**2)))


@dataclass(frozen=True)
class Material:
    """Isotropic linear-elastic shaft material: Young's modulus E [Pa], shear modulus G [Pa], density ρ [kg/m³].

    Give G, or leave it None and give Poisson's ratio ν (G = E/(2(1+ν))). When both are given, ν is the one used
    in the shear coefficient and G the one in the stiffness (as Friswell et al. 2010 give E, G and ρ separately).
    """

    youngs_modulus: float
    density: float
    shear_modulus: float | None = None
    poisson_ratio: float | None = None

    def __post_init__(self) -> None:
        _positive("material.youngs_modulus", self.youngs_modulus, "E in Pa must be positive")
        _positive("material.density", self.density, "ρ in kg/m³ must be positive")
        if self.shear_modulus is None and self.poisson_ratio is None:
            raise CaseError("material.shear_modulus", None, "a shear modulus [Pa] or a Poisson's ratio",
                            "torsion and shear need G")
        if self.poisson_ratio is not None and not -1.0 < float(self.poisson_ratio) < 0.5:
            raise CaseError("material.poisson_ratio", self.poisson_ratio, "(-1, 0.5)", "isotropic elasticity")
        if self.shear_modulus is not None:
            _positive("material.shear_modulus", self.shear_modulus, "G in Pa must be positive")

    @property
    def shear(self) -> float:
        """Shear modulus G [Pa]."""
        if self.shear_modulus is not None:
            return float(self.shear_modulus)
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))

    @property
    def poisson(self) -> float:
        """Poisson's ratio ν [-] (from E and G where not given: ν = E/(2G) − 1)."""
        if self.poisson_ratio is not None:
            return float(self.poisson_ratio)
        return self.youngs_modulus / (2.0 * self.shear_modulus) - 1.0


@dataclass(frozen=True)
class CrossSection:
    """Annular shaft section: outer and inner diameter [m] (inner 0 for a solid shaft)."""

    outer_diameter: float
    inner_diameter: float = 0.0

    def __post_init__(self) -> None:
        _positive("outer_diameter", self.outer_diameter, "a shaft section needs a positive diameter [m]")
        inner = float(self.inner_diameter)
        if not math.isfinite(inner) or not 0.0 <= inner < self.outer_diameter:
            raise CaseError("inner_diameter", self.inner_diameter, f"[0, {self.outer_diameter}) m",
                            "the bore must be smaller than the outer diameter")

    @property
    def area(self) -> float:
        """A = π(d_o² − d_i²)/4 [m²]."""
        return math.pi * (self.outer_diameter**2 - self.inner_diameter**2) / 4.0

    @property
    def second_moment(self) -> float:
        """Diametral second moment of area I = π(d_o⁴ − d_i⁴)/64 [m⁴]."""
        return math.pi * (self.outer_diameter**4 - self.inner_diameter**4) / 64.0

    @property
    def polar_moment(self) -> float:
        """Polar second moment J = 2I [m⁴] (torsion constant of a circular tube)."""
        return 2.0 * self.second_moment

    @property
    def diameter_ratio(self) -> float:
        """m = d_i/d_o [-]."""
        return self.inner_diameter / self.outer_diameter
