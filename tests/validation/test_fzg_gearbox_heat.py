"""The FZG test gearbox (built-in set ``fzg_test_gearbox``) against what FZG rigs do and what is published: stable
steady states at every load stage a rig runs, a 15-min load stage from 90 °C oil against the sump temperatures FZG
scuffing tests reach, the FVA 54/7 reference point against its commercial bulk temperature, and the energy balance
with every friction law. Nothing here is tuned: the set's housing and internal coefficients are stated assumptions
(docs/gearbox-temperature.md, "Validation")."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from thermogear.friction.models import FRICTION_MODELS
from thermogear.fzg import FZG_LOAD_STAGE_TORQUE_NM
from thermogear.gearbox.description import GearboxOperatingPoint, OilConditioning
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
from thermogear.gearbox.model import GearboxThermalModel
from thermogear.gearbox.procedure import FZG_START_C, fzg_load_stages, run_load_stages

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")
FZG_PINION_RPM = 2175.0  # motor 1450 rpm on the wheel shaft (ASTM D5182 §10.2), u = 1.5


@pytest.fixture(scope="module")
def model():
    return GearboxThermalModel(illustrative_fzg_gearbox())


@pytest.mark.parametrize("stage", range(5, 13), ids=[f"K{stage}" for stage in range(5, 13)])
def test_every_load_stage_a_rig_runs_has_a_stable_steady_state(model, stage):
    # FZG rigs run K5..K12 stage after stage: each must have a stable steady state (every eigenvalue of C⁻¹J < 0),
    # hot ones flagged, none "runaway"
    state = model.steady_state(GearboxOperatingPoint(FZG_PINION_RPM, FZG_LOAD_STAGE_TORQUE_NM[stage], 20.0))
    assert state.largest_eigenvalue < 0.0
    assert state.energy_balance_w < 1e-9


@pytest.fixture(scope="module")
def stages(model):
    # the FZG procedure: 15-min stages, each from 90 °C, the heater on its thermostat at 90 °C (ASTM D5182 §10.2–10.4;
    # heater power 1 kW assumed)
    return run_load_stages(model, FZG_PINION_RPM, fzg_load_stages(5, 12),
                           conditioning=OilConditioning(FZG_START_C, heater=1000.0))


def test_stage_end_temperatures_rise_with_the_load(stages):
    oil = [stage.oil_c for stage in stages]
    assert np.all(np.diff(oil) > 0.0)
    assert abs(oil[0] - FZG_START_C) < 1.0  # K5: the heater holds the oil near its set point
    assert all(stage.energy_residual < 1e-5 for stage in stages)  # the integration's identity, to about its rtol


# "Final sump temperatures as high as 140 °C are often reached after the final load stage (Load Stage 12)" of the
# A/8,33/90 test, each stage started at the same sump temperature (abstract of a World Tribology Congress III paper,
# ASME 2005, asmedigitalcollection.asme.org/WTC/proceedings-abstract/WTC2005/42010/465/307328). That test runs type A
# gears; the type C gears here lose less at the same torque (Ohlendorf's H_V 0.195 against about 0.31 for type A by
# the same closed form, evaluated by hand from its d_a 88.8/112.5 mm and x 0.8532/−0.5 — outside the form's validity
# there, ε1 = 1.11 —; μ differs by under 10 %), so a C-gear K12 stage should end at or below that value. Tolerance
# +5 K on the "as high as" reading (the abstract gives no spread).
PUBLISHED_K12_SUMP_C = 140.0


@pytest.mark.xfail(strict=True, reason="known gap: the set's assumed housing (40 kg, 0.45 x 0.30 x 0.40 m) and "
                                       "assumed internal coefficients run the C-gear K12 stage to 162 °C oil (148 °C "
                                       "while the shafts were lumped with their bearings, 151 °C while both shafts "
                                       "shared one node); the published A-gear value is at most 140 °C "
                                       "(docs/gearbox-temperature.md, 'What the gaps say')")
def test_k12_stage_from_90_c_ends_within_the_published_sump_temperature(stages):
    assert stages[-1].oil_c <= PUBLISHED_K12_SUMP_C + 5.0


# FVA information sheet 54/7 reference point as printed by a commercial calculation (KISSsoft "Reference data FZG-C
# test"): T1 = 265.1 N·m, 2250 rpm, oil 90 °C, pinion bulk temperature θ_M = 127.7 °C (37.7 K above the oil).
# The oil is held at 90 °C by the rig's thermostat (heater 2 kW, cooling 5 kW, gain 2 kW/K: within 0.1 K).
# Tolerance: no independent statement of the scatter of bulk-temperature measurements or calculations could be read
# (ISO/TS 6336-20/-21 and the FZG reports are not in the stored sources), so the ±30 % of the rise kept here is NOT
# an argued tolerance; the test is a strict xfail, a record of the gap, not a validation.
# History: 145.7 °C while both shafts shared one node; 138.6 °C with each shaft its own node, the gear body's
# conduction from its formula and Blok's heat partition; 157.6 °C once the stretch of shaft from each gear's seat to
# each bearing is a fin (Incropera Table 3.4 case B) instead of a conductor without resistance: a Ø30 mm steel shaft
# conducts only k·A/L = 0.65 W/K over the 50 mm from the gear to a bearing, so the pinion's path to its shaft node
# falls from 5.5 to 0.77 W/K and its heat must leave through the assumed gear–oil coefficient (200 W/(m² K)).
FVA_54_7_BULK_C = 127.7


@pytest.fixture(scope="module")
def fva_point(model):
    held = GearboxThermalModel(dataclasses.replace(model.description, conditioning=OilConditioning(
        90.0, heater=2000.0, cooling=5000.0, gain=2000.0)))
    return held.steady_state(GearboxOperatingPoint(2250.0, 265.1, 20.0))


def test_fva_point_holds_the_oil_at_90_c(fva_point):
    assert fva_point.oil_c == pytest.approx(90.0, abs=0.2)
    assert fva_point.energy_balance_w < 1e-9


@pytest.mark.xfail(strict=True, reason="known gap: the pinion's heat leaves mainly through the assumed gear–oil "
                                       "coefficient once the shaft's own conduction limits the path to the bearings "
                                       "(157.6 °C against 127.7 °C); no independently argued tolerance")
def test_fva_54_7_pinion_bulk_temperature(fva_point):
    assert fva_point.pinion_c == pytest.approx(FVA_54_7_BULK_C, abs=0.3 * (FVA_54_7_BULK_C - 90.0))


@pytest.mark.parametrize("name", sorted(FRICTION_MODELS))
def test_energy_balance_with_every_friction_law(model, name):
    description = dataclasses.replace(model.description, friction=FRICTION_MODELS[name],
                                      friction_constant=0.05 if name == "constant" else None)
    # K8: below the fold of the paper's law (near 285 N·m at 2175 rpm), so every law has a stable state there
    state = GearboxThermalModel(description).steady_state(GearboxOperatingPoint(FZG_PINION_RPM,
                                                                                FZG_LOAD_STAGE_TORQUE_NM[8], 20.0))
    assert state.energy_balance_w < 1e-9
    assert abs(float(np.sum(state.losses.node_sources)) - state.heat_out) < 1e-9
