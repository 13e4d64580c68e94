"""Timoshenko shaft element: two nodes, 6 DOF each (x, y, z, α, β, θ), bending in two planes, axial, torsion.

Bending after the shear-deformable beam element with interpolation depending on the shear parameter
φ = 12EI/(κGAL²) (Przemieniecki, Theory of Matrix Structural Analysis, 1968; the consistent translational and
rotary mass in the form of Friswell, Penny, Garvey & Lees, Dynamics of Rotating Machines, CUP 2010, §5.4, and of
Nelson, "A finite rotating shaft element using Timoshenko beam theory", J. Mech. Des. 102 (1980) 793–803).
φ = 0 gives the Euler–Bernoulli element. In the x–z plane the DOFs are (x₁, β₁, x₂, β₂) with dx/dz = +β; in the
y–z plane (y₁, α₁, y₂, α₂) with dy/dz = −α, i.e. the same matrices transformed by T = diag(1, −1, 1, −1).
The gyroscopic matrix follows from the spin inertia ρJ = 2ρI per length (Nelson 1980): it couples the two planes
through the rotary-inertia matrix, G(y, x) = −2·T·M_R, G(x, y) = 2·M_R·T, and is multiplied by the shaft speed.
Torsion and axial motion use linear elements: K = (GJ/L)[[1, −1], [−1, 1]], M = (ρJL/6)[[2, 1], [1, 2]].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.section import CrossSection, Material, cowper_shear_coefficient
from thermogear.errors import CaseError

__all__ = ["ShaftElement", "bending_stiffness", "translational_mass", "rotary_mass"]

_X_PLANE = np.array([0, 4, 6, 10])   # x1, β1, x2, β2 in the 12 element DOFs
_Y_PLANE = np.array([1, 3, 7, 9])    # y1, α1, y2, α2
_AXIAL = np.array([2, 8])
_TORSION = np.array([5, 11])
_PLANE_SIGNS = np.diag([1.0, -1.0, 1.0, -1.0])


def bending_stiffness(ei: float, length: float, phi: float) -> np.ndarray:
    """4×4 bending stiffness [N/m, N, N·m] on (w₁, ψ₁, w₂, ψ₂), shear parameter φ (Przemieniecki 1968)."""
    L = length
    return ei / (L**3 * (1.0 + phi)) * np.array([
        [12.0, 6.0 * L, -12.0, 6.0 * L],
        [6.0 * L, (4.0 + phi) * L**2, -6.0 * L, (2.0 - phi) * L**2],
        [-12.0, -6.0 * L, 12.0, -6.0 * L],
        [6.0 * L, (2.0 - phi) * L**2, -6.0 * L, (4.0 + phi) * L**2]])


def translational_mass(rho_a: float, length: float, phi: float) -> np.ndarray:
    """4×4 consistent translational mass [kg, kg·m, kg·m²] on (w₁, ψ₁, w₂, ψ₂) (Friswell et al. 2010 §5.4)."""
    L, p = length, phi
    a = 312.0 + 588.0 * p + 280.0 * p**2
    b = (44.0 + 77.0 * p + 35.0 * p**2) * L
    d = 108.0 + 252.0 * p + 140.0 * p**2
    e = (26.0 + 63.0 * p + 35.0 * p**2) * L
    f = (8.0 + 14.0 * p + 7.0 * p**2) * L**2
    g = (6.0 + 14.0 * p + 7.0 * p**2) * L**2
    return rho_a * L / (840.0 * (1.0 + p) ** 2) * np.array([
        [a, b, d, -e], [b, f, e, -g], [d, e, a, -b], [-e, -g, -b, f]])


def rotary_mass(rho_i: float, length: float, phi: float) -> np.ndarray:
    """4×4 consistent rotary-inertia mass on (w₁, ψ₁, w₂, ψ₂), ρI per length [kg·m] (Friswell et al. 2010 §5.4)."""
    L, f = length, phi
    p = (3.0 - 15.0 * f) * L
    s = (4.0 + 5.0 * f + 10.0 * f**2) * L**2
    t = (-1.0 - 5.0 * f + 5.0 * f**2) * L**2
    return rho_i / (30.0 * L * (1.0 + f) ** 2) * np.array([
        [36.0, p, -36.0, p], [p, s, -p, t], [-36.0, -p, 36.0, -p], [p, t, -p, s]])


def _place(target: np.ndarray, block: np.ndarray, rows: np.ndarray, columns: np.ndarray) -> None:
    target[np.ix_(rows, columns)] += block


@dataclass(frozen=True)
class ShaftElement:
    """One uniform Timoshenko shaft element of length [m], section and material.

    ``shear_coefficient`` κ [-]: None takes Cowper's (1966) value for the section and ν; pass
    ``hutchinson_shear_coefficient(ν, m)`` or any number in (0, 1] to choose another. ``shear_deformation`` False
    gives the Euler–Bernoulli element (φ = 0); ``rotary_inertia`` False drops the rotary-inertia mass (and with it
    the gyroscopic matrix, which comes from the same spin inertia).
    """

    length: float
    section: CrossSection
    material: Material
    shear_coefficient: float | None = None
    shear_deformation: bool = True
    rotary_inertia: bool = True

    def __post_init__(self) -> None:
        length = float(self.length)
        if not math.isfinite(length) or length <= 0.0:
            raise CaseError("shaft element length", self.length, "> 0 m", "an element needs a positive length")
        if self.shear_coefficient is not None and not 0.0 < float(self.shear_coefficient) <= 1.0:
            raise CaseError("shear_coefficient", self.shear_coefficient, "(0, 1]",
                            "κ of a solid or hollow circle lies between about 0.5 and 0.93")

    @property
    def kappa(self) -> float:
        """Shear coefficient κ [-] used by the element."""
        if self.shear_coefficient is not None:
            return float(self.shear_coefficient)
        return cowper_shear_coefficient(self.material.poisson, self.section.diameter_ratio)

    @property
    def shear_parameter(self) -> float:
        """φ = 12EI/(κGAL²) [-], 0 for an Euler–Bernoulli element."""
        if not self.shear_deformation:
            return 0.0
        s, m = self.section, self.material
        return 12.0 * m.youngs_modulus * s.second_moment / (self.kappa * m.shear * s.area * self.length**2)

    def stiffness(self) -> np.ndarray:
        """12×12 stiffness matrix [SI]."""
        s, m, L = self.section, self.material, self.length
        plane = bending_stiffness(m.youngs_modulus * s.second_moment, L, self.shear_parameter)
        matrix = np.zeros((12, 12))
        _place(matrix, plane, _X_PLANE, _X_PLANE)
        _place(matrix, _PLANE_SIGNS @ plane @ _PLANE_SIGNS, _Y_PLANE, _Y_PLANE)
        bar = np.array([[1.0, -1.0], [-1.0, 1.0]])
        _place(matrix, m.youngs_modulus * s.area / L * bar, _AXIAL, _AXIAL)
        _place(matrix, m.shear * s.polar_moment / L * bar, _TORSION, _TORSION)
        return matrix

    def _rotary(self) -> np.ndarray:
        return rotary_mass(self.material.density * self.section.second_moment, self.length, self.shear_parameter)

    def mass(self) -> np.ndarray:
        """12×12 consistent mass matrix [SI]."""
        s, m, L = self.section, self.material, self.length
        phi = self.shear_parameter
        plane = translational_mass(m.density * s.area, L, phi)
        if self.rotary_inertia:
            plane = plane + self._rotary()
        matrix = np.zeros((12, 12))
        _place(matrix, plane, _X_PLANE, _X_PLANE)
        _place(matrix, _PLANE_SIGNS @ plane @ _PLANE_SIGNS, _Y_PLANE, _Y_PLANE)
        consistent = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
        _place(matrix, m.density * s.area * L * consistent, _AXIAL, _AXIAL)
        _place(matrix, m.density * s.polar_moment * L * consistent, _TORSION, _TORSION)
        return matrix

    def gyroscopic(self) -> np.ndarray:
        """12×12 skew-symmetric gyroscopic matrix per unit spin speed [kg·m² per rad/s of spin]."""
        matrix = np.zeros((12, 12))
        if not self.rotary_inertia:
            return matrix
        rotary = self._rotary()
        _place(matrix, -2.0 * _PLANE_SIGNS @ rotary, _Y_PLANE, _X_PLANE)
        _place(matrix, 2.0 * rotary @ _PLANE_SIGNS, _X_PLANE, _Y_PLANE)
        return matrix
