"""The mesh state drives the drivetrain: in the limit of rigid shafts and bearings the n-DOF periodic response is
the 1-DOF one of the same mesh state (DTE, Kv, multipliers); bearing forces balance the mesh force."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetrain_builders import geared_pair

from thermogear.drivetrain import Material
from thermogear.drivetrain.response import drivetrain_periodic_response
from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
from thermogear.mesh.state import MeshState
from thermogear.geometry.mesh_cycle import MeshGrid

R_B1, R_B2 = 0.0381, 0.0493
SHAFT_POLAR = 7810.0 * math.pi * 0.04**4 / 32 * 0.2  # ρ J_p L of one 0.2 m, d = 40 mm shaft [kg·m²]
J_1, J_2 = 4e-3 + SHAFT_POLAR, 9e-3 + SHAFT_POLAR


def _mesh_state(mass: float, speed_rpm: float = 1500.0, teeth: int = 20, deviation: float = 0.0) -> MeshState:
    """A square-wave mesh period (contact ratio 1.6) as a mesh model would hand it over: two pair slots."""
    period = 60.0 / (teeth * speed_rpm)
    nodes = np.array([0.0, 0.3 * period, 0.6 * period, period])
    in_contact = np.array([[True, True, True], [True, True, False]])
    pair_stiffness = np.array([[1.9e7, 2.1e7, 2.7e7], [2.0e7, 1.8e7, 0.0]])
    pair_damping = np.array([[900.0, 1000.0, 1500.0], [1000.0, 900.0, 0.0]])
    grid = MeshGrid(nodes=nodes, midpoints=0.5 * (nodes[1:] + nodes[:-1]), roll=np.zeros((2, 3)),
                    in_contact=in_contact, contact_count=in_contact.sum(axis=0))
    return MeshState(model="test", speed_rpm=speed_rpm, normal_load=3000.0, mass=mass, grid=grid,
                     pair_stiffness=pair_stiffness, pair_damping=pair_damping,
                     mesh_damping=pair_damping.sum(axis=0), pair_deviation=np.where(in_contact, deviation, 0.0),
                     pair_engaged=in_contact, static_transmission_error=None, backlash=None, face_width=0.02,
                     mesh_frequency_hz=1.0 / period)


def _stiffened_pair(scale: float):
    """The pair with shafts ``scale`` times stiffer than steel and bearings of 1e8·scale N/m; material (β = 1e-2/scale
    s) and bearing damping damp the support modes so that every multiplier is inside the unit circle."""
    stiff = Material(youngs_modulus=211e9 * scale, density=7810.0, poisson_ratio=0.3)
    return geared_pair(bearing_x=1e8 * scale, bearing_y=1e8 * scale, material=stiff, pinion_inertia=(1.0, 4e-3, 2e-3),
                       wheel_inertia=(1.5, 9e-3, 4.5e-3), bearing_damping=1e3, material_damping=1e-2 / scale)


def _limit(stiff: float, stiffer: float) -> float:
    """Richardson's extrapolation of a quantity q(s) = q∞ + a/s + O(1/s²) to s → ∞ from its values at s and 10 s."""
    return stiffer + (stiffer - stiff) / 9.0


