"""The drivetrain's pictures show what they say: every element of the layout drawn and labelled where it sits,
the mode shapes of the chosen modes, one marker per computed crossing in the interference diagram, the bearing-force
bars at the computed amplitudes."""

from __future__ import annotations

import math
from dataclasses import replace

import matplotlib
import numpy as np
import pytest
from drivetrain_builders import geared_pair

from thermogear.drivetrain import CrossSection, NodeLocation, RigidDisk, Shaft, ShaftSegment
from thermogear.drivetrain.campbell import campbell_diagram
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.drivetrain.plots import (plot_bearing_spectra, plot_layout, plot_mode_shape, shaft_placement)
from thermogear.drivetrain.point_elements import Coupling, TorsionalSupport

matplotlib.use("Agg")  # tests only: no display


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def _with_motor():
    """The geared pair with a motor on its own 0.1 m shaft, coupled to the pinion shaft's first end and held at
    speed."""
    pair = geared_pair(elements=2, bearing_damping=200.0)
    steel = pair.shafts[0].segments[0].material
    motor = Shaft("motor shaft", (ShaftSegment(0.1, CrossSection(0.03), steel),), 0.05)
    rotor = RigidDisk("rotor", NodeLocation("motor shaft", 0.05), 4.0, 4.0e-3, 2.0e-3)
    coupling = Coupling("coupling", NodeLocation("motor shaft", 0.1), NodeLocation("pinion shaft", 0.0), 1e4, 1.0)
    support = TorsionalSupport("motor", NodeLocation("motor shaft", 0.0), 1e3, 1.0)
    return replace(pair, shafts=(*pair.shafts, motor), disks=(*pair.disks, rotor), couplings=(coupling,),
                   torsional_supports=(support,))


def _gids(ax) -> list[str]:
    return [artist.get_gid() for artist in (*ax.patches, *ax.lines, *ax.collections) if artist.get_gid()]


def test_the_layout_draws_and_labels_every_element_where_it_sits():
    drivetrain = _with_motor()
    figure = plot_layout(drivetrain)
    ax = figure.axes[0]
    gids = _gids(ax)
    texts = {text.get_text() for text in ax.texts}
    for shaft in drivetrain.shafts:
        assert gids.count(f"shaft:{shaft.name}") == len(shaft.segments) and shaft.name in texts
    for bearing in drivetrain.bearings:
        assert gids.count(f"bearing:{bearing.name}") == 1 and bearing.name in texts
    assert {"gear:pinion", "gear:wheel", "disk:rotor", "coupling:coupling", "support:motor", "mesh:mesh"} <= set(gids)
    assert {"pinion", "wheel", "rotor", "coupling", "motor", "mesh"} <= texts
    # meshing shafts one centre distance apart (the pitch radii r_b/cos α_w), gears at the same z; the motor on the
    # pinion shaft's axis with the coupling's two points at the same z
    mesh = drivetrain.meshes[0]
    placed = shaft_placement(drivetrain)
    centre_distance = (mesh.base_radius_1 + mesh.base_radius_2) / math.cos(mesh.operating_pressure_angle)
    assert placed["pinion shaft"].row - placed["wheel shaft"].row == pytest.approx(centre_distance, rel=1e-12)
    assert placed["pinion shaft"].offset + 0.1 == pytest.approx(placed["wheel shaft"].offset + 0.1)
    assert placed["motor shaft"].row == placed["pinion shaft"].row
    assert placed["motor shaft"].offset + 0.1 == pytest.approx(placed["pinion shaft"].offset + 0.0)
    # the gears touch at the pitch point: the pinion's rectangle ends where the wheel's begins
    gears = {patch.get_gid(): patch for patch in ax.patches if (patch.get_gid() or "").startswith("gear:")}
    assert gears["gear:pinion"].get_y() == pytest.approx(
        gears["gear:wheel"].get_y() + gears["gear:wheel"].get_height(), abs=1e-9)


