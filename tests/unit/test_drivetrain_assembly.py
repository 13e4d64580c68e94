"""Assembly of a geared two-shaft drivetrain: rigid-body modes, the torsional mesh mode, energy shares, invariance
of the modes to the pressure and centre-line angles on isotropic bearings, and the static state."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetrain_builders import STEEL, geared_pair

from thermogear.drivetrain import Material, NodeLocation
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.drivetrain.static_state import static_state
from thermogear.errors import CaseError


def test_assembled_matrices_are_symmetric_and_the_groups_add_up():
    assembled = geared_pair().assemble()
    assert assembled.size == 2 * 5 * 6
    for matrix in (assembled.mass, assembled.structure_stiffness, assembled.stiffness()):
        assert np.allclose(matrix, matrix.T, rtol=0, atol=1e-12 * np.abs(matrix).max())
    assert np.allclose(assembled.gyroscopic, -assembled.gyroscopic.T)
    total = sum(assembled.stiffness_groups.values())
    assert np.allclose(total, assembled.structure_stiffness, rtol=0, atol=1e-9)
    # the wheel shaft turns the other way at r_b1/r_b2 of the pinion's speed
    assert assembled.speed_ratios == pytest.approx({"pinion shaft": 1.0, "wheel shaft": -0.0381 / 0.0493})


@pytest.mark.parametrize("axial_stiffness, expected", [(1e9, 1), (0.0, 3)])
def test_rigid_body_modes_are_counted(axial_stiffness, expected):
    # one free torsional rotation of the train (no torsional ground) plus one axial mode per unlocated shaft
    drivetrain = geared_pair()
    if axial_stiffness == 0.0:
        from dataclasses import replace
        drivetrain = replace(drivetrain, bearings=tuple(replace(b, stiffness_z=0.0) for b in drivetrain.bearings))
    modes = drivetrain_modes(drivetrain.assemble())
    assert modes.rigid_mode_count == expected
    assert modes.angular_frequencies.min() > 100.0  # no rigid mode left among the elastic ones


def test_torsional_mesh_mode_of_rigid_gears_on_rigid_bearings():
    # shafts and bearings 10⁶ times stiffer than steel and real bearings: the pair is two rigid inertias on the
    # mesh spring, ω² = k_m(r_b1²/J₁ + r_b2²/J₂), with J the gear plus its whole shaft (ρJ_pL, rigid rotation).
    # The residual compliance (mesh 3e8 N/m in series with > 1e14 N/m) shifts ω by ~1e-6 relative: tolerance 1e-5.
    stiff = Material(youngs_modulus=211e15, density=7810.0, poisson_ratio=0.3)
    drivetrain = geared_pair(bearing_x=2e14, bearing_y=2e14, material=stiff,
                             pinion_inertia=(1.0, 4e-3, 2e-3), wheel_inertia=(1.5, 9e-3, 4.5e-3))
    assembled = drivetrain.assemble()
    shaft_polar = 7810.0 * math.pi * 0.04**4 / 32 * 0.2
    j_1, j_2 = 4e-3 + shaft_polar, 9e-3 + shaft_polar
    expected = math.sqrt(3e8 * (0.0381**2 / j_1 + 0.0493**2 / j_2))
    modes = drivetrain_modes(assembled)
    assert modes.angular_frequencies[0] == pytest.approx(expected, rel=1e-5)
    assert modes.labels[0] == "torsional"
    # all of that mode's strain energy is in the mesh (shares sum to 1; the rest ~ k_m/k_b)
    assert modes.mesh_share("mesh")[0] == pytest.approx(1.0, abs=1e-5)


def test_strain_energy_shares_and_kinetic_fractions_sum_to_one():
    modes = drivetrain_modes(geared_pair().assemble())
    shares = sum(modes.strain_energy_shares.values())
    assert np.allclose(shares, 1.0, rtol=0, atol=1e-12)
    fractions = sum(modes.kinetic_fractions.values())
    assert np.allclose(fractions, 1.0, rtol=0, atol=1e-12)
    assert set(modes.strain_energy_shares) == {"pinion shaft", "wheel shaft", "mesh"} | {
        f"{s} bearing {e}" for s in ("pinion shaft", "wheel shaft") for e in "AB"}
    # a mesh-dominated mode exists and is torsional-lateral coupled
    assert modes.mesh_share("mesh").max() > 0.3


def _frequencies(**options) -> np.ndarray:
    return drivetrain_modes(geared_pair(**options).assemble(), count=12).angular_frequencies


def test_modes_do_not_depend_on_pressure_or_centre_line_angle_on_isotropic_bearings():
    # rotating the line of action rotates the transverse plane, which isotropic supports do not see
    reference = _frequencies()
    for options in ({"pressure_angle": math.radians(25.0)}, {"centre_line_angle": 1.1}, {"rotation_sense": -1}):
        assert np.allclose(_frequencies(**options), reference, rtol=1e-9)
    # with anisotropic bearings they do (so the check above can fail)
    skewed = {"bearing_x": 2e8, "bearing_y": 2e7}
    shift = _frequencies(**skewed, pressure_angle=math.radians(25.0)) / _frequencies(**skewed) - 1.0
    assert np.abs(shift).max() > 1e-3


def test_static_state_mesh_force_lever_rule_and_deflection():
    drivetrain = geared_pair()
    assembled = drivetrain.assemble()
    load, deviation = 4000.0, 5e-6
    state = static_state(assembled, load, mean_deviation=deviation)
    # torsion carries the torque pair to the mesh: F = W exactly, δ̄ = W/k̄ + ē
    assert state.mesh_force[0] == pytest.approx(load, rel=1e-9)
    assert state.mesh_deflection[0] == pytest.approx(load / 3e8 + deviation, rel=1e-9)
    # each shaft's two bearings carry the gear force; gear at mid-span: half each (the lever rule)
    u = drivetrain.meshes[0].line_of_action
    for shaft, sign in (("pinion shaft", -1.0), ("wheel shaft", 1.0)):
        for end in "AB":
            force = state.bearing_forces[f"{shaft} bearing {end}"]
            assert force[:2] == pytest.approx(sign * 0.5 * load * u, rel=1e-9)
            assert abs(force[2]) < 1e-9 * load


def test_unbalanced_torques_are_refused():
    assembled = geared_pair().assemble()
    forces = np.zeros(assembled.size)
    forces[assembled.dof(NodeLocation("pinion shaft", 0.1), "theta")] = 100.0
    with pytest.raises(CaseError, match="torques"):
        static_state(assembled, 0.0, external_forces=forces)


def test_unknown_shaft_and_duplicate_names_are_refused():
    from dataclasses import replace

    drivetrain = geared_pair()
    with pytest.raises(CaseError, match="shaft"):
        replace(drivetrain, bearings=drivetrain.bearings + (replace(drivetrain.bearings[0], name="x",
                location=NodeLocation("no such shaft", 0.0)),))
    with pytest.raises(CaseError, match="unique names"):
        replace(drivetrain, bearings=drivetrain.bearings + (drivetrain.bearings[0],))
    with pytest.raises(CaseError, match="position"):
        replace(drivetrain, bearings=drivetrain.bearings + (replace(drivetrain.bearings[0], name="far",
                location=NodeLocation("pinion shaft", 0.5)),)).assemble()


def _with_motor(support_stiffness: float | None):
    """The pair with a motor shaft (a rigid disk on a short shaft) coupled to the pinion shaft's end."""
    from dataclasses import replace

    from thermogear.drivetrain import (Bearing, Coupling, CrossSection, RigidDisk, Shaft, ShaftSegment,
                                       TorsionalSupport)

    drivetrain = geared_pair()
    motor = Shaft("motor shaft", (ShaftSegment(0.1, CrossSection(0.03), STEEL),), 0.05)
    end = NodeLocation("motor shaft", 0.1)
    coupling = Coupling("coupling", end, NodeLocation("pinion shaft", 0.0), torsional_stiffness=2e3,
                        torsional_damping=0.5)
    supports = () if support_stiffness is None else (
        TorsionalSupport("speed control", NodeLocation("motor shaft", 0.0), support_stiffness, 1.0),)
    return replace(drivetrain, shafts=(motor,) + drivetrain.shafts,
                   disks=drivetrain.disks + (RigidDisk("rotor", NodeLocation("motor shaft", 0.05), 5.0, 0.02, 0.01),),
                   bearings=drivetrain.bearings + tuple(Bearing(f"motor bearing {z}", NodeLocation("motor shaft", z),
                                                                1e8, 1e8, 1e8) for z in (0.0, 0.1)),
                   couplings=(coupling,), torsional_supports=supports)


def test_a_coupled_motor_shares_the_rigid_rotation_and_a_speed_control_removes_it():

    free = _with_motor(None)
    assembled = free.assemble()
    # the coupling carries the pinion's speed to the motor shaft; the wheel turns the other way
    assert assembled.speed_ratios["motor shaft"] == pytest.approx(1.0)
    modes = drivetrain_modes(assembled, count=4)
    assert modes.rigid_mode_count == 1  # motor, pinion and wheel turn together: one free rotation
    # a torsional spring to ground (motor held at speed) leaves no rigid mode: the lowest mode is now the motor
    # rotor on the coupling and the speed-control spring
    held = drivetrain_modes(_with_motor(1e3).assemble(), count=4)
    assert held.rigid_mode_count == 0
    assert held.labels[0] == "torsional" and held.angular_frequencies[0] > 0.0
    # and the static state needs no torque balance any more: the support reacts the driving torque
    state = static_state(_with_motor(1e3).assemble(), 1000.0)
    assert state.mesh_force[0] == pytest.approx(1000.0, rel=1e-6)