@pytest.mark.slow
def test_rigid_supports_reproduce_the_one_dof_periodic_result():
    from thermogear.dynamics.results.metrics import compute_metrics

    mass = J_1 * J_2 / (J_1 * R_B2**2 + J_2 * R_B1**2)
    state = _mesh_state(mass, deviation=3e-6)
    orbit = periodic_steady_state(state.problem(), samples_per_interval=16)
    scale = np.abs(orbit.displacement).max()
    interval = np.minimum(np.arange(orbit.time.size) // 16, 2)
    one_dof = compute_metrics(state.problem(), orbit.time, orbit.displacement, orbit.velocity, interval,
                              orbit.multipliers)
    stiff, stiffer = (drivetrain_periodic_response(_stiffened_pair(stiffening).assemble(), state, samples_per_piece=16)
                      for stiffening in (1e4, 1e5))
    errors = [np.abs(response.transmission_error - orbit.displacement).max() / scale for response in (stiff, stiffer)]
    # The supports' compliance is physical: it lowers the mesh mode by ~k_m/k_support, so the difference from the
    # 1-DOF orbit is a/k + O(1/k²) (measured 3.17e-5 → 3.19e-6, a fall of 9.93 per decade). It cannot be followed
    # directly below ~1e-6: at 1e6× steel the support modes reach ~1e7 rad/s, ω·h ≈ 6e3 rad over a piece, and the
    # ~14 squarings of their exponentials leave a rounding floor of ~5e-7 (measured 8.4e-7 at 1e6×, 2.3e-5 at
    # 1e7×). So the limit is taken honestly by its rate: the fall per decade is 10 within 20 % (1/k; the O(1/k²)
    # and the floor move it by < 1 % here), the error law then gives < 1e-6 from 3.2e5× steel on, and Richardson's
    # extrapolation of the two solutions (which removes a/k) reproduces the 1-DOF orbit to 1e-6, as the issue asks
    # (measured 4.3e-8; Kv 2.4e-8, DTE rms 4.7e-8, multipliers 9e-8)
    assert errors[1] < 1e-5
    assert 8.0 < errors[0] / errors[1] < 12.0
    limit = _limit(stiff.transmission_error, stiffer.transmission_error)
    assert np.abs(limit - orbit.displacement).max() < 1e-6 * scale
    assert _limit(stiff.kv, stiffer.kv) == pytest.approx(one_dof["kv"], rel=1e-6)
    assert _limit(stiff.metrics["dte_rms"], stiffer.metrics["dte_rms"]) == pytest.approx(one_dof["dte_rms"], rel=1e-6)
    # the pair's two multipliers are among the n-DOF system's (the support modes add their own), each extrapolated
    # from its nearest one at both stiffnesses
    for multiplier in orbit.multipliers:
        nearest = [response.multipliers[np.argmin(np.abs(response.multipliers - multiplier))]
                   for response in (stiff, stiffer)]
        assert abs(_limit(*nearest) - multiplier) < 1e-6 * abs(multiplier)


def test_bearing_forces_balance_the_mesh_force_on_each_shaft():
    # flexible pair: the shaft's two bearings carry the gear's force less the inertia forces, which average to zero
    # over a period; gear at mid-span, so each pinion bearing carries −½·mean(F)·u on average (harmonic 0)
    drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6)
    assembled = drivetrain.assemble()
    response = drivetrain_periodic_response(assembled, _mesh_state(0.5), samples_per_piece=16)
    u = drivetrain.meshes[0].line_of_action
    frequencies, amplitudes = response.bearing_spectrum("pinion shaft bearing A")
    assert frequencies[1] == pytest.approx(500.0, rel=1e-12)  # 20 teeth at 1500 rpm
    # F jumps with k(τ) at the nodes: integrate it piece by piece, the end of each piece at its left limit
    problem = _mesh_state(0.5).problem()
    excitation = problem.force_per_interval - problem.static_load
    integral = 0.0
    for piece in range(3):
        rows = np.arange(16 * piece, 16 * piece + 17)
        values = (problem.stiffness[piece] * response.transmission_error[rows] - excitation[piece]
                  + problem.damping[piece] * response.transmission_error_rate[rows])
        integral += np.trapezoid(values, response.time[rows])
    mean_force = integral / response.period
    # both means come from 16 samples per piece (trapezoid vs resampled FFT): 1e-3 covers their quadrature error
    assert amplitudes[:2, 0] == pytest.approx(np.abs(0.5 * mean_force * u), rel=1e-3)
    assert np.all(amplitudes[:2, 1] > 0.0)  # the mesh harmonics reach the housing
    assert response.kv > 1.0