def test_a_mode_shape_draws_each_shafts_motion_to_one_scale():
    assembled = geared_pair(elements=4, bearing_damping=200.0).assemble()
    modes = drivetrain_modes(assembled, count=8)
    index = int(np.argmax(modes.mesh_share("mesh")))
    figure = plot_mode_shape(assembled, modes.shapes[:, index], "mesh mode")
    ax = figure.axes[0]
    lines = {line.get_gid(): line for line in ax.lines if line.get_gid()}
    assert set(lines) == {f"mode:{shaft}:{part}" for shaft in ("pinion shaft", "wheel shaft")
                          for part in ("x", "y", "torsion")}
    placed = shaft_placement(assembled.drivetrain)
    spacing = abs(placed["pinion shaft"].row - placed["wheel shaft"].row) * 1e3
    # the largest motion is drawn at 0.4 of the row spacing, and each curve is the shape's own entries
    largest = max(np.abs(line.get_ydata() - placed[gid.split(":")[1]].row * 1e3).max() for gid, line in lines.items())
    assert largest == pytest.approx(0.4 * spacing, rel=1e-9)
    offset = assembled.node_offsets["wheel shaft"]
    count = assembled.node_positions["wheel shaft"].size
    theta = modes.shapes[6 * offset + 5: 6 * (offset + count): 6, index]
    drawn = lines["mode:wheel shaft:torsion"].get_ydata() - placed["wheel shaft"].row * 1e3
    np.testing.assert_allclose(drawn / np.abs(drawn).max(), theta / np.abs(theta).max(), atol=1e-12)


def test_the_campbell_diagram_marks_every_crossing_and_labels_those_the_mesh_reaches():
    assembled = geared_pair(elements=2, bearing_damping=200.0).assemble()
    diagram = campbell_diagram(assembled, np.linspace(100.0, 30000.0, 30), 20, mode_count=10)
    figure = diagram.plot_campbell()
    ax = figure.axes[0]
    markers = [c for c in ax.collections if c.get_gid() == "crossings"]
    assert len(markers) == 1
    offsets = markers[0].get_offsets()
    assert len(offsets) == len(diagram.crossings) > 5
    np.testing.assert_allclose(offsets, [(c.speed_rpm, c.frequency_hz) for c in diagram.crossings])
    np.testing.assert_allclose(markers[0].get_array(), [c.mesh_share for c in diagram.crossings])
    # the crossings of modes the mesh reaches (share >= 0.01) are numbered by speed, and the legend says for each
    # its harmonic, speed and frequency
    reached = [c for c in diagram.crossings if c.mesh_share >= 0.01]
    numbers = [t for t in ax.texts if t.get_gid() == "crossing-label"]
    assert [t.get_text() for t in numbers] == [str(n) for n in range(1, len(reached) + 1)]
    assert 0 < len(reached) < len(diagram.crossings)
    assert [t.xy for t in numbers] == [(c.speed_rpm, c.frequency_hz) for c in reached]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == [f"{c.harmonic}× at {c.speed_rpm:.0f} rpm, {c.frequency_hz:.0f} Hz {c.label}, share "
                      f"{c.mesh_share:.2f}" for c in reached]
    # each mode's line is coloured by its mesh share between grid speeds; each harmonic drawn and named
    for mode in range(diagram.frequencies_hz.shape[1]):
        line = next(c for c in ax.collections if c.get_gid() == f"mode:{mode}")
        shares = diagram.mesh_shares[:, mode]
        np.testing.assert_allclose(line.get_array(), 0.5 * (shares[:-1] + shares[1:]))
    assert {f"harmonic:{j}" for j in diagram.harmonics} <= set(_gids(ax))
    assert {f"{j}× mesh" for j in diagram.harmonics} <= {t.get_text() for t in ax.texts}
    assert ax.get_xlabel() == "pinion speed [rpm]" and ax.get_ylabel() == "frequency [Hz]"


def test_the_bearing_spectra_are_bars_at_the_computed_amplitudes():
    spectra = {"A": ([100.0, 200.0, 300.0], [3.0, 1.0, 0.5]), "B": ([100.0, 200.0, 300.0], [2.0, np.nan, 4.0])}
    ax = plot_bearing_spectra(spectra, title="elastic").axes[0]
    for name, (_, amplitudes) in spectra.items():
        bars = [p for p in ax.patches if p.get_gid() == f"bearing-spectrum:{name}"]
        # a harmonic not computed (NaN) is drawn as no bar (zero height), never as a number
        np.testing.assert_array_equal([bar.get_height() for bar in bars], np.nan_to_num(amplitudes))
    assert [t.get_text() for t in ax.get_xticklabels()] == ["1×\n100 Hz", "2×\n200 Hz", "3×\n300 Hz"]


