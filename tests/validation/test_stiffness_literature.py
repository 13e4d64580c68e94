"""PEM mesh stiffness against published mesh-stiffness results, and the physical limits of the issue.

Published results used (see docs/stiffness.md, "Validation"):

1. ISO 6336-1:2006, §9 (Method B): the single stiffness c′ and mean mesh stiffness c_γα of spur gears, an
   empirical fit by the standard (after Winter & Podlesnik's measurements and FE data) to steel gears with solid
   discs and the ISO 53 basic rack. Formulas as in ISO 6336-1 clause 9 [S: python-gearbox, GEARpie].
2. ISO 6336-1 / DIN 3990-1 (Method C): in the absence of better data, steel spur gears with solid discs and
   a standard basic rack have c′ ≈ 14 N/(mm·μm) and c_γα ≈ 20 N/(mm·μm). [R]: recalled from the standard; the
   same two values are the default of independent public gear codes found with the search tool (a C# rating
   code with ``cGamma = 20`` and a project plan quoting "c′ ≈ 14 and c_γ ≈ 20 N/(mm·µm)" as the published gate).

No table of a PEM paper (Tian 2004, Chaari 2009, Ma 2014, Kiekbusch 2011) could be opened in this session, so the
comparison is with the standard's values; the gap is stated in docs/stiffness.md.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.geometry import Gear, GearPair
from thermogear.materials import Material
from thermogear.geometry.mesh_cycle import MeshCycle
from thermogear.stiffness.iso6336 import iso6336_stiffness
from thermogear.stiffness.potential_energy import pair_compliance

STEEL = Material()
N_PER_MM_UM = 1e9

# Standard spur pairs (α = 20°, ISO 53 rack, b = 20 mm) with "solid-disc-like" bodies: bore radius 0.4 r, i.e.
# h_f = r_f / r_int ≈ 2.2–2.4, inside Sainsot's fitted range. (teeth 1, teeth 2, module [mm], x1, x2)
PAIRS = [(20, 40, 3.0, 0.0, 0.0), (25, 50, 4.0, 0.0, 0.0), (30, 30, 3.0, 0.0, 0.0), (40, 80, 2.0, 0.0, 0.0),
         (18, 36, 3.0, 0.2, 0.1), (27, 35, 3.0, 0.0, 0.0), (50, 50, 2.0, 0.0, 0.0), (60, 90, 2.0, 0.0, 0.0)]


def make_pair(teeth_1, teeth_2, module_mm, shift_1, shift_2, width=0.02) -> GearPair:
    def gear(teeth, shift):
        return Gear(teeth=teeth, module=module_mm * 1e-3, pressure_angle=math.radians(20), face_width=width,
                    profile_shift=shift, bore_radius=0.4 * module_mm * teeth * 0.5e-3)

    return GearPair.create(gear(teeth_1, shift_1), gear(teeth_2, shift_2))


def pem(pair: GearPair, mesh_stiffness) -> tuple[float, float]:
    """(max single-pair stiffness, mean mesh stiffness) per unit width [N/(mm·μm)]."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        width = pair.face_width
        single = pair_compliance(pair, STEEL, pair.roll_grid(201)).stiffness.max() / width / N_PER_MM_UM
        grid, _, total = mesh_stiffness(pair, STEEL, 1000.0, 1024)
    return single, float(grid.time_average(total)) / width / N_PER_MM_UM


@pytest.mark.parametrize("pair_data", PAIRS, ids=lambda p: f"z{p[0]}-{p[1]}-m{p[2]}-x{p[3]}-{p[4]}")
def test_mean_mesh_stiffness_against_iso6336_method_b(pair_data, mesh_stiffness):
    """PEM mean vs ISO c_γα within 12 %. Tolerance: Method B is a fit with no stated accuracy; published
    comparisons of PEM variants with FE and ISO (Cooley et al. 2016, MMT 105:540; Kiekbusch et al. 2011) show
    method-to-method spreads of order 10 % [R]; the fit also ignores the bore (h_f), which moves the PEM value by
    several percent over Sainsot's range. Measured here: −5 % … +9 %."""
    pair = make_pair(*pair_data)
    iso = iso6336_stiffness(pair, STEEL)
    _, mean = pem(pair, mesh_stiffness)
    assert mean == pytest.approx(iso["c_gamma_alpha"] / N_PER_MM_UM, rel=0.12)


