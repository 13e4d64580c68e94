"""Elastic and thermo-elastic deformation of one gear's tooth at the contact points of the path (2-D, P2).

Model (docs/fem.md):
- domain: by default the whole gear (``[fem].sector_teeth = 0``) from the bore to the tips, fine on the loaded
  tooth and its two neighbours, coarse elsewhere; or a sector of an odd number of teeth cut on radial lines
  through the tooth-space centres (cut faces free: too soft for few teeth, kept for studies); plane stress (the
  potential energy method uses E) or plane strain;
- elastic runs: bore clamped (rigid shaft; the Sainsot fillet-foundation term of the potential energy method
  assumes a rim down to a fixed bore). One run per contact point: the normal load, per unit face
  width, spread over the Hertz half-width a_H = 2√(F′R/(πE*)) as an elliptical pressure along the line of action;
- local contact deformation is separated by reading the **section** of the tooth at the height of the contact
  point instead of the loaded surface point: the displacement across the chord through K perpendicular to the
  tooth centreline is fitted by plane-section kinematics (mean transverse displacement, linear axial
  displacement = translation + rotation) over the inner part of the chord (−0.75 x_K … +0.5 x_K), and that
  rigid-section motion taken to K and projected on the line of action is the tooth deflection. What is left out
  is the near field of the contact (Hertz flattening), which the pair model adds back as the Hertz compliance
  4(1 − ν²)/(π E b) of Tian 2004; Chaari et al. 2009, as in the potential energy method. The PEM compliance compared with is
  bending + shear + axial + fillet foundation;
- thermal runs: the bulk temperature rise above the stress-free reference as a load, bore free, cut faces on
  rollers (no displacement normal to the radial cut lines: cyclic symmetry of a tooth field and a free gear
  that expands about its centre, as Eq. 10 assumes). The thermal displacement of the contact point K projected
  on the flank's outward normal (the line of action) is the FE flank expansion, to compare with Eqs. 8–12.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

import numpy as np
import skfem
from skfem.helpers import dot

from thermogear.fem.elasticity import (solve_many, stiffness_matrix, thermal_load, traction_load, vector_basis)
from thermogear.fem.sampling import probe_matrix
from thermogear.fem.tooth_heat import gear_of
from thermogear.fem.tooth_mesh import ToothMesh, nominal_bore_radius, tooth_mesh
from thermogear.schema.fem import FemSection

if TYPE_CHECKING:
    from thermogear.geometry import GearPair
    from thermogear.materials import Material

#: Chord of the section reading, as fractions of x_K (the contact point's distance from the centreline).
SECTION_FROM, SECTION_TO, SECTION_POINTS = -0.75, 0.5, 13

#: Roller penalty on the cut faces of the thermal runs, relative to E / module [–].
ROLLER_PENALTY = 1e5

#: Distance by which K is moved into the tooth for the thermal displacement probe [m].
INWARD_OFFSET = 2e-6


# --------------------------------------------------------------------------------------------- functions
def contact_point_geometry(gear, own_roll):
    """Contact point K of a gear's right flank at its own roll distance ρ [m]: (x_K, y_K) [m] in the tooth frame,
    the load angle ω = α_K − φ_K [rad] (= α1 of Chaari et al. (2009)) and the outward flank normal (cos ω, sin ω)."""
    own_roll = np.asarray(own_roll, dtype=float)
    radius = np.hypot(gear.base_radius, own_roll)
    half_angle = np.asarray(gear.half_angle_at(radius), dtype=float)
    load_angle = np.arctan2(own_roll, gear.base_radius) - half_angle
    return (radius * np.sin(half_angle), radius * np.cos(half_angle), load_angle,
            np.stack([np.cos(load_angle), np.sin(load_angle)]))


def hertz_half_width(unit_load, relative_radius, youngs_modulus: float, poisson_ratio: float):
    """a_H = 2 √(F′ R / (π E*)), 1/E* = 2 (1 − ν²)/E for two equal materials [m] (docs/fem.md)."""
    effective = youngs_modulus / (2.0 * (1.0 - poisson_ratio**2))
    return 2.0 * np.sqrt(np.asarray(unit_load) * np.asarray(relative_radius) / (math.pi * effective))


def section_deflection(ux, uy, chord_x, contact_x, normal):
    """Rigid-section motion of a tooth section taken to K and projected on −n (positive into the tooth) [m].

    ``ux``, ``uy`` (points, loads): displacements across the chord at positions ``chord_x`` (points, loads);
    ``contact_x`` x_K (loads); ``normal`` (2, loads). Fit: u_x = mean, u_y = b + θ x (least squares).
    Returns (deflection (loads,), displacement of K (2, loads)).
    """
    mean_x = chord_x.mean(axis=0)
    slope = np.sum((chord_x - mean_x) * (uy - uy.mean(axis=0)), axis=0) / np.sum((chord_x - mean_x) ** 2, axis=0)
    axial = uy.mean(axis=0) + slope * (contact_x - mean_x)
    transverse = ux.mean(axis=0)
    displacement = np.stack([transverse, axial])
    return -(displacement[0] * normal[0] + displacement[1] * normal[1]), displacement


# ------------------------------------------------------------------------------------------------ model
@dataclass(frozen=True, eq=False)
class ToothModel:
    """The assembled elasticity problem of one gear's tooth sector (the ``which`` gear of ``gear_pair``)."""

    gear_pair: "GearPair"
    material: "Material"
    which: str
    mesh: ToothMesh
    basis: skfem.CellBasis
    matrix: object
    plane: str

    @property
    def gear(self):
        return self.mesh.gear

    @property
    def x_dofs(self) -> np.ndarray:
        return np.concatenate([self.basis.nodal_dofs[0], self.basis.facet_dofs[0]])

    @property
    def y_dofs(self) -> np.ndarray:
        return np.concatenate([self.basis.nodal_dofs[1], self.basis.facet_dofs[1]])

    def contact_loads(self, own_roll, unit_load: float) -> np.ndarray:
        """Load columns (dofs, contacts) of a unit resultant [N per m of face width] pressing on the right flank
        of the middle tooth at each contact point, spread over the Hertz half-width of ``unit_load`` [N/m]."""
        gear, material = self.gear, self.material
        x_k, y_k, _, normal = contact_point_geometry(gear, own_roll)
        relative = self.gear_pair.relative_radius_of_curvature(self._pair_roll(own_roll))
        half_width = hertz_half_width(unit_load, relative, material.youngs_modulus, material.poisson_ratio)
        facets = self.mesh.facets("active_flank")
        facet_basis = skfem.FacetBasis(self.mesh.mesh, self.basis.elem, facets=facets, intorder=6)
        ends = self.mesh.mesh.p[:, self.mesh.mesh.facets[:, facets]]
        spacing = float(np.max(np.hypot(*(ends[:, 0] - ends[:, 1]))))  # the window spans at least two facets
        columns = []
        for index in range(len(x_k)):
            width = max(float(half_width[index]), spacing)
            centre = (x_k[index], y_k[index])
            direction = -normal[:, index]

            def traction(x, y, centre=centre, width=width, direction=direction):
                distance = np.hypot(x - centre[0], y - centre[1]) / width
                pressure = np.sqrt(np.clip(1.0 - distance**2, 0.0, None))
                return direction[0] * pressure, direction[1] * pressure

            column = traction_load(facet_basis, traction)
            resultant = np.hypot(column[self.x_dofs].sum(), column[self.y_dofs].sum())
            if not resultant > 0.0:
                raise RuntimeError("the contact load window holds no quadrature point; refine the flank mesh")
            columns.append(column / resultant)
        return np.column_stack(columns)

    def _pair_roll(self, own_roll):
        pair = self.gear_pair
        return own_roll if self.which == "pinion" else pair.line_of_action_length - np.asarray(own_roll)

    def elastic_displacements(self, loads: np.ndarray) -> np.ndarray:
        """Solve the bore-clamped problem for the load columns."""
        fixed = self.basis.get_dofs("bore").all()
        return solve_many(self.matrix, loads, fixed)

    def section_reading(self, solutions: np.ndarray, own_roll):
        """(deflection along the line of action (contacts,), displacement of K (2, contacts)) per load column,
        by the section reading of the module docstring."""
        x_k, y_k, _, normal = contact_point_geometry(self.gear, own_roll)
        fractions = np.linspace(SECTION_FROM, SECTION_TO, SECTION_POINTS)
        chord_x = fractions[:, None] * x_k[None, :]
        chord_y = np.broadcast_to(y_k[None, :], chord_x.shape)
        probes = probe_matrix(self.basis, np.vstack([chord_x.ravel(), chord_y.ravel()]))
        values = probes @ solutions  # rows: x comps of all points, then y comps; columns: loads
        count = chord_x.size
        ux = values[:count].reshape(chord_x.shape + (-1,))
        uy = values[count:].reshape(chord_x.shape + (-1,))
        loads = np.arange(len(x_k))
        return section_deflection(ux[:, loads, loads], uy[:, loads, loads], chord_x, x_k, normal)

    def thermal_displacement(self, rise: Callable | float, expansion_coefficient: float) -> np.ndarray:
        """Displacement field [m] of a free gear (rollers on the cut faces, free bore) under a temperature rise
        ``rise`` [K] (number or function of (x, y))."""
        material = self.material
        load = thermal_load(self.basis, material.youngs_modulus, material.poisson_ratio, self.plane,
                            expansion_coefficient, rise)
        penalty = ROLLER_PENALTY * material.youngs_modulus / self.gear.module
        side = skfem.FacetBasis(self.mesh.mesh, self.basis.elem, facets=self.mesh.facets("side"))

        @skfem.BilinearForm
        def roller(u, v, w):
            return penalty * dot(u, w.n) * dot(v, w.n)

        matrix = self.matrix + roller.assemble(side)
        return solve_many(matrix, load, np.zeros(0, dtype=int))

    def point_displacement(self, solution: np.ndarray, own_roll) -> np.ndarray:
        """Displacement (2, contacts) [m] of the contact points (probed just inside the flank)."""
        x_k, y_k, _, _ = contact_point_geometry(self.gear, own_roll)
        radius = np.hypot(x_k, y_k)
        angle = np.arctan2(x_k, y_k) - INWARD_OFFSET / radius
        values = probe_matrix(self.basis, np.vstack([radius * np.sin(angle), radius * np.cos(angle)])) @ solution
        return values.reshape(2, -1)