@pytest.mark.slow
def test_backlash_drivetrain_in_permanent_contact_equals_the_linear_drivetrain():
    # load large against the vibration at a speed far from resonance: the teeth never separate, so the backlash
    # orbit is the linear one (same flow, no switch): 1e-9 relative
    from dataclasses import replace

    from thermogear.drivetrain.response import drivetrain_backlash_system, drivetrain_periodic_system
    from thermogear.dynamics.backlash.backlash_ndof import backlash_periodic_orbit
    from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response

    drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2)
    state = replace(_mesh_state(0.5, speed_rpm=600.0), backlash=50e-6)
    assembled = drivetrain.assemble()
    system, _ = drivetrain_backlash_system(assembled, state)
    orbit = backlash_periodic_orbit(system, substeps=4)
    linear, _ = drivetrain_periodic_system(assembled, state)
    reference = periodic_response(linear, 1).initial_state
    assert orbit.converged and orbit.switches == 0
    assert np.abs(orbit.initial_state - reference).max() < 1e-9 * np.abs(reference).max()


def test_speed_sweep_equals_one_solution_per_speed():
    # three speeds whose mesh stiffness differs too (±15 %), so that the first state's modal basis is not the others'
    from dataclasses import replace

    from thermogear.drivetrain.response import drivetrain_speed_sweep

    assembled = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=3).assemble()
    states = []
    for speed, factor in ((900.0, 1.0), (1500.0, 1.15), (2600.0, 0.85)):
        state = _mesh_state(0.5, speed_rpm=speed, deviation=2e-6)
        states.append(replace(state, pair_stiffness=factor * state.pair_stiffness))
    full = [drivetrain_periodic_response(assembled, state, samples_per_piece=4) for state in states]
    # every DOF: the shared rigid-body reduction is the same subspace, so the orbits agree to rounding (measured
    # 1.5e-12 of the DTE): 1e-10
    for swept, single in zip(drivetrain_speed_sweep(assembled, states, samples_per_piece=4), full):
        scale = np.abs(single.transmission_error).max()
        assert np.abs(swept.transmission_error - single.transmission_error).max() < 1e-10 * scale
        assert swept.kv == pytest.approx(single.kv, rel=1e-10)
    # modes below 10 kHz plus static corrections: the first state's basis serves all three with the statics exact, so
    # its distance to the full orbit is that of a basis per speed (measured 0.91–1.0 times it); 1.5 times allows
    # for the other truncated modes without letting a wrong static correction (an error of the order of 1) pass
    swept = drivetrain_speed_sweep(assembled, states, samples_per_piece=4, cutoff_hz=1e4)
    for state, reduced, reference in zip(states, swept, full):
        own = drivetrain_periodic_response(assembled, state, samples_per_piece=4, cutoff_hz=1e4)
        scale = np.abs(reference.transmission_error).max()
        shared_error = np.abs(reduced.transmission_error - reference.transmission_error).max() / scale
        own_error = np.abs(own.transmission_error - reference.transmission_error).max() / scale
        assert shared_error <= 1.5 * own_error and own_error < 1e-4


def _near_resonance_backlash_state():
    """The rigid-support backlash case near resonance (1.05 × the mesh mode) and its 1-DOF orbit (two switches)."""
    from dataclasses import replace

    from thermogear.dynamics.backlash.backlash_periodic import linear_initial_state, shoot

    mass = J_1 * J_2 / (J_1 * R_B2**2 + J_2 * R_B1**2)
    natural = math.sqrt(3.6e7 / mass) / (2 * math.pi)  # the square wave's mean stiffness is 3.6e7 N/m
    state = _mesh_state(mass, speed_rpm=1.05 * natural * 60.0 / 20)
    state = replace(state, pair_damping=0.25 * state.pair_damping, mesh_damping=0.25 * state.mesh_damping,
                    backlash=8.77e-5)
    problem = state.backlash_problem()
    return state, problem, shoot(problem, linear_initial_state(problem), tolerance=1e-13)


