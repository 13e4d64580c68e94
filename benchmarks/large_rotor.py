"""A geared two-shaft rotor of a chosen size for the scaling benchmarks (issue 38), built from the drivetrain API.

Two steel shafts (0.8 m, d = 60 mm) of ``elements`` Timoshenko elements each, the gears at mid-span, four rolling
bearings at the shaft ends (2e8 N/m, 2e3 N·s/m, axial 1e9 N/m), light material damping; a square-wave mesh
stiffness (1.6e8 N/m with one pair, 2.6e8 N/m with two, contact ratio 1.6). 40 elements per shaft give 2·41·6 =
492 DOF; 4, 40 and 166 elements give about 60, 500 and 2000.
"""

from __future__ import annotations

import math

import numpy as np

PINION_TEETH = 20
PINION_RADIUS, WHEEL_RADIUS = 0.0564, 0.0752  # base radii [m]
SHAFT_LENGTH = 0.8


def rotor(elements: int, stiffness: float = 2.1e8):
    """The drivetrain with ``elements`` shaft elements per shaft (2·(elements + 1)·6 DOF; the gears' node is one of
    them when ``elements`` is even)."""
    from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation,
                                       RigidDisk, Shaft, ShaftSegment)

    steel = Material(youngs_modulus=206e9, density=7850.0, poisson_ratio=0.3)
    names = ("pinion shaft", "wheel shaft")
    shafts = tuple(Shaft(name, (ShaftSegment(SHAFT_LENGTH, CrossSection(0.06), steel),),
                         SHAFT_LENGTH / elements * (1 + 1e-9), material_damping=2e-6) for name in names)
    middle = SHAFT_LENGTH / 2.0
    pinion, wheel = NodeLocation(names[0], middle), NodeLocation(names[1], middle)
    angle = math.radians(20.0)
    disks = (RigidDisk.annulus("pinion", pinion, 7850.0, 0.03, 2 * PINION_RADIUS / math.cos(angle), 0.06),
             RigidDisk.annulus("wheel", wheel, 7850.0, 0.03, 2 * WHEEL_RADIUS / math.cos(angle), 0.06))
    bearings = tuple(Bearing(f"{shaft} {end}", NodeLocation(shaft, z), 2e8, 2e8, 1e9, 2e3, 2e3, 2e3)
                     for shaft in names for end, z in (("A", 0.0), ("B", SHAFT_LENGTH)))
    mesh = GearMesh("mesh", pinion, wheel, PINION_RADIUS, WHEEL_RADIUS, angle, stiffness)
    return Drivetrain(shafts, disks, bearings, meshes=(mesh,))


def square_wave(speed_rpm: float, intervals: int = 2, noise: float = 0.0, seed: int = 1):
    """A square-wave mesh period on ``intervals`` equal intervals (two pairs over the first 60 %): k = 2.6e8 N/m
    with two pairs, 1.6e8 N/m with one, c = 1500 N·s/m, W = 5000 N; ``intervals = 2`` gives the two pieces
    [0, 0.6), [0.6, 1). ``noise``: relative scatter added to every interval's stiffness and damping (uniform,
    ±noise), as a table from a measurement or another tool carries in its last digits."""
    from thermogear.mesh.state import mesh_state_from_arrays

    if intervals == 2:
        phase = np.array([0.0, 0.6])
    else:
        phase = np.arange(intervals) / intervals
    double = phase < 0.6 - 1e-12
    stiffness = np.where(double, 2.6e8, 1.6e8)
    damping = np.full(phase.size, 1500.0)
    if noise:
        generator = np.random.default_rng(seed)
        stiffness = stiffness * (1.0 + noise * generator.uniform(-1.0, 1.0, phase.size))
        damping = damping * (1.0 + noise * generator.uniform(-1.0, 1.0, phase.size))
    period = 60.0 / (PINION_TEETH * speed_rpm)
    return mesh_state_from_arrays(phase, stiffness, period=period, normal_load=5000.0, mass=1.0, damping=damping,
                                  speed_rpm=speed_rpm)