def tooth_model(gear_pair: "GearPair", material: "Material", which: str, settings: FemSection,
                refinement: float | None = None, plane: str | None = None, teeth: int | None = None) -> ToothModel:
    """Mesh and assemble the elasticity problem of the ``which`` gear's tooth sector of ``gear_pair`` in
    ``material``; ``settings``: the case's ``[fem]`` section (refinement, plane and sector teeth where not given)."""
    refinement = settings.mesh_refinement if refinement is None else refinement
    gear = gear_of(gear_pair, which)
    mesh = tooth_mesh(gear, nominal_bore_radius(gear), teeth=settings.sector_teeth if teeth is None else teeth,
                      refinement=refinement)
    basis = vector_basis(mesh.mesh, 2)
    plane = settings.plane if plane is None else plane
    matrix = stiffness_matrix(basis, material.youngs_modulus, material.poisson_ratio, plane)
    return ToothModel(gear_pair, material, which, mesh, basis, matrix, plane)


def own_roll_of(gear_pair, which: str, roll) -> np.ndarray:
    """The ``which`` gear's own roll distance ρ [m] of pair roll distances T1K [m] of a gear pair."""
    roll = np.asarray(roll, dtype=float)
    return roll if which == "pinion" else gear_pair.line_of_action_length - roll


