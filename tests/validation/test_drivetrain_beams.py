"""A single shaft against analytic beam and rod frequencies, with mesh convergence.

Euler–Bernoulli: ω_n = (β_nL)²·√(EI/(ρAL⁴)); simply supported β_nL = nπ, free–free cos x·cosh x = 1 (roots
4.730041, 7.853205, 10.995608; Blevins, Formulas for Natural Frequency and Mode Shape, 1979, Table 8-1).
Timoshenko, simply supported (w = sin kz, ψ = cos kz, k = nπ/L in ρAẅ = κGA(w″ − ψ′), ρIψ̈ = EIψ″ + κGA(w′ − ψ);
Timoshenko 1921): ρ²AI·ω⁴ − (ρIκGAk² + ρA·EIk² + ρA·κGA)·ω² + κGA·EIk⁴ = 0, lower root.
Torsion of a shaft carrying end disks J₁, J₂ (wave equation with inertial end conditions):
tan βL = (μ₁ + μ₂)/(μ₁μ₂/β − β), β = ω√(ρ/G), μ_i = J_iω²/(GJ_p); massless-shaft limit ω² = k(1/J₁ + 1/J₂).
The element is exact for none of these; it converges from above (consistent mass, Rayleigh–Ritz).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.linalg import eigh
from scipy.optimize import brentq

from thermogear.drivetrain import (CrossSection, Drivetrain, Material, NodeLocation, RigidDisk, Shaft, ShaftSegment,
                                   cowper_shear_coefficient)

STEEL = Material(youngs_modulus=211e9, density=7810.0, poisson_ratio=0.3)
DIAMETER = 0.05
FREE_FREE_ROOTS = (4.730040745, 7.853204624, 10.995607838)


def _shaft(length, elements, shear=True, rotary=True, material=STEEL, disks=()):
    shaft = Shaft("shaft", (ShaftSegment(length, CrossSection(DIAMETER), material),), length / elements * (1 + 1e-12),
                  shear_deformation=shear, rotary_inertia=rotary)
    return Drivetrain((shaft,), disks).assemble()


def _plane(assembled, fixed):
    keep = []
    for node, z in enumerate(assembled.node_positions["shaft"]):
        if not any(abs(z - p) < 1e-12 for p in fixed):
            keep.append(6 * node)
        keep.append(6 * node + 4)
    keep = np.array(keep)
    return assembled.mass[np.ix_(keep, keep)], assembled.structure_stiffness[np.ix_(keep, keep)]


def _bending(length, elements, fixed, shear=True, rotary=True, count=3, skip=0):
    mass, stiffness = _plane(_shaft(length, elements, shear, rotary), fixed)
    values = eigh(stiffness, mass, eigvals_only=True, subset_by_index=(0, skip + count - 1))
    return np.sqrt(np.clip(values[skip:], 0.0, None))


def _euler_bernoulli(length, roots):
    section = CrossSection(DIAMETER)
    return np.array(roots) ** 2 * math.sqrt(STEEL.youngs_modulus * section.second_moment
                                            / (STEEL.density * section.area * length**4))


def _timoshenko(length, n):
    s, m = CrossSection(DIAMETER), STEEL
    kappa = cowper_shear_coefficient(m.poisson, 0.0)
    k = n * math.pi / length
    rho, a, i, e, g = m.density, s.area, s.second_moment, m.youngs_modulus, m.shear * kappa
    quartic, middle, constant = rho**2 * a * i, rho * i * g * a * k**2 + rho * a * e * i * k**2 + rho * a * g * a, \
        g * a * e * i * k**4
    return math.sqrt((middle - math.sqrt(middle**2 - 4 * quartic * constant)) / (2 * quartic))


@pytest.mark.parametrize("support, fixed, roots, skip", [
    ("simply supported", (0.0, 1.0), (math.pi, 2 * math.pi, 3 * math.pi), 0),
    ("free-free", (), FREE_FREE_ROOTS, 2),
])
def test_euler_bernoulli_beam_converges_from_above_at_fourth_order(support, fixed, roots, skip):
    exact = _euler_bernoulli(1.0, roots)
    errors = np.array([_bending(1.0, n, fixed, shear=False, rotary=False, skip=skip) / exact - 1.0
                       for n in (4, 8, 16, 32)])
    # Rayleigh–Ritz with consistent mass: every frequency from above, and each halving of h lowers the error
    assert np.all(errors > 0.0)
    assert np.all(np.diff(errors, axis=0) < 0.0)
    # cubic Hermite elements: O(h⁴) in the eigenvalue error; observed order of mode 1 between 3.5 and 4.5
    order = np.log2(errors[1, 0] / errors[2, 0])
    assert 3.5 < order < 4.5
    # converged mesh: within 0.1 % (the criterion), in fact far inside it
    assert np.abs(errors[-1]).max() < 1e-3


def test_slender_timoshenko_shaft_tends_to_euler_bernoulli():
    # L/d = 200: shear and rotary inertia change the first three frequencies by < 0.01 % (ratio 1 − O((d/L)²))
    length = 200 * DIAMETER
    frequencies = _bending(length, 32, (0.0, length))
    assert np.allclose(frequencies, _euler_bernoulli(length, (math.pi, 2 * math.pi, 3 * math.pi)), rtol=1e-3)


@pytest.mark.parametrize("slenderness, modes", [(5.0, (1, 2, 3)), (2.0, (1, 2))])
def test_stubby_timoshenko_shaft_against_the_exact_frequency_equation(slenderness, modes):
    length = slenderness * DIAMETER
    exact = np.array([_timoshenko(length, n) for n in modes])
    coarse, fine = (_bending(length, n, (0.0, length), count=len(modes)) for n in (16, 64))
    # converged mesh within 0.1 %; from above, and closer on the finer mesh
    assert np.abs(fine / exact - 1.0).max() < 1e-3
    assert np.all(fine >= exact * (1 - 1e-12)) and np.all(coarse > fine)
    # shear matters here: Euler–Bernoulli is off by > 4 % on mode 1 (so the test can tell the theories apart)
    assert _euler_bernoulli(length, (math.pi,))[0] / exact[0] - 1.0 > 0.04


def _two_inertia_exact(length, polar_1, polar_2):
    section, m = CrossSection(DIAMETER), STEEL
    gj = m.shear * section.polar_moment

    def residual(omega):
        beta = omega * math.sqrt(m.density / m.shear)
        mu_1, mu_2 = polar_1 * omega**2 / gj, polar_2 * omega**2 / gj
        return math.sin(beta * length) * (mu_1 * mu_2 / beta - beta) - (mu_1 + mu_2) * math.cos(beta * length)

    guess = math.sqrt(gj / length * (1 / polar_1 + 1 / polar_2))
    return brentq(residual, 0.5 * guess, 1.0 * guess)


def _torsion(length, elements, polar_1, polar_2, material=STEEL):
    disks = (RigidDisk("one", NodeLocation("shaft", 0.0), 1.0, polar_1, 1.0),
             RigidDisk("two", NodeLocation("shaft", length), 1.0, polar_2, 1.0))
    assembled = _shaft(length, elements, material=material, disks=disks)
    theta = np.arange(5, assembled.size, 6)
    values = eigh(assembled.structure_stiffness[np.ix_(theta, theta)], assembled.mass[np.ix_(theta, theta)],
                  eigvals_only=True, subset_by_index=(1, 1))
    return math.sqrt(values[0])


def test_two_inertia_torsion_shaft():
    length, polar_1, polar_2 = 0.5, 0.02, 0.05
    exact = _two_inertia_exact(length, polar_1, polar_2)
    errors = [_torsion(length, n, polar_1, polar_2) / exact - 1.0 for n in (1, 2, 4, 8)]
    # linear elements, consistent mass: from above, monotone, within 0.1 % once refined (O(h²))
    assert all(e > 0 for e in errors) and all(a > b for a, b in zip(errors, errors[1:]))
    assert errors[-1] < 1e-3
    # a nearly massless shaft is the two-inertia closed form ω² = (GJ/L)(1/J₁ + 1/J₂), to rounding
    light = Material(youngs_modulus=211e9, density=1e-9, poisson_ratio=0.3)
    gj = light.shear * CrossSection(DIAMETER).polar_moment
    closed = math.sqrt(gj / length * (1 / polar_1 + 1 / polar_2))
    assert _torsion(length, 1, polar_1, polar_2, light) == pytest.approx(closed, rel=1e-9)
