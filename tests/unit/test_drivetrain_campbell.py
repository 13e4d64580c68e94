"""Interference diagram: crossings of the mesh harmonics with the modes found by root-finding equal the closed form
n_c = 60·f_i/(j·z₁) where the modes do not move with speed; with the gyroscopic terms they do move and every crossing
still lies on its harmonic line."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from drivetrain_builders import geared_pair

from thermogear.drivetrain.campbell import campbell_diagram
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.errors import CaseError

TEETH = 20


@pytest.fixture(scope="module")
def assembled():
    return geared_pair(elements=2, bearing_damping=200.0).assemble()


def test_crossings_equal_the_closed_form_without_gyroscopic_terms(assembled):
    still = replace(assembled, gyroscopic=np.zeros_like(assembled.gyroscopic), _cache={})
    modes = drivetrain_modes(still, damped=True, count=6)
    speeds = np.linspace(100.0, 30000.0, 7)
    diagram = campbell_diagram(still, speeds, TEETH, harmonics=(1, 2), mode_count=6, basis_cutoff_hz=math.inf)
    expected = sorted(60.0 * f / (j * TEETH) for j in (1, 2) for f in modes.frequencies_hz
                      if speeds[0] < 60.0 * f / (j * TEETH) < speeds[-1])
    found = [crossing.speed_rpm for crossing in diagram.crossings]
    # Brent to xtol 3e-5 rpm on a function that is exactly linear in n here: 1e-9 relative is rounding only
    assert len(found) == len(expected) > 3
    assert found == pytest.approx(expected, rel=1e-9)
    assert np.ptp(diagram.frequencies_hz, axis=0).max() < 1e-9 * diagram.frequencies_hz.max()


def test_gyroscopic_terms_move_the_modes_and_crossings_lie_on_their_lines(assembled):
    speeds = np.linspace(100.0, 30000.0, 9)
    diagram = campbell_diagram(assembled, speeds, TEETH, harmonics=(1, 2, 3), mode_count=12)
    # the lateral modes split into forward and backward whirl as the shafts spin (Friswell et al. 2010 §3.6):
    # some frequency moves by more than 0.1 % over the range (measured: several %)
    assert (np.ptp(diagram.frequencies_hz, axis=0) / diagram.frequencies_hz.min(axis=0)).max() > 1e-3
    for crossing in diagram.crossings:
        line = crossing.harmonic * TEETH * crossing.speed_rpm / 60.0
        assert crossing.frequency_hz == pytest.approx(line, rel=1e-8)
        assert 0.0 <= crossing.mesh_share <= 1.0
    assert any(crossing.mesh_share > 0.5 for crossing in diagram.crossings)  # the mesh mode is met
    assert all(c.mesh_share >= 0.1 for c in diagram.tooth_critical(0.1))


def test_plot_returns_a_figure(assembled):
    import matplotlib

    matplotlib.use("Agg")
    diagram = campbell_diagram(assembled, np.linspace(100.0, 30000.0, 4), TEETH, mode_count=4)
    figure = diagram.plot_campbell()
    assert figure.axes and figure.axes[0].get_xlabel() == "pinion speed [rpm]"


def test_bad_input_is_named(assembled):
    with pytest.raises(CaseError, match="speeds_rpm"):
        campbell_diagram(assembled, np.array([100.0, 50.0]), TEETH)
    with pytest.raises(CaseError, match="teeth"):
        campbell_diagram(assembled, np.array([100.0, 500.0]), 0)
    with pytest.raises(CaseError, match="harmonics"):
        campbell_diagram(assembled, np.array([100.0, 500.0]), TEETH, harmonics=(0,))


def _nearest_relative(found: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """Relative distance of each found frequency to the nearest reference frequency."""
    return np.min(np.abs(found[:, None] - reference[None, :]), axis=1) / found


@pytest.mark.parametrize("name", ["geared pair", "fzg_rig_type_c"])
def test_the_reduced_basis_meets_the_full_solve(assembled, name):
    """The speeds are solved on the undamped modes up to 1.5× the highest mode drawn plus the quasi-static vectors of
    the damping and gyroscopic forces (campbell module docstring). Against the full damped, spinning eigen-solve
    at every speed (drivetrain_modes, all DOFs) each followed frequency lies within 1e-4 relative of a full one, and
    the crossings lie within 1e-4 of those of the full basis. The tolerance: what is left out is the dynamics of
    the modes above the cut-off, second order in their coupling over the frequency gap; measured 1.2e-5 on the FZG
    rig set up to 15 000 rpm (6.5e-5 at a cut-off of 1× the highest mode, 7.8e-7 at 3×), and 1e-4 of a frequency is
    far below what the diagram or a crossing speed is read to (the damped and undamped frequencies of the same
    mode differ by a percent where the bearing damping is non-proportional)."""
    if name == "geared pair":
        system, teeth, top = assembled, TEETH, 30000.0
    else:
        from thermogear.case import load_case
        from thermogear.drivetrain.case_model import case_drivetrain

        built = case_drivetrain(load_case(name), ("elastic",))
        system, teeth, top = built.assembled("elastic"), built.teeth, 15000.0
    speeds = np.linspace(0.0, top, 7)
    reduced = campbell_diagram(system, speeds, teeth)
    full = campbell_diagram(system, speeds, teeth, basis_cutoff_hz=math.inf)
    assert reduced.basis_size < full.basis_size == system.size - drivetrain_modes(system).rigid_mode_count
    for index, speed in enumerate(speeds):
        exact = drivetrain_modes(system, speed=speed * math.pi / 30.0, damped=True, count=30).frequencies_hz
        assert _nearest_relative(reduced.frequencies_hz[index], exact).max() < 1e-4
        # the full basis is the full solve, to rounding
        assert _nearest_relative(full.frequencies_hz[index], exact).max() < 1e-9
    assert len(reduced.crossings) == len(full.crossings) > 5
    for mine, exact in zip(reduced.crossings, full.crossings):
        # (the column of a mode of an x/y pair degenerate at standstill may differ: which of the two is "first"
        # is a matter of rounding there; the crossing itself is the same)
        assert mine.harmonic == exact.harmonic
        assert mine.speed_rpm == pytest.approx(exact.speed_rpm, rel=1e-4)
        assert mine.mesh_share == pytest.approx(exact.mesh_share, abs=1e-4)


def test_modes_are_followed_by_their_shape_not_their_rank(assembled):
    """Each column is one mode: its shape at one speed is closest (MAC) to its own shape at the next, so where a
    forward and a backward whirl mode cross in frequency the columns cross too (by rank they would swap)."""
    speeds = np.linspace(0.0, 60000.0, 41)
    diagram = campbell_diagram(assembled, speeds, TEETH, mode_count=10)
    order = np.argsort(diagram.frequencies_hz, axis=1)
    # some pair of columns changes its frequency order over the range: followed by rank, it never would
    assert np.any(order[0] != order[-1])


def test_the_diagram_takes_what_a_case_builds():
    """``campbell_diagram(built.drivetrains["elastic"], ...)`` (a Drivetrain, not yet assembled) equals the diagram
    of its assembly; the CaseDrivetrain itself is refused with the advice to give one of its drivetrains."""
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import case_drivetrain

    built = case_drivetrain(load_case("fzg_rig_type_c"), ("elastic",))
    speeds = np.linspace(500.0, 9000.0, 5)
    direct = campbell_diagram(built.drivetrains["elastic"], speeds, built.teeth, mode_count=6)
    assembled = campbell_diagram(built.assembled("elastic"), speeds, built.teeth, mode_count=6)
    np.testing.assert_array_equal(direct.frequencies_hz, assembled.frequencies_hz)
    with pytest.raises(CaseError, match="drivetrain"):
        campbell_diagram(built, speeds, built.teeth)


def test_without_damping_and_spin_the_basis_holds_the_modes_exactly():
    """Limit: no damping and no gyroscopic terms leave no force to couple the kept modes to the others, so the
    diagram's frequencies are the undamped modes at every speed, to rounding (and no augmentation vector is added)."""
    still = geared_pair(elements=2).assemble()  # no damping anywhere
    still = replace(still, gyroscopic=np.zeros_like(still.gyroscopic), _cache={})
    diagram = campbell_diagram(still, np.linspace(0.0, 30000.0, 5), TEETH, mode_count=4)
    exact = drivetrain_modes(still, count=4).frequencies_hz
    np.testing.assert_allclose(diagram.frequencies_hz, np.broadcast_to(exact, (5, 4)), rtol=1e-9)
    assert diagram.basis_size == 4 + 6  # the modes drawn and the spare ones offered to the shape matching


def test_eigen_solves_run_on_one_blas_thread(assembled, monkeypatch):
    # issue 36: 100 speeds cost 4.4 s CPU with two OpenBLAS threads against 0.8 s on one (the ~90-row eigen-solves
    # only contend); whatever the caller's BLAS threads, each solve sees one
    from threadpoolctl import threadpool_info, threadpool_limits

    import thermogear.drivetrain.campbell as campbell

    seen = []
    solve = campbell._ReducedSpinningModes.solve

    def watched(self, speed):
        seen.extend(info["num_threads"] for info in threadpool_info() if info["user_api"] == "blas")
        return solve(self, speed)

    monkeypatch.setattr(campbell._ReducedSpinningModes, "solve", watched)
    with threadpool_limits(limits=2, user_api="blas"):
        campbell_diagram(assembled, np.linspace(0.0, 6000.0, 4), teeth=20, harmonics=(1,), mode_count=2)
    assert seen and set(seen) == {1}