@pytest.fixture(scope="module")
def rig():
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import case_drivetrain

    return case_drivetrain(load_case("fzg_rig_type_c"), ("elastic",))


def test_a_case_gives_its_four_pictures_and_they_name_why_each_mode_is_drawn(rig):
    from thermogear.drivetrain.pictures import PICTURES, campbell_for_case, drivetrain_pictures, pictured_modes

    figures = drivetrain_pictures(rig)
    assert set(figures) == set(PICTURES)
    modes = drivetrain_modes(rig.assembled("elastic"))
    chosen = pictured_modes(rig, modes, None, "elastic")
    # the first is the mode with the largest mesh share (the torsional mesh mode, 0.90), then those behind the
    # largest bearing force (a lateral mode of the shafts carries most of it)
    assert chosen[0][0] == int(np.argmax(modes.mesh_share("mesh"))) and "largest mesh share" in chosen[0][1]
    assert any("largest bearing force" in why for _, why in chosen)
    titles = [ax.get_title() for ax in figures["drivetrain_modes"].axes if ax.get_title()]
    assert len(titles) == len(chosen) and all(f"mode {index + 1}:" in title for (index, _), title
                                              in zip(chosen, titles))
    # the report's diagram reaches the mesh mode and marks each of its computed crossings
    diagram, speed = campbell_for_case(rig, "elastic")
    assert diagram.mesh_shares.max() > 0.5 and diagram.speeds_rpm.size == 100
    ax = figures["drivetrain_campbell"].axes[0]
    markers = next(c for c in ax.collections if c.get_gid() == "crossings")
    assert len(markers.get_offsets()) == len(diagram.crossings)
    assert any(line.get_gid() == "operating-speed" and line.get_xdata()[0] == speed for line in ax.lines)


def test_the_modal_terms_of_a_bearing_force_add_up_to_the_direct_solution():
    """Identity: without damping, the sum over every elastic mode of K_b φ_i,b (φ_iᵀw)/(ω_i² − ω²) is the bearing's
    force K_b u_b with (K − ω²M) u = w solved directly on the elastic coordinates (w does not move the free rigid
    rotation of the train, which the modes leave out)."""
    from thermogear.drivetrain.participation import bearing_force_modal_terms, bearing_force_terms
    from thermogear.dynamics.modes.rigid_body import rigid_body_reduction

    assembled = geared_pair(elements=4).assemble()  # no damping anywhere
    modes = drivetrain_modes(assembled)  # every elastic mode
    frequency = 0.7 * modes.frequencies_hz[5] + 0.3 * modes.frequencies_hz[6]  # between two modes
    terms = bearing_force_modal_terms(assembled, modes, "wheel shaft bearing A", frequency)
    reduction = rigid_body_reduction(assembled.mass, assembled.connection_stiffness(), assembled.rigid_candidates())
    omega = 2.0 * np.pi * frequency
    dynamic = reduction.project(assembled.stiffness() - omega ** 2 * assembled.mass)
    displacement = reduction.expand(np.linalg.solve(dynamic, reduction.project_vector(assembled.mesh_vectors[0])))
    bearing = next(b for b in assembled.drivetrain.bearings if b.name == "wheel shaft bearing A")
    dofs = [assembled.dof(bearing.location, name) for name in ("x", "y", "z")]
    direct = bearing.stiffness_matrix()[:2, :3] @ displacement[dofs]
    np.testing.assert_allclose(terms.sum(axis=1).real, direct, rtol=1e-9, atol=1e-12 * np.abs(direct).max())
    sizes = bearing_force_terms(assembled, modes, "wheel shaft bearing A", frequency)
    assert sizes.shape == modes.frequencies_hz.shape and np.all(sizes >= 0.0)