@pytest.mark.slow
def test_a_missed_switch_is_refined_or_reported_never_converged():
    # the case of the stiff-support test at 1e4× steel with only 4 sub-steps per piece: depending on the BLAS's
    # last digits Newton ended on a point of one located crossing of g = 0 (measured on two BLAS threads: residual
    # 2.2e-8, free flight 1.30e-4 s), which the odd-crossing guard shoots again with 8 sub-steps to the two-switch
    # orbit; on one thread 4 sub-steps find that orbit at once. Either way: never a one-switch "converged" orbit
    # (the guard's refinement itself is tested deterministically in test_backlash_ndof.py)
    from thermogear.drivetrain.response import drivetrain_backlash_system
    from thermogear.dynamics.backlash.backlash_ndof import backlash_flow_ndof, backlash_periodic_orbit, odd_crossings

    state, _, shot = _near_resonance_backlash_state()
    system, _ = drivetrain_backlash_system(_stiffened_pair(1e4).assemble(), state)
    lift = np.linalg.solve(system.linear.mass, system.linear.force_pattern)
    lift = lift / (system.linear.force_pattern @ lift)
    start = np.concatenate([shot["state"][0] * lift, shot["state"][1] * lift])
    orbit = backlash_periodic_orbit(system, initial_state=start, substeps=4, tolerance=1e-7)
    if orbit.converged:
        _, _, info = backlash_flow_ndof(system, orbit.initial_state, orbit.substeps)
        assert orbit.switches == 2 and odd_crossings(info["crossings"]) == [] and orbit.failure == ""
    else:
        assert "odd number" in orbit.failure


@pytest.mark.slow
def test_rigid_supports_reproduce_the_one_dof_backlash_orbit():
    # near resonance (1.05 × the mesh mode), with contact loss: the 1-DOF orbit leaves contact once per period for
    # 1.07e-4 s (two switches). Orbits coexist here (from the linear state the drivetrain's shooting can land on one
    # with a single switch), so the drivetrain's is shot from the 1-DOF (δ, δ̇) lifted onto the mesh coordinate
    # (q = δ·M⁻¹w/(wᵀM⁻¹w)) at 1e4× steel, and from that orbit at 1e5×: the start selects the orbit, the shooting
    # finds the drivetrain's own
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
    from thermogear.drivetrain.response import drivetrain_backlash_system
    from thermogear.dynamics.backlash.backlash_metrics import orbit_metrics
    from thermogear.dynamics.backlash.backlash_ndof import backlash_periodic_orbit
    from thermogear.dynamics.backlash.backlash_periodic import backlash_flow, orbit_from_shot

    state, problem, shot = _near_resonance_backlash_state()
    _, _, contact = backlash_flow(problem, shot["state"])
    reference = orbit_from_shot(problem, shot, 1, 16, shot["iterations"])
    assert shot["converged"] and contact["switches"] == 2 and contact["free_flight_time"] > 0.0
    scales = np.array([np.abs(reference.history.displacement).max(), np.abs(reference.history.velocity).max()])
    states, multipliers, previous, metrics = [], [], None, []
    for stiffening in (1e4, 1e5):
        assembled = _stiffened_pair(stiffening).assemble()
        system, _ = drivetrain_backlash_system(assembled, state)
        if previous is None:
            lift = np.linalg.solve(system.linear.mass, system.linear.force_pattern)
            lift = lift / (system.linear.force_pattern @ lift)
            previous = np.concatenate([shot["state"][0] * lift, shot["state"][1] * lift])
        # shooting to 1e-7: the stiff support modes leave a rounding floor of the residual near 2e-8 at 1e5×
        # 16 substeps per interval (the solver's default) to find the switches: with 4, a short contact change within
        # a substep could be missed and Newton ended, depending on the last digits of the BLAS, on a one-switch point
        # (free flight 1.2993e-4 s at both stiffnesses) that is no orbit of either system
        orbit = backlash_periodic_orbit(system, initial_state=previous, substeps=16, tolerance=1e-7)
        assert orbit.converged and orbit.switches == 2
        previous = orbit.initial_state
        size = system.linear.size
        w = system.linear.force_pattern
        states.append(np.array([w @ orbit.initial_state[:size], w @ orbit.initial_state[size:]]))
        multipliers.append(orbit.multipliers)
        response = drivetrain_backlash_response(assembled, state, initial_state=orbit.initial_state,
                                                samples_per_piece=16, tolerance=1e-7)
        assert response.converged and response.switches == 2 and response.stable
        metrics.append(response.metrics)
    errors = [np.abs(value - shot["state"]) / scales for value in states]
    # the supports' compliance again: (δ, δ̇) at τ = 0 fall tenfold per decade (measured 1.07e-4 → 1.08e-5 of the
    # orbit's peak δ, a fall of 9.9). Extrapolated to rigid supports (Richardson, as for the linear orbit) they meet
    # the 1-DOF orbit to 1e-6 of its peak displacement and velocity, as the issue asks (measured 1.3e-7 and 5.0e-7:
    # what is left is the rounding floor of the stiff flows, whose shooting residual stops near 2e-8 at 1e5×, not
    # the O(1/k²) term — a third stiffness, 1e3×, does not lower it)
    assert 8.0 < errors[0][0] / errors[1][0] < 12.0
    limit = _limit(*states)
    assert np.all(np.abs(limit - shot["state"]) < 1e-6 * scales)
    # the pair's multipliers, extrapolated likewise, reach 7.2e-7 (6.5–7.5e-7 over shooting tolerances 1e-7 to 1e-9):
    # inside the 1e-6, but with that floor the assertion allows 2e-6 rather than a margin of 1.4
    for multiplier in reference.multipliers:
        nearest = [values[np.argmin(np.abs(values - multiplier))] for values in multipliers]
        assert abs(_limit(*nearest) - multiplier) < 2e-6 * abs(multiplier)
    # the response's metrics, extrapolated likewise, against the 1-DOF solver's on the same grid (16 samples per
    # piece, every switch, extremum and node): Kv is exact at its samples and the DTE RMS the trapezoid rule on the
    # same points in both, so what is left is the orbit's own 1e-6 (measured 1.0e-7 and 4.9e-7). The contact-loss
    # fraction (free flight / period, exact between located switches) converges as 1/k too, but its switch times
    # carry a larger 1/k² term: extrapolated from 1e4 and 1e5 it is 1.1e-5 from the 1-DOF value (2.2e-4 from 1e3
    # and 1e4; raw 5.2e-4 at 1e5), so 3e-5 is asserted for it, not the 1e-6 of the other two
    one_dof = orbit_metrics(reference)
    for key, tolerance in (("kv", 1e-6), ("dte_rms", 1e-6), ("contact_loss_fraction", 3e-5)):
        assert _limit(metrics[0][key], metrics[1][key]) == pytest.approx(one_dof[key], rel=tolerance), key


