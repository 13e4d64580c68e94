"""Steady heat conduction in a 2-D tooth sector (scikit-fem): friction heat on the meshing flank, convection on
the other surfaces and a sink term for the end faces (docs/fem.md).

Strong form per unit face width, with T the temperature, T_a the oil temperature:

    −∇·(k ∇T) + s (T − T_a) = f                in Ω        (s = 2 h_e / b: the two end faces of a gear of width b)
    k ∂T/∂n + h (T − T_a) = g                 on Γ_R      (g: heat flux into the body, h: convection)

Weak form: ∫ k ∇T·∇v + ∫ s T v + Σ ∫_Γ h T v = ∫ (f + s T_a) v + Σ ∫_Γ (g + h T_a) v.
Boundaries not named are adiabatic (sector cut faces: cyclic symmetry of a steady field averaged over a turn).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np
import skfem
from skfem.helpers import dot, grad
from scipy.sparse.linalg import spsolve

Field = Callable[[np.ndarray, np.ndarray], np.ndarray] | float

#: Oil–air mist: air properties at about 60 °C (VDI Heat Atlas tables, rounded): k [W/(m K)], ρ [kg/m³],
#: c [J/(kg K)], η [Pa s].
AIR_CONDUCTIVITY = 0.029
AIR_DENSITY = 1.06
AIR_SPECIFIC_HEAT = 1007.0
AIR_VISCOSITY = 2.0e-5


# --------------------------------------------------------------------------------------------- functions
def blok_heat_partition(rolling_speed_1, rolling_speed_2, effusivity_1: float = 1.0, effusivity_2: float = 1.0):
    """Share of the friction heat entering body 1, β1 = B1√v1 / (B1√v1 + B2√v2) [–] (Blok; docs/fem.md).

    ``rolling_speed_1/2`` v1, v2 [m/s]; ``effusivity`` B = √(k ρ c) of each body (equal for two steel gears).
    """
    one = effusivity_1 * np.sqrt(np.asarray(rolling_speed_1, dtype=float))
    two = effusivity_2 * np.sqrt(np.asarray(rolling_speed_2, dtype=float))
    return one / (one + two)


def mean_flank_heat_flux(heat_share, friction_coefficient, unit_load, sliding_speed, radius_of_curvature,
                         conversion_factor: float = 1.0):
    """Friction heat flux on a flank averaged over one revolution, q̄ = γ β μ F′ v_s / (2π ρ) [W/m²]
    (docs/fem.md, after GEARpie CONTACT.py ``qvzp1ms``).

    ``heat_share`` β [–]; ``friction_coefficient`` μ [–]; ``unit_load`` F′ [N/m] (the pair's load per unit face
    width); ``sliding_speed`` v_s [m/s]; ``radius_of_curvature`` ρ of this flank at the point [m] (the point is in
    contact for 2a/(ω ρ) once per turn 2π/ω); ``conversion_factor`` γ: share of the friction work turned to heat.
    """
    radius = np.asarray(radius_of_curvature, dtype=float)
    return (conversion_factor * np.asarray(heat_share) * np.asarray(friction_coefficient) * np.asarray(unit_load)
            * np.asarray(sliding_speed) / (2.0 * math.pi * radius))


def mist_properties(oil_fraction: float, oil_conductivity: float, oil_density: float, oil_specific_heat: float,
                    oil_viscosity: float) -> dict[str, float]:
    """Volume-weighted oil–air mist properties (Handschuh & Kicher 1994 style mixing, docs/fem.md, unverified):
    k, ρ, η linear in the oil fraction X, c from the mixed heat capacity. Returns k [W/(m K)], rho [kg/m³],
    c [J/(kg K)], nu [m²/s], prandtl [–]."""
    x = oil_fraction
    conductivity = x * oil_conductivity + (1.0 - x) * AIR_CONDUCTIVITY
    density = x * oil_density + (1.0 - x) * AIR_DENSITY
    heat_capacity = x * oil_density * oil_specific_heat + (1.0 - x) * AIR_DENSITY * AIR_SPECIFIC_HEAT
    viscosity = x * oil_viscosity + (1.0 - x) * AIR_VISCOSITY
    specific_heat = heat_capacity / density
    return {"k": conductivity, "rho": density, "c": specific_heat, "nu": viscosity / density,
            "prandtl": viscosity * specific_heat / conductivity}


def rotating_disc_coefficient(conductivity: float, prandtl: float, angular_speed: float, kinematic_viscosity: float,
                              exponent: float = 2.0) -> float:
    """End-face convection of a free rotating disc, laminar: h = 0.308 k (m + 2)^0.5 Pr^0.5 (ω/ν)^0.5 [W/(m² K)]
    (docs/fem.md, unverified, the form cited after Patir & Cheng / Handschuh & Kicher; m: exponent of the radial
    temperature profile)."""
    return 0.308 * conductivity * math.sqrt(exponent + 2.0) * math.sqrt(prandtl) * math.sqrt(
        angular_speed / kinematic_viscosity)


def tooth_surface_coefficient(conductivity: float, prandtl: float, angular_speed: float, radius: float,
                              length: float, kinematic_viscosity: float) -> float:
    """Flank/tip convection h = 0.228 Re^0.731 Pr^(1/3) k / L, Re = ω r L / ν [W/(m² K)] (docs/fem.md, unverified)."""
    reynolds = angular_speed * radius * length / kinematic_viscosity
    return 0.228 * reynolds**0.731 * prandtl ** (1.0 / 3.0) * conductivity / length


# ----------------------------------------------------------------------------------------------- solver
def _evaluate(value: Field, x: np.ndarray) -> np.ndarray:
    if callable(value):
        return value(x[0], x[1])
    return value + 0.0 * x[0]


@dataclass(frozen=True)
class RobinBoundary:
    """A boundary (facet indices) with convection ``h`` [W/(m² K)] to ``ambient`` and an extra flux ``flux``
    [W/m²] into the body (numbers or functions of (x, y))."""

    facets: np.ndarray
    h: Field = 0.0
    ambient: Field = 0.0
    flux: Field = 0.0


def solve_steady_conduction(mesh: skfem.Mesh, conductivity: float, boundaries: list[RobinBoundary],
                            sink: float = 0.0, ambient: Field = 0.0, source: Field = 0.0,
                            element: skfem.Element | None = None) -> tuple[skfem.Basis, np.ndarray]:
    """Solve −∇·(k∇T) + s(T − T_a) = f with Robin/flux conditions (module docstring); returns (basis, T dofs).

    ``conductivity`` k [W/(m K)]; ``sink`` s [W/(m³ K)]; ``ambient`` T_a of the sink; ``source`` f [W/m³];
    ``element`` defaults to quadratic triangles.
    """
    element = element or skfem.ElementTriP2()
    basis = skfem.Basis(mesh, element)

    @skfem.BilinearForm
    def volume(u, v, w):
        return conductivity * dot(grad(u), grad(v)) + sink * u * v

    @skfem.LinearForm
    def volume_load(v, w):
        return (_evaluate(source, w.x) + sink * _evaluate(ambient, w.x)) * v

    matrix = volume.assemble(basis)
    load = volume_load.assemble(basis)
    for boundary in boundaries:
        if len(boundary.facets) == 0:
            continue
        facet_basis = skfem.FacetBasis(mesh, element, facets=boundary.facets)
        h_value, t_value, q_value = boundary.h, boundary.ambient, boundary.flux

        @skfem.BilinearForm
        def robin(u, v, w, h_value=h_value):
            return _evaluate(h_value, w.x) * u * v

        @skfem.LinearForm
        def robin_load(v, w, h_value=h_value, t_value=t_value, q_value=q_value):
            return (_evaluate(q_value, w.x) + _evaluate(h_value, w.x) * _evaluate(t_value, w.x)) * v

        matrix = matrix + robin.assemble(facet_basis)
        load = load + robin_load.assemble(facet_basis)
    return basis, spsolve(matrix.tocsc(), load)


__all__ = ["RobinBoundary", "blok_heat_partition", "mean_flank_heat_flux", "mist_properties",
           "rotating_disc_coefficient", "solve_steady_conduction", "tooth_surface_coefficient"]
