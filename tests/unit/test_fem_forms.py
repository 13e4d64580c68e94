"""Manufactured-solution convergence of the FE forms (heat and plane elasticity) on the unit square: the L2 error
must fall at the rate of the element (P1: 2, P2: 3) under uniform refinement."""

from __future__ import annotations

import numpy as np
import pytest
import skfem

from thermogear.fem.elasticity import (body_force_load, solve_many, stiffness_matrix, thermal_load, thermal_stress_factor,
                                       vector_basis)
from thermogear.fem.heat import RobinBoundary, solve_steady_conduction

K, SINK, H = 3.0, 5.0, 7.0


def exact_temperature(x, y):
    return np.sin(np.pi * x) * np.exp(y) + x * y


def _heat_error(level: int, element) -> float:
    mesh = skfem.MeshTri.init_symmetric().refined(level)
    # −k ΔT + s T = f with T_a = 0; ΔT = −π² sin(πx) e^y + sin(πx) e^y
    source = lambda x, y: -K * (1.0 - np.pi**2) * np.sin(np.pi * x) * np.exp(y) + SINK * exact_temperature(x, y)

    def flux(x, y):  # k ∂T/∂n + h T = g on the whole boundary (outward normal from the position)
        gx = np.pi * np.cos(np.pi * x) * np.exp(y) + y
        gy = np.sin(np.pi * x) * np.exp(y) + x
        nx = np.where(np.isclose(x, 1.0), 1.0, np.where(np.isclose(x, 0.0), -1.0, 0.0))
        ny = np.where(np.isclose(y, 1.0), 1.0, np.where(np.isclose(y, 0.0), -1.0, 0.0))
        return K * (gx * nx + gy * ny) + H * exact_temperature(x, y)

    basis, temperature = solve_steady_conduction(mesh, K, [RobinBoundary(mesh.boundary_facets(), h=H, flux=flux)],
                                                 sink=SINK, source=source, element=element)
    error = basis.interpolate(temperature)
    quad = basis.global_coordinates()
    values = np.asarray(error) - exact_temperature(quad[0], quad[1])
    return float(np.sqrt(np.sum(values**2 * basis.dx)))


@pytest.mark.parametrize("element, rate", [(skfem.ElementTriP1(), 2.0), (skfem.ElementTriP2(), 3.0)])
def test_heat_form_converges_at_the_element_rate(element, rate):
    errors = [_heat_error(level, element) for level in (2, 3, 4)]
    rates = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert rates[-1] == pytest.approx(rate, abs=0.25)


E, NU = 200e9, 0.3


def exact_displacement(x, y):
    return 1e-3 * np.sin(np.pi * x) * np.sin(np.pi * y), 1e-3 * x**2 * y


def _body_force(plane):
    from thermogear.fem.elasticity import plane_lame_parameters

    lam, mu = plane_lame_parameters(E, NU, plane)

    def force(x, y):  # f = −div σ(u)
        s, c = np.sin, np.cos
        p = np.pi
        uxx = -1e-3 * p**2 * s(p * x) * s(p * y)
        uxy = 1e-3 * p**2 * c(p * x) * c(p * y)
        uyy = -1e-3 * p**2 * s(p * x) * s(p * y)
        vxx, vxy, vyy = 2e-3 * y, 2e-3 * x, 0.0 * x
        fx = -((lam + 2 * mu) * uxx + mu * uyy + (lam + mu) * vxy)
        fy = -((lam + 2 * mu) * vyy + mu * vxx + (lam + mu) * uxy)
        return fx, fy

    return force


def _elastic_error(level: int, order: int, plane: str) -> float:
    mesh = skfem.MeshTri.init_symmetric().refined(level)
    basis = vector_basis(mesh, order)
    matrix = stiffness_matrix(basis, E, NU, plane)
    load = body_force_load(basis, _body_force(plane))
    fixed = basis.get_dofs().all()
    values = basis.project(lambda x: np.array(exact_displacement(x[0], x[1])))
    solution = solve_many(matrix, load, fixed, np.where(np.isin(np.arange(basis.N), fixed), values, 0.0))
    field = basis.interpolate(solution)
    quad = basis.global_coordinates()
    ux, uy = exact_displacement(quad[0], quad[1])
    displacement = np.asarray(field)
    squared = (displacement[0] - ux) ** 2 + (displacement[1] - uy) ** 2
    return float(np.sqrt(np.sum(squared * basis.dx)))


@pytest.mark.parametrize("order, rate", [(1, 2.0), (2, 3.0)])
@pytest.mark.parametrize("plane", ["stress", "strain"])
def test_elasticity_form_converges_at_the_element_rate(order, rate, plane):
    errors = [_elastic_error(level, order, plane) for level in (2, 3, 4)]
    rates = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert rates[-1] == pytest.approx(rate, abs=0.3)


@pytest.mark.parametrize("plane, strain_factor", [("stress", 1.0), ("strain", 1.3)])
def test_uniform_temperature_rise_of_a_free_body_is_stress_free_expansion(plane, strain_factor):
    """A free square heated uniformly expands homogeneously by α ΔT (plane stress) or (1 + ν) α ΔT (plane
    strain); rigid motion fixed by three dof constraints at the corner (0, 0) and (1, 0)."""
    mesh = skfem.MeshTri.init_symmetric().refined(2)
    basis = vector_basis(mesh, 2)
    matrix = stiffness_matrix(basis, E, NU, plane)
    load = thermal_load(basis, E, NU, plane, 1e-5, 50.0)
    origin = int(np.argmin(np.hypot(mesh.p[0], mesh.p[1])))
    right = int(np.argmin(np.hypot(mesh.p[0] - 1.0, mesh.p[1])))
    fixed = np.array([basis.nodal_dofs[0, origin], basis.nodal_dofs[1, origin], basis.nodal_dofs[1, right]])
    solution = solve_many(matrix, load, fixed)
    strain = 50.0 * 1e-5 * strain_factor
    expected = basis.project(lambda x: np.array([strain * x[0], strain * x[1]]))
    assert np.max(np.abs(solution - expected)) < 1e-9 * strain
    assert thermal_stress_factor(E, NU, plane) > 0