def _loaded_pair():
    """The geared pair at 600 rpm with a load large against its vibration (the teeth never separate) and a
    backlash of 50 μm."""
    from dataclasses import replace

    drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2)
    return drivetrain.assemble(), replace(_mesh_state(0.5, speed_rpm=600.0), backlash=50e-6)


@pytest.mark.slow
def test_backlash_response_in_permanent_contact_equals_the_linear_response():
    # no switch: the same flow sampled at the same grid (the backlash response adds both sides of each node and
    # the extrema of δ): δ, the mesh force and the bearing forces agree to 1e-9 of their scale (measured 6e-13 and
    # 2e-11); Kv, taken at the true maximum of the pair loads, is at least the linear one's maximum over its grid
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response

    assembled, state = _loaded_pair()
    response = drivetrain_backlash_response(assembled, state, substeps=4, samples_per_piece=4)
    linear = drivetrain_periodic_response(assembled, state, samples_per_piece=4)
    assert response.converged and response.stable and response.switches == 0
    assert response.contact_loss_fraction == 0.0 and response.back_contact_fraction == 0.0
    rows = [int(np.flatnonzero(np.abs(response.time - t) <= 1e-12 * linear.period)[-1]) for t in linear.time]
    for ours, theirs in ((response.transmission_error, linear.transmission_error),
                         (response.mesh_force, linear.mesh_force),
                         *((response.bearing_forces[name], linear.bearing_forces[name])
                           for name in linear.bearing_forces)):
        assert np.abs(ours[rows] - theirs).max() < 1e-9 * np.abs(theirs).max()
    assert np.sort(np.abs(response.multipliers)) == pytest.approx(np.sort(np.abs(linear.multipliers)), rel=1e-9)
    assert response.kv >= linear.kv - 1e-12 and response.metrics["valid"]


