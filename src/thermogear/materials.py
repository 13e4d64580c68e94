"""Gear material."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Material:
    """Isotropic linear-elastic, thermally conducting gear material (SI units)."""

    youngs_modulus: float = 206e9  # E [Pa]
    poisson_ratio: float = 0.3  # ν [–]
    density: float = 7850.0  # ρ [kg/m³]
    specific_heat: float = 465.0  # c [J/(kg K)]
    thermal_conductivity: float = 46.0  # k_th [W/(m K)]
    thermal_expansion: float = 11.5e-6  # α_th [1/K]

    @property
    def shear_modulus(self) -> float:
        """G = E / (2(1 + ν)) [Pa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))

    @property
    def thermal_effusivity(self) -> float:
        """sqrt(k ρ c) [W s^0.5/(m² K)], the thermal contact coefficient of Blok's heat partition."""
        return (self.thermal_conductivity * self.density * self.specific_heat) ** 0.5
