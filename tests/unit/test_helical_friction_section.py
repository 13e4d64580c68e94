"""A helical pair's friction damping takes the friction law on the normal section, as the gearbox's loss model does
(one definition, ``friction.models.normal_section_radius``): ISO/TR 13989-1 defines the relative radius of curvature
of a helical contact on the normal section, ρ_n = ρ_t/cos β_b, and its law takes the helical load factor K_Bγ.
Checked on the built-in H501 set against the same transverse pair taken as spur (``helical_pair`` removed), where
the load share, the unit load, the rolling speeds and the viscosity are the same, so the ratio of μ is the law's
own power of the two factors."""

from __future__ import annotations

import copy
import math
import tomllib
import warnings
from dataclasses import replace
from importlib import resources

import numpy as np
import pytest

from thermogear.case import case_from_document
from thermogear.friction.models import helical_load_factor, normal_section_radius
from thermogear.mesh.model import MeshModel


def _case(friction_model: str | None = None):
    document = tomllib.loads(resources.files("thermogear.parameter_sets").joinpath("fzg_h501.toml").read_text())
    document = copy.deepcopy(document)
    if friction_model is not None:
        document.setdefault("damping", {})["friction_model"] = friction_model
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_from_document(document)


def _friction(case) -> np.ndarray:
    model = MeshModel(case, "elastic")
    points = model.gear_pair.path_points
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return model.pair_damping_at(np.array([points["C"], 0.5 * (points["A"] + points["C"])])).friction_coefficient


def test_a_spur_pair_keeps_its_transverse_radius_exactly():
    assert normal_section_radius(0.0123, 0.0) == 0.0123


@pytest.mark.parametrize("friction_model, exponents", [
    # the paper's law (DIN 3990-4 mean μ, the damping's default): μ ∝ ρ^−0.25, no K_Bγ
    (None, (0.0, 0.25)),
    # ISO/TR 13989: μ ∝ (K_Bγ/ρ)^0.2·X_R with X_R ∝ ρ^−0.25
    ("iso_tr_13989_2", (0.2, 0.45)),
])
def test_the_damping_takes_the_normal_section_and_the_helical_load_factor(friction_model, exponents):
    helical = _case(friction_model)
    as_spur = replace(helical, helical_pair=None)
    base_helix = helical.helical_pair.base_helix_angle
    factor = helical_load_factor(helical.helical_pair.total_contact_ratio)
    expected = _friction(as_spur) * factor ** exponents[0] * math.cos(base_helix) ** exponents[1]
    assert base_helix > 0.2  # β = 15°: the factors differ from 1 by far more than the tolerance
    assert _friction(helical) == pytest.approx(expected, rel=1e-12)  # a power of exact factors: rounding only