def test_bearing_force_of_a_clearance_is_zero_inside_the_gap():
    # the force law per direction: zero for |u| <= δ, k(u ∓ δ) + c·u̇ beyond; z (no clearance) stays k·u + c·u̇
    from dataclasses import replace

    from thermogear.drivetrain.backlash_response import bearing_forces

    drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2)
    gap = 5e-6
    loose = replace(drivetrain, bearings=tuple(replace(bearing, radial_clearance=gap)
                                               for bearing in drivetrain.bearings))
    assembled = loose.assemble()
    bearing = loose.bearings[0]
    dofs = [assembled.dof(bearing.location, axis) for axis in ("x", "y", "z")]
    displacement, velocity = np.zeros((3, assembled.size)), np.zeros((3, assembled.size))
    displacement[:, dofs] = [[4e-6, -4.9e-6, 1e-6], [7e-6, -9e-6, 0.0], [-6e-6, 0.0, 0.0]]
    velocity[:, dofs] = [[0.3, -0.2, 0.1], [0.1, 0.2, 0.0], [-0.4, 0.0, 0.0]]
    force = bearing_forces(assembled, displacement, velocity)[bearing.name]
    k, c = (bearing.stiffness_x, bearing.stiffness_y), (bearing.damping_x, bearing.damping_y)
    assert force[0, :2].tolist() == [0.0, 0.0]  # inside the gap in x and y, moving or not
    assert force[0, 2] == pytest.approx(bearing.stiffness_z * 1e-6 + bearing.damping_z * 0.1, rel=1e-15)
    assert force[1, :2] == pytest.approx([k[0] * 2e-6 + c[0] * 0.1, k[1] * -4e-6 + c[1] * 0.2], rel=1e-12)
    assert force[2, 0] == pytest.approx(k[0] * -1e-6 + c[0] * -0.4, rel=1e-12) and force[2, 1] == 0.0


@pytest.mark.slow
@pytest.mark.parametrize("backlash", [True, False])
def test_motion_from_rest_approaches_the_periodic_orbit(backlash):
    # from rest the distance to the orbit falls as |μ|ᴺ at most, μ the largest Floquet multiplier (0.62 here), and
    # starts at the orbit's own size: after 12 periods the last period's δ is within |μ|¹² = 3.4e-3 of the orbit's
    # scale (measured 1.2e-5 with and 1.3e-5 without backlash: the slowest mode is little excited from rest); Kv of
    # the last period likewise (measured 4e-6 and 7e-6)
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
    from thermogear.drivetrain.transient_response import drivetrain_transient

    assembled, state = _loaded_pair()
    periods = 12
    transient = drivetrain_transient(assembled, state, periods, backlash=backlash, samples_per_piece=4, substeps=4)
    orbit = (drivetrain_backlash_response(assembled, state, substeps=4, samples_per_piece=4) if backlash
             else drivetrain_periodic_response(assembled, state, samples_per_piece=4))
    bound = float(np.abs(orbit.multipliers).max()) ** periods
    start = (periods - 1) * transient.period
    matched = 0
    for time, value in zip(orbit.time, orbit.transmission_error):  # the grid (extrema differ between the two)
        rows = np.flatnonzero(np.abs(transient.time - start - time) <= 1e-12 * transient.period)
        if rows.size:
            scale = np.abs(orbit.transmission_error).max()
            assert np.abs(transient.transmission_error[rows] - value).max() < bound * scale
            matched += 1
    assert matched >= 3 * 4 + 1
    assert transient.last_period["kv"] == pytest.approx(orbit.kv, rel=bound)
    assert transient.last_period["contact_loss_fraction"] == 0.0 and transient.time[0] == 0.0
    assert transient.transmission_error[0] == 0.0  # from rest
