"""Luo & Li (2020) §2.1 / Fig. 4: thermal stiffness of the Table 1 pair, one test per published number.

What is calibrated and what is predicted: X_te is calibrated (closed form, Eq. 18) to the paper's 14.52 % drop
at the pitch point C, with F_n = the external normal load (the luo2019 default). Everything else below is a
prediction from the reconstructed temperature field (docs/thermal.md, "Validation").

Known unknowns behind every tolerance: the paper gives no expansion coefficient, no bore radii, no base-circle
or bore temperature and no coefficients of its Fig. 3(c) temperature polynomial; the luo2019 set reconstructs
them (assumptions in the parameter set). Its elastic stiffness (PEM + Sainsot fillet) agrees with ISO 6336-1
within ~4 % but the paper's own k_e curve is not tabulated.
"""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.case.pieces import call_with_pieces
from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model
from thermogear.mesh.model import MeshModel
from thermogear.summaries.thermal import thermal_curves, thermal_stiffness_summary


@pytest.fixture(scope="module")
def summary(luo2019):
    return thermal_stiffness_summary(call_with_pieces(paper_thermal_model, luo2019), MeshModel(luo2019, "elastic"),
                                     MeshModel(luo2019, "thermal"))


@pytest.fixture(scope="module")
def pair_share_curves(luo2019):
    pair_share = luo2019.with_changes(**{"thermal.load_basis": "pair_share"})
    return thermal_curves(call_with_pieces(paper_thermal_model, pair_share))


def test_calibration_is_reported_and_reproduces_its_target(summary):
    # Not a validation (it is the calibration): it checks the calibration is labelled and self-consistent.
    assert summary["x_te_source"].startswith("calibrated")
    assert summary["stiffness_drop_percent"]["C"] == pytest.approx(14.52, abs=1e-9)
    assert 0.0 < summary["x_te"] < 1.0


# The paper: 8.53 % at A and E. Tolerance ±3 percentage points (issue's acceptance band). Argument: with X_te
# fixed at C, Eq. 18 gives drop(A)/drop(C) ≈ [k_e(A)/k_e(C)]·[ΣΔ_t(A)/ΣΔ_t(C)]. ΣΔ_t is nearly constant along the
# path (the radial parts project as λΔT·ρ_k and ρ1 + ρ2 = T1T2), so the temperature assumptions barely matter
# (base/bore 60/40 to 77/77 °C, λ 11.5–12.5e-6, fit degree 4–6: drop at A 10.3–10.6 %); what sets it is the
# elastic ratio k_e(A)/k_e(C), 0.69 for this PEM model (docs/derivations.md likewise) against the ≈0.55 the paper's
# 8.53/14.52 implies. A ±20 % difference in that ratio between stiffness models is common (fillet-foundation
# and Hertz variants), which is ±2–3 points here.
@pytest.mark.parametrize("point", ["A", "E"])
def test_drop_at_meshing_in_and_out(summary, point):
    assert summary["stiffness_drop_percent"][point] == pytest.approx(8.53, abs=3.0)


def test_largest_drop_at_the_pitch_point(summary):
    # Paper: "the largest drop where k_e is largest" — C is the maximum of the drop along the whole path.
    drops = summary["stiffness_drop_percent"]
    assert drops["C"] >= max(drops.values()) - 1e-9
    assert summary["stiffness_drop_percent_range"]["max"] == pytest.approx(drops["C"], abs=0.01)


def test_thermal_below_elastic_along_the_whole_path(summary, luo2019):
    assert summary["thermal_below_elastic_everywhere"] is True
    curves = thermal_curves(call_with_pieces(paper_thermal_model, luo2019))
    assert np.all(curves.curve.stiffness < curves.curve.elastic_stiffness)


# Tips: the paper gives +20.02 % (driving) and +16.29 % (driven). Tolerance ±6 points (issue's band): the tip
# change (1 + X_te)·δ_Tp/δ − δ_Tpi/δ_i is a difference of two terms of ~0.2–0.7 each, so a 10 % uncertainty in the
# reconstructed expansion of one flank moves it by ~5 points.
@pytest.mark.parametrize("key, paper", [("driving_tip", 20.02), ("driven_tip", 16.29)])
def test_tip_compliance_change(summary, key, paper):
    assert summary["single_tooth_compliance_change_percent"][key] == pytest.approx(paper, abs=6.0)


# Roots: the paper gives −42.2 % (driving) and −92 % (driven). The reconstruction does NOT reach them (driving
# +8.5 %, driven −22 %). At the root the change (1 + X_te)ΣΔ_t/(F_n δ) − Δ_ti/(F_n δ_i) is a small difference of
# two terms of ~0.65 and ~0.6–0.9; the paper's values need Δ_ti/(F_n δ_i) ≈ 1.08 (driving, A) and 1.57 (driven,
# E), about 1.8–1.9 times the 0.57 and 0.88 found here, i.e. much more root-flank expansion per unit of the root's
# elastic deflection than Eqs. 8–12 give for any stated temperature (docs/thermal.md, "Validation").
# Asserted is what holds in both: the root change is well below the tip change on both gears.
@pytest.mark.parametrize("gear, paper_tip, paper_root", [("driving", 20.02, -42.2), ("driven", 16.29, -92.0)])
def test_root_change_is_below_tip_change(summary, gear, paper_tip, paper_root):
    changes = summary["single_tooth_compliance_change_percent"]
    assert paper_root < paper_tip  # the published ordering being checked
    assert changes[f"{gear}_root"] < changes[f"{gear}_tip"] - 10.0


def test_driven_root_compliance_is_reduced(summary):
    # Paper −92 %: the sign (thermal compliance below elastic at the driven root) is reproduced, not the size.
    assert summary["single_tooth_compliance_change_percent"]["driven_root"] < 0.0


def test_single_tooth_curves_cross_at_most_once(summary):
    # Paper: elastic and thermal single-tooth curves cross exactly once, near the root, thermal stiffer on the root
    # side. Here: the driven tooth crosses once, on its root side of the pitch point (its root is at E, Γ > 0);
    # the driving tooth does not cross (its thermal compliance stays above the elastic one down to A, +8.5 %).
    counts = summary["single_tooth_crossing_count"]
    crossing = summary["single_tooth_crossing_gamma"]
    assert counts["driven"] == 1 and crossing["driven"] > 0.0
    assert counts["driving"] <= 1


def test_only_the_external_load_gives_the_paper_shape(summary, pair_share_curves):
    # The check, confirmed: with F_n = the pair's share the drop is largest where the pair shares the load
    # (the double-contact zone, up to A and E), not at C; with the external load it is largest at C.
    share = pair_share_curves.points.drop_percent  # A, B, C, D, E
    assert share[0] > share[2] + 5.0 and share[4] > share[2] + 5.0
    external = summary["stiffness_drop_percent"]
    assert external["C"] > external["A"] and external["C"] > external["E"]
