"""2-D linear (thermo-)elasticity forms (scikit-fem), plane stress or plane strain, per unit thickness.

    ∫ σ(u):ε(v) = ∫ f·v + ∫_Γ t·v + ∫ c_th α ΔT div v,   σ = 2μ ε + λ* tr(ε) I

with λ* = E ν/(1 − ν²) (plane stress) or E ν/((1 + ν)(1 − 2ν)) (plane strain), μ = E/(2(1 + ν)), and the thermal
stress per unit α ΔT, c_th = E/(1 − ν) (plane stress; in-plane thermal strain α ΔT) or E/(1 − 2ν) (plane strain;
in-plane thermal strain (1 + ν) α ΔT). Sources: Timoshenko & Goodier, Theory of Elasticity, ch. 13 (thermal
stress); scikit-fem's ``skfem.models.elasticity``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Literal

import numpy as np
import skfem
from scipy.sparse.linalg import splu
from skfem.helpers import div
from skfem.models.elasticity import lame_parameters, linear_elasticity, plane_stress

Plane = Literal["stress", "strain"]


@dataclass(frozen=True)
class PlaneAssumption:
    """A 2-D elasticity assumption (``[fem] plane``, module docstring): ``lame(E, ν)`` → (λ*, μ) [Pa],
    ``thermal_stress(E, ν)`` → c_th [Pa], and the ``other`` assumption (the FE check's comparison run)."""

    name: str
    lame: Callable[[float, float], tuple[float, float]]
    thermal_stress: Callable[[float, float], float]
    other: str


#: The plane assumptions by name: the one place the names are compared.
PLANE_ASSUMPTIONS: dict[str, PlaneAssumption] = {assumption.name: assumption for assumption in (
    PlaneAssumption("stress", plane_stress, lambda youngs, poisson: youngs / (1.0 - poisson), "strain"),
    PlaneAssumption("strain", lame_parameters, lambda youngs, poisson: youngs / (1.0 - 2.0 * poisson), "stress"))}


def plane_assumption(plane: str) -> PlaneAssumption:
    """The plane assumption called ``plane``; ValueError for any other name."""
    assumption = PLANE_ASSUMPTIONS.get(plane)
    if assumption is None:
        raise ValueError(f"plane must be 'stress' or 'strain', not {plane!r}")
    return assumption


def plane_lame_parameters(youngs_modulus: float, poisson_ratio: float, plane: Plane) -> tuple[float, float]:
    """(λ*, μ) [Pa] of the 2-D constitutive law (module docstring)."""
    return plane_assumption(plane).lame(youngs_modulus, poisson_ratio)


def thermal_stress_factor(youngs_modulus: float, poisson_ratio: float, plane: Plane) -> float:
    """c_th [Pa]: isotropic in-plane thermal stress per unit α ΔT of a fully restrained 2-D body."""
    return plane_assumption(plane).thermal_stress(youngs_modulus, poisson_ratio)


def vector_basis(mesh: skfem.Mesh, order: int = 2) -> skfem.Basis:
    """Vector Lagrange basis on triangles (P2 default)."""
    scalar = skfem.ElementTriP2() if order == 2 else skfem.ElementTriP1()
    return skfem.Basis(mesh, skfem.ElementVector(scalar))


def stiffness_matrix(basis: skfem.Basis, youngs_modulus: float, poisson_ratio: float, plane: Plane):
    """Assembled elasticity matrix [N/m per unit thickness]."""
    lam, mu = plane_lame_parameters(youngs_modulus, poisson_ratio, plane)
    return linear_elasticity(lam, mu).assemble(basis)


def thermal_load(basis: skfem.Basis, youngs_modulus: float, poisson_ratio: float, plane: Plane,
                 expansion_coefficient: float, rise) -> np.ndarray:
    """Load vector of a temperature rise: ∫ c_th α ΔT div v. ``rise`` ΔT [K]: a number, a function of (x, y), or
    a scalar :class:`skfem.DiscreteField` at the basis' quadrature points (``scalar_basis.interpolate(T)``)."""
    factor = thermal_stress_factor(youngs_modulus, poisson_ratio, plane) * expansion_coefficient
    if isinstance(rise, skfem.DiscreteField):
        @skfem.LinearForm
        def field_form(v, w):
            return factor * w["rise"] * div(v)

        return field_form.assemble(basis, rise=rise)

    @skfem.LinearForm
    def form(v, w):
        value = rise(w.x[0], w.x[1]) if callable(rise) else rise + 0.0 * w.x[0]
        return factor * value * div(v)

    return form.assemble(basis)


def _vector_load(basis: skfem.AbstractBasis, density: Callable[[np.ndarray, np.ndarray], tuple]) -> np.ndarray:
    """Load vector ∫ (d_x v_x + d_y v_y) of a vector load density d(x, y) = (d_x, d_y) over the basis' cells (a
    body force) or facets (a traction)."""

    @skfem.LinearForm
    def form(v, w):
        dx, dy = density(w.x[0], w.x[1])
        return dx * v[0] + dy * v[1]

    return form.assemble(basis)


def body_force_load(basis: skfem.Basis, force: Callable[[np.ndarray, np.ndarray], tuple]) -> np.ndarray:
    """Load vector of a body force f(x, y) = (f_x, f_y) [N/m³]."""
    return _vector_load(basis, force)


def traction_load(facet_basis: skfem.FacetBasis, traction: Callable[[np.ndarray, np.ndarray], tuple]) -> np.ndarray:
    """Load vector of a surface traction t(x, y) = (t_x, t_y) [N/m²] on the facet basis' facets."""
    return _vector_load(facet_basis, traction)


def solve_many(matrix, loads: np.ndarray, fixed_dofs: np.ndarray, fixed_values: np.ndarray | None = None) -> np.ndarray:
    """Solve K u = b for several load columns with the dofs ``fixed_dofs`` prescribed (zero by default): one
    sparse LU factorisation for all columns. ``loads`` (n,) or (n, m); returns the same shape."""
    loads = np.asarray(loads, dtype=float)
    single = loads.ndim == 1
    loads = loads[:, None] if single else loads
    count = matrix.shape[0]
    prescribed = np.zeros(count) if fixed_values is None else np.asarray(fixed_values, dtype=float)
    free = np.setdiff1d(np.arange(count), fixed_dofs)
    matrix = matrix.tocsr()
    factor = splu(matrix[free][:, free].tocsc())
    rhs = loads[free] - (matrix[free] @ prescribed)[:, None]
    solution = np.repeat(prescribed[:, None], loads.shape[1], axis=1)
    solution[free] = factor.solve(rhs)
    return solution[:, 0] if single else solution


__all__ = ["PLANE_ASSUMPTIONS", "PlaneAssumption", "body_force_load", "plane_assumption", "plane_lame_parameters", "solve_many", "stiffness_matrix", "thermal_load",
           "thermal_stress_factor", "traction_load", "vector_basis"]
