"""The gearbox network around a helical pair (issue 37: the gearbox temperature model took only spur pairs): the
FZG test gearbox with the H501 helical gears. The helix enters the losses three ways (gearbox/losses.py): Ohlendorf's
H_V ∝ 1/cos β_b, the normal section's relative radius ρ_t/cos β_b in the friction law, and K_Bγ(ε_γ) in the
ISO/TR 13989 law; each is checked here against the same transverse pair taken as spur, and the whole against the
spur limit (β → 0) and the energy balance."""

from __future__ import annotations

import copy
import math
import tomllib
import warnings
from dataclasses import replace
from importlib import resources

import pytest

from thermogear.case import case_from_document
from thermogear.errors import CaseError
from thermogear.friction.models import helical_load_factor
from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
from thermogear.gearbox.losses import LossModel
from thermogear.gearbox.mesh_loss import pair_gear_loss_factor


def _document(name: str) -> dict:
    return tomllib.loads(resources.files("thermogear.parameter_sets").joinpath(f"{name}.toml").read_text())


def _case(helix_angle_deg: float = 15.0, friction_model: str | None = None):
    document = copy.deepcopy(_document("fzg_test_gearbox"))
    document["gears"] = copy.deepcopy(_document("fzg_h501")["gears"])  # z 20/30, m_n 3.5 mm, β 15°, b 23 mm
    document["gears"]["helix_angle_deg"] = helix_angle_deg
    if friction_model is not None:
        document["gearbox"]["friction_model"] = friction_model
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_from_document(document)


def _losses(case) -> LossModel:
    description = gearbox_model_from_case(case).description
    return LossModel(description, gearbox_operating_point(case.operating_point, case.gearbox))


@pytest.fixture(scope="module")
def helical():
    return _case()


def test_a_helical_pair_takes_the_gearbox_model_and_its_steady_state_balances(helical):
    assert helical.helical_pair is not None and helical.temperature.model == "gearbox"
    model = gearbox_model_from_case(helical)
    assert model.description.helical_pair is helical.helical_pair
    state = model.steady_state(gearbox_operating_point(helical.operating_point, helical.gearbox))
    assert abs(state.energy_residual) < 1e-9  # [W]
    assert state.largest_eigenvalue < 0.0
    # the loader wrote the network's oil temperature into the case (check = run: every command loads this case)
    assert helical.lubricant.operating_temperature_c == pytest.approx(state.oil_c, abs=1e-6)


def test_the_helix_enters_as_its_three_factors(helical):
    losses = _losses(helical)
    description = losses.description
    base_helix = helical.helical_pair.base_helix_angle
    as_spur = LossModel(replace(description, helical_pair=None), losses.operating)
    # H_V: Ohlendorf's 1/cos β_b on the transverse section's addendum contact ratios
    assert losses.loss_factor == pytest.approx(pair_gear_loss_factor(description.gear_pair) / math.cos(base_helix),
                                               rel=1e-14)
    # Schlenk's μ ∝ ρ^−0.2: the normal section's ρ_t/cos β_b gives μ·cos(β_b)^0.2
    assert losses.friction_coefficient(80.0) == pytest.approx(as_spur.friction_coefficient(80.0)
                                                              * math.cos(base_helix)**0.2, rel=1e-12)


def test_the_iso_tr_law_takes_the_helical_load_factor():
    case = _case(friction_model="iso_tr_13989_2")
    losses = _losses(case)
    as_spur = LossModel(replace(losses.description, helical_pair=None), losses.operating)
    base_helix = case.helical_pair.base_helix_angle
    factor = helical_load_factor(case.helical_pair.total_contact_ratio)
    assert factor > 1.0  # ε_γ = 2.0014 for H501: just above 2
    # μ ∝ (K_Bγ/ρ)^0.2·X_R, X_R ∝ ρ^−0.25: K_Bγ^0.2·cos(β_b)^0.2·cos(β_b)^0.25
    expected = as_spur.friction_coefficient(80.0) * factor**0.2 * math.cos(base_helix)**0.45
    assert losses.friction_coefficient(80.0) == pytest.approx(expected, rel=1e-12)


def test_a_vanishing_helix_is_the_spur_pair():
    # β = 1e-7° against β = 0 (the spur path, no helical pair): every loss and temperature to 1e-9
    nearly, spur = _case(1e-7), _case(0.0)
    assert spur.helical_pair is None and nearly.helical_pair is not None
    operating = gearbox_operating_point(spur.operating_point, spur.gearbox)
    first = gearbox_model_from_case(nearly).steady_state(operating)
    second = gearbox_model_from_case(spur).steady_state(operating)
    assert first.temperatures_c == pytest.approx(second.temperatures_c, rel=1e-9)
    assert first.losses.mesh == pytest.approx(second.losses.mesh, rel=1e-9)
    assert first.losses.churning == pytest.approx(second.losses.churning, rel=1e-9)


def test_the_fe_model_still_refuses_a_helical_pair_naming_the_allowed_models():
    document = copy.deepcopy(_document("fzg_h501"))
    document["temperature"] = {"model": "fem", "reference_c": 20.0}
    with pytest.raises(CaseError) as error:
        case_from_document(document)
    assert error.value.key == "temperature.model" and "gearbox" in str(error.value)
