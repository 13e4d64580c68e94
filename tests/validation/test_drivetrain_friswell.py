"""Published rotor-dynamics numbers: Friswell, Penny, Garvey & Lees, Dynamics of Rotating Machines (CUP 2010),
Examples 5.9.1 (two disks, isotropic bearings), 5.9.5 (the same with bearing damping) and 5.9.9 (overhung disk).

Shaft 1.5 m, d = 50 mm, E = 211 GPa, G = 81.2 GPa, ρ = 7810 kg/m³, 6 equal Timoshenko elements; disks of width
70 mm and bore 50 mm (the shaft), outer diameters 280 mm and 350 mm. The book prints 4 or 5 significant digits
(86.66 rad/s, 1174.2 rad/s, 13.91 Hz): the rounding alone is up to 6e-4 relative (5e-3/86.66 for the first),
so 1e-3 relative is the tightest tolerance the printed numbers support; a wrong matrix entry (e.g. dropping the
rotary inertia or the gyroscopic matrix) moves these modes by more than 1 %. The sign of the gyroscopic matrix
does not change the frequencies, only which mode whirls forward: the whirl test checks it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, Material, NodeLocation, RigidDisk, Shaft,
                                   ShaftSegment)
from thermogear.drivetrain.modes import drivetrain_modes

STEEL = Material(youngs_modulus=211e9, density=7810.0, shear_modulus=81.2e9)
SPEED_4000_RPM = 4000 * math.pi / 30


def _rotor(example: str) -> Drivetrain:
    shaft = Shaft("rotor", (ShaftSegment(1.5, CrossSection(0.05), STEEL),), 0.25 * (1 + 1e-12))
    at = lambda z: NodeLocation("rotor", z)  # noqa: E731
    if example == "5.9.9":
        disks = (RigidDisk.annulus("disk", at(1.5), 7810.0, 0.07, 0.35, 0.05),)
        bearings = (Bearing("left", at(0.0), 1e7, 1e7), Bearing("right", at(1.0), 1e7, 1e7))
    else:
        damping = 3e3 if example == "5.9.5" else 0.0
        disks = (RigidDisk.annulus("disk 1", at(0.5), 7810.0, 0.07, 0.28, 0.05),
                 RigidDisk.annulus("disk 2", at(1.0), 7810.0, 0.07, 0.35, 0.05))
        bearings = tuple(Bearing(name, at(z), 1e6, 1e6, damping_x=damping, damping_y=damping)
                         for name, z in (("left", 0.0), ("right", 1.5)))
    return Drivetrain((shaft,), disks, bearings)


CASES = [  # (example, speed [rad/s], quantity, published values, lateral modes only)
    ("5.9.1", 0.0, "rad/s", (86.66, 86.66, 274.31, 274.31, 650.41, 716.78), False),
    ("5.9.1", SPEED_4000_RPM, "rad/s", (85.39, 87.80, 251.78, 294.71, 600.18, 650.41), False),
    ("5.9.9", 0.0, "rad/s", (90.14, 90.14, 630.73, 630.73, 830.43, 830.43), False),
    ("5.9.9", SPEED_4000_RPM, "rad/s", (76.19, 103.91, 565.99, 634.23, 647.75, 1174.2), False),
    ("5.9.5", 0.0, "natural Hz", (13.91, 13.91, 48.18, 48.18, 137.06, 137.06), True),
    ("5.9.5", 0.0, "damped Hz", (13.89, 13.89, 46.54, 46.54, 103.22, 103.22), True),
]


@pytest.mark.parametrize("example, speed, quantity, published, lateral_only", CASES,
                         ids=[f"{c[0]}-{c[2]}-{c[1]:.0f}" for c in CASES])
def test_friswell_examples(example, speed, quantity, published, lateral_only):
    modes = drivetrain_modes(_rotor(example).assemble(), speed=speed, damped=example == "5.9.5")
    keep = np.array([label.startswith("lateral") for label in modes.labels]) if lateral_only else \
        np.ones(len(modes.labels), dtype=bool)
    if quantity == "rad/s":
        values = modes.angular_frequencies[keep]
    elif quantity == "natural Hz":
        values = modes.frequencies_hz[keep]
    else:
        values = (modes.angular_frequencies * np.sqrt(1 - modes.damping_ratios**2))[keep] / (2 * math.pi)
    assert values[:6] == pytest.approx(published, rel=1e-3)


def test_forward_whirl_rises_and_backward_falls_with_speed():
    # Ex. 5.9.1: the first pair splits 86.66 → 85.39 (backward) / 87.80 (forward) at 4000 rpm; with the spin
    # reversed the pair splits the same way (whirl is relative to the spin), so the frequencies are unchanged
    rotor = _rotor("5.9.1").assemble()
    modes = drivetrain_modes(rotor, SPEED_4000_RPM)
    x, y = rotor.dof(NodeLocation("rotor", 1.0), "x"), rotor.dof(NodeLocation("rotor", 1.0), "y")
    # forward whirl with the spin about +z: x = cos ωt, y = sin ωt, i.e. ŷ/x̂ = −i for the e^{iωt} eigenvector
    ratios = modes.shapes[y, :2] / modes.shapes[x, :2]
    assert ratios == pytest.approx([1j, -1j], abs=1e-6)
    still = drivetrain_modes(rotor, 0.0).angular_frequencies[:2]
    spinning = drivetrain_modes(rotor, SPEED_4000_RPM).angular_frequencies[:2]
    reversed_spin = drivetrain_modes(rotor, -SPEED_4000_RPM).angular_frequencies[:2]
    assert spinning[0] < still[0] < spinning[1]
    assert reversed_spin == pytest.approx(spinning, rel=1e-9)