@dataclass(frozen=True, eq=False)
class ToothDeflection:
    """FE single-tooth compliance along the path, beside the PEM's [m/N, totals over the face width]."""

    which: str
    roll: np.ndarray  # pair roll distance T1K [m]
    gamma: np.ndarray
    compliance: np.ndarray  # FE (section reading)
    pem: np.ndarray  # PEM bending + shear + axial + fillet
    unit_displacement: np.ndarray  # (2, n) displacement of K per N/m of face width [m²/N]
    plane: str
    elements: int

    @property
    def difference_percent(self) -> np.ndarray:
        return 100.0 * (self.compliance / self.pem - 1.0)


def tooth_deflection(model: ToothModel, roll, normal_load: float) -> ToothDeflection:
    """FE compliance of the tooth of ``model`` at pair roll distances ``roll`` [m] under the external normal load
    ``normal_load`` F_n [N, total over the face width] (it sets the Hertz width of the load), with the PEM's beside
    it."""
    from thermogear.stiffness.potential_energy import tooth_compliance  # noqa: PLC0415

    pair, which = model.gear_pair, model.which
    roll = np.asarray(roll, dtype=float)
    own = own_roll_of(pair, which, roll)
    width = model.gear.face_width
    unit_load = normal_load / pair.face_width
    solutions = model.elastic_displacements(model.contact_loads(own, unit_load))
    deflection, displacement = model.section_reading(solutions, own)
    _, _, load_angle, _ = contact_point_geometry(model.gear, own)
    pem = tooth_compliance(model.gear, load_angle, model.material, width, which, warn=False).total
    return ToothDeflection(which, roll, np.asarray(pair.gamma(roll)), deflection / width, pem,
                           displacement, model.plane, model.mesh.element_count)


__all__ = ["ToothDeflection", "ToothModel", "contact_point_geometry", "hertz_half_width", "own_roll_of",
           "section_deflection", "tooth_deflection", "tooth_model"]
