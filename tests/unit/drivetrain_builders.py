"""Small drivetrains for the drivetrain tests: a uniform shaft, and a gear pair on two shafts with two bearings each."""

from __future__ import annotations

import math

import numpy as np

from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation, RigidDisk,
                                   Shaft, ShaftSegment)

STEEL = Material(youngs_modulus=211e9, density=7810.0, poisson_ratio=0.3)


def uniform_shaft(length: float, diameter: float, elements: int, material: Material = STEEL,
                  shear_deformation: bool = True, rotary_inertia: bool = True) -> Shaft:
    """One uniform solid shaft cut into ``elements`` equal elements."""
    segment = ShaftSegment(length, CrossSection(diameter), material)
    return Shaft("shaft", (segment,), length / elements * (1.0 + 1e-12), shear_deformation=shear_deformation,
                 rotary_inertia=rotary_inertia)


def plane_matrices(assembled, fixed_positions: tuple[float, ...]) -> tuple[np.ndarray, np.ndarray]:
    """Mass and stiffness of the x–z bending plane (DOFs x, β) with x held at the given positions (exact
    constraints, not penalty springs)."""
    keep = []
    for node, z in enumerate(assembled.node_positions["shaft"]):
        if not any(abs(z - p) < 1e-12 for p in fixed_positions):
            keep.append(6 * node)
        keep.append(6 * node + 4)
    keep = np.array(keep)
    return (assembled.mass[np.ix_(keep, keep)], assembled.structure_stiffness[np.ix_(keep, keep)])


def geared_pair(bearing_x: float = 2e8, bearing_y: float = 2e8, pressure_angle: float = math.radians(20.0),
                centre_line_angle: float = 0.0, rotation_sense: int = 1, mesh_stiffness: float = 3e8,
                material: Material = STEEL, pinion_inertia: tuple[float, float, float] | None = None,
                wheel_inertia: tuple[float, float, float] | None = None, elements: int = 4,
                bearing_damping: float = 0.0, material_damping: float = 0.0) -> Drivetrain:
    """Two 0.2 m shafts (d = 40 mm) with a gear at mid-span and bearings at both ends; gear bodies as annuli
    (pitch diameters 81 mm and 105 mm, width 20 mm) unless (m, I_p, I_d) are given."""
    shafts = tuple(Shaft(name, (ShaftSegment(0.2, CrossSection(0.04), material),), 0.2 / elements * (1 + 1e-12),
                         material_damping=material_damping)
                   for name in ("pinion shaft", "wheel shaft"))
    pinion, wheel = NodeLocation("pinion shaft", 0.1), NodeLocation("wheel shaft", 0.1)
    disks = []
    for name, location, diameter, inertia in (("pinion", pinion, 0.081, pinion_inertia),
                                              ("wheel", wheel, 0.105, wheel_inertia)):
        if inertia is None:
            disks.append(RigidDisk.annulus(name, location, 7810.0, 0.02, diameter, 0.04))
        else:
            disks.append(RigidDisk(name, location, *inertia))
    bearings = tuple(Bearing(f"{shaft} bearing {end}", NodeLocation(shaft, position), bearing_x, bearing_y, 1e9,
                             bearing_damping, bearing_damping, bearing_damping)
                     for shaft in ("pinion shaft", "wheel shaft") for end, position in (("A", 0.0), ("B", 0.2)))
    mesh = GearMesh("mesh", pinion, wheel, base_radius_1=0.0381, base_radius_2=0.0493,
                    operating_pressure_angle=pressure_angle, stiffness=mesh_stiffness,
                    centre_line_angle=centre_line_angle, rotation_sense=rotation_sense)
    return Drivetrain(shafts, tuple(disks), bearings, meshes=(mesh,))