@pytest.mark.parametrize("pair_data", PAIRS, ids=lambda p: f"z{p[0]}-{p[1]}-m{p[2]}-x{p[3]}-{p[4]}")
def test_single_pair_maximum_against_iso6336_method_b(pair_data, mesh_stiffness):
    """ISO c′ is the maximum single-pair stiffness: PEM max within 12 % (same argument as above)."""
    pair = make_pair(*pair_data)
    iso = iso6336_stiffness(pair, STEEL)
    single, _ = pem(pair, mesh_stiffness)
    assert single == pytest.approx(iso["c_prime"] / N_PER_MM_UM, rel=0.12)


@pytest.mark.parametrize("pair_data", [p for p in PAIRS if p[3] == p[4] == 0.0],
                         ids=lambda p: f"z{p[0]}-{p[1]}")
def test_typical_values_of_iso6336(pair_data, mesh_stiffness):
    """c′ ≈ 14 and c_γα ≈ 20 N/(mm·μm) for unshifted steel spur gears with solid discs [R]. These are rounded
    typical values (two figures) meant for pairs the standard does not resolve: ±10 % for c′, ±15 % for c_γα
    (c_γα grows with ε_α, which spans 1.63–1.81 here)."""
    single, mean = pem(make_pair(*pair_data), mesh_stiffness)
    assert single == pytest.approx(14.0, rel=0.10)
    assert mean == pytest.approx(20.0, rel=0.15)


# ------------------------------------------------------------------------------------------ physical limits
def test_stiffness_proportional_to_modulus_and_face_width():
    pair = make_pair(27, 35, 3.0, 0.0, 0.0, width=0.02)
    wide = make_pair(27, 35, 3.0, 0.0, 0.0, width=0.05)
    roll = pair.roll_grid(31)
    base = pair_compliance(pair, STEEL, roll).stiffness
    np.testing.assert_allclose(pair_compliance(pair, Material(youngs_modulus=3 * 206e9), roll).stiffness,
                               3 * base, rtol=1e-12)
    np.testing.assert_allclose(pair_compliance(wide, STEEL, roll).stiffness, 2.5 * base, rtol=1e-12)


def test_one_to_one_pair_symmetric_about_the_pitch_point():
    pair = make_pair(30, 30, 3.0, 0.0, 0.0)
    points = pair.path_points
    offsets = np.linspace(0.0, points["E"] - points["C"], 15)
    left = pair_compliance(pair, STEEL, points["C"] - offsets).stiffness
    right = pair_compliance(pair, STEEL, points["C"] + offsets).stiffness
    np.testing.assert_allclose(left, right, rtol=1e-12)
    # and the mesh stiffness over one period is symmetric about the middle of the single-contact zone
    cycle = MeshCycle(pair, 1000.0)
    start, end = cycle.transition_times[1], cycle.period
    times = np.linspace(start, end, 41)[1:-1]
    roll, in_contact = cycle.positions(times)
    assert np.all(in_contact.sum(axis=0) == 1)
    values = pair_compliance(pair, STEEL, roll[0]).stiffness
    np.testing.assert_allclose(values, values[::-1], rtol=1e-10)


def test_tooth_compliance_grows_toward_the_tip():
    pair = make_pair(27, 35, 3.0, 0.0, 0.0)
    compliance = pair_compliance(pair, STEEL, pair.roll_grid(51))
    assert np.all(np.diff(compliance.pinion.total) > 0)  # pinion contact moves root → tip along the path
    assert np.all(np.diff(compliance.wheel.total) < 0)  # wheel contact moves tip → root
