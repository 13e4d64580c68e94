"""A geared two-shaft turbo-alternator against the damped natural frequencies another open-source rotordynamics
code documents for it.

Data after Rao, Shiau & Chang, Mech. Mach. Theory 33 (1998) 761, as set up in ROSS (github.com/petrobras/ross,
``ross.multi_rotor.two_shaft_rotor_example``): E = 207 GPa, G = 79.5 GPa, ρ = 7800 kg/m³; shaft 1 of four segments
(0.1, 4.24, 1.16, 0.3 m; d = 0.3, 0.3, 0.22, 0.22 m), one element each, disks 525.7 kg and 116.04 kg, the bull
gear (726.4 kg, r_b = 0.5086 m) at its end, bearings at its nodes 0 and 3 (k_xx = 183.9 MN/m, k_yy = 200.4 MN/m);
shaft 2 (0.3, 5, 0.1 m; d = 0.15 m) with the pinion (5 kg, r_b = 0.03567 m) at its start, the turbine at node 2 and
bearings at nodes 1 and 3 (k_xx = 10.1 MN/m, k_yy = 41.6 MN/m); all bearings c = 3 kN·s/m; α = 22.5°, k_m = 100 MN/m.
ROSS's docstring prints the four lowest damped frequencies at standstill rounded to whole rad/s (74, 77, 112,
113): the rounding allows ±0.5 rad/s, i.e. 0.7 % of the lowest, which is the tolerance. ROSS counts the driven
shaft's rotation in its own sense; that flips the signs of its torsional DOFs and leaves the frequencies unchanged.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation, RigidDisk,
                                   Shaft, ShaftSegment)
from thermogear.drivetrain.modes import drivetrain_modes


def _turbo_alternator() -> Drivetrain:
    material = Material(207e9, 7800.0, shear_modulus=79.5e9)

    def shaft(name, lengths, diameters):
        return Shaft(name, tuple(ShaftSegment(length, CrossSection(diameter), material)
                                 for length, diameter in zip(lengths, diameters)), maximum_element_length=10.0)

    at = NodeLocation
    disks = (RigidDisk("disk 1", at("bull shaft", 0.1), 525.7, 32.2, 16.1),
             RigidDisk("disk 2", at("bull shaft", 4.34), 116.04, 6.23, 3.115),
             RigidDisk("bull gear", at("bull shaft", 5.8), 726.4, 113.9, 56.95),
             RigidDisk("pinion", at("pinion shaft", 0.0), 5.0, 0.004, 0.002),
             RigidDisk("turbine", at("pinion shaft", 5.3), 7.45, 0.149, 0.0745))
    bearings = tuple(Bearing(name, at(shaft_name, z), kx, ky, damping_x=3e3, damping_y=3e3)
                     for name, shaft_name, z, kx, ky in (("bull 0", "bull shaft", 0.0, 183.9e6, 200.4e6),
                                                         ("bull 3", "bull shaft", 5.5, 183.9e6, 200.4e6),
                                                         ("pinion 1", "pinion shaft", 0.3, 10.1e6, 41.6e6),
                                                         ("pinion 3", "pinion shaft", 5.4, 10.1e6, 41.6e6)))
    mesh = GearMesh("mesh", at("bull shaft", 5.8), at("pinion shaft", 0.0), 0.5086, 0.03567, math.radians(22.5),
                    1e8)
    return Drivetrain((shaft("bull shaft", (0.1, 4.24, 1.16, 0.3), (0.3, 0.3, 0.22, 0.22)),
                       shaft("pinion shaft", (0.3, 5.0, 0.1), (0.15, 0.15, 0.15))), disks, bearings, meshes=(mesh,))


@pytest.mark.parametrize("index, published", list(enumerate((74.0, 77.0, 112.0, 113.0))))
def test_damped_frequencies_at_standstill(index, published):
    modes = drivetrain_modes(_turbo_alternator().assemble(), damped=True, count=6)
    damped = modes.angular_frequencies * np.sqrt(1.0 - modes.damping_ratios**2)
    assert damped[index] == pytest.approx(published, abs=0.5)


def test_the_coupled_torsional_mode_carries_the_mesh_energy():
    modes = drivetrain_modes(_turbo_alternator().assemble(), damped=True, count=6)
    # three rigid-body modes (one free rotation of the train, one axial per shaft) are removed
    assert modes.rigid_mode_count == 3
    # the four lowest modes are lateral; the fifth is the torsional mode and stores the most mesh energy
    assert all(label.startswith("lateral") for label in modes.labels[:4])
    assert modes.labels[4] == "torsional"
    assert int(np.argmax(modes.mesh_share("mesh"))) == 4
