"""Luo & Li (2020) §3–4 dynamic results, reproduced by the full chain (own PEM stiffness, own thermal stiffness
with X_te calibrated to the paper's 14.52 % drop at C, own friction damping under the paper's mesh rule, exact
periodic steady state). One test per published number; each tolerance is argued beside it.

Why the tolerances cannot be tighter than they are: the paper does not give the bores (they set the fillet
stiffness, the equivalent mass and the base-circle expansion), its stiffness curve, its temperature polynomial
or X_te; our damping comes out 1.6-1.7x the paper's magnitudes for those reasons (docs/derivations.md), and the
paper reads its values off a transient RK4 run from rest, not the exact steady state.
"""

from __future__ import annotations

import pytest

from thermogear.simulation import Simulation, compare

pytestmark = pytest.mark.filterwarnings("ignore::thermogear.errors.ExtrapolationWarning")


@pytest.fixture(scope="module")
def responses(luo2019):
    return {model: response.metrics for model, response in compare(Simulation(luo2019), method="periodic").items()}


def test_frequency_ratio(responses):
    # paper §3: lambda = 0.153. f_n ~ sqrt(k_mean/me): the assumed bores move k_mean by +-7 % and me by +-5 %
    # (docs/derivations.md), i.e. lambda by about +-0.01.
    assert responses["elastic"]["frequency_ratio"] == pytest.approx(0.153, abs=0.01)


@pytest.mark.parametrize("model, paper", [("elastic", 1.21), ("thermal", 1.13)])
def test_dynamic_load_factor(responses, model, paper):
    # paper Eq. 29 / §4.2: Kv 1.21 (elastic), 1.13 (thermal). Kv - 1 scales with the damping ratio, which carries
    # the 1.6x damping-magnitude uncertainty; +-0.06 is about a quarter of Kv - 1 (docs/derivations.md found 1.25-1.26
    # and 1.17-1.18 for three bore assumptions with the paper's own damping).
    assert responses[model]["kv"] == pytest.approx(paper, abs=0.06)


def test_heat_lowers_the_dynamic_load_factor(responses):
    # paper §4.2: Kv falls from 1.21 to 1.13 because c_r > c_e
    assert responses["thermal"]["kv"] < responses["elastic"]["kv"]


def test_maximum_system_load_ratio(responses):
    # paper §4.2: the maximum system dynamic load is 1.65 x static (thermal case), at the single-to-double
    # transition. docs/derivations.md found 1.59-1.76 over the bore assumptions: +-0.12 covers that spread.
    assert responses["thermal"]["max_system_load_ratio"] == pytest.approx(1.65, abs=0.12)


@pytest.mark.parametrize("region, paper_percent", [("single", 20.82), ("double", 14.13)])
def test_thermal_equilibrium_rise(responses, region, paper_percent):
    # paper §4.1: thermal equilibrium (static TE) above elastic by 20.82 % (single) and 14.13 % (double). The rise
    # is the inverse of the stiffness drop in each region; our reconstructed flank temperature and the
    # calibrated X_te reproduce the drops at A/C/E within ~3 points, so +-6 points on the rise.
    rise = 100.0 * (responses["thermal"]["equilibrium_per_region"][region]
                    / responses["elastic"]["equilibrium_per_region"][region] - 1.0)
    assert rise == pytest.approx(paper_percent, abs=6.0)


def test_single_region_amplitude_falls_under_heat(responses):
    # paper §4.1: single-region amplitude 5.31 -> 4.13 um (-22.3 %) because the thermal damping is larger
    assert (responses["thermal"]["amplitude_per_region"]["single"]
            < responses["elastic"]["amplitude_per_region"]["single"])


def test_response_is_stable_and_in_contact(responses):
    # paper §4.1: the response converges to a periodic orbit (Floquet multipliers inside the unit circle) and the
    # teeth never separate at this load (static TE ~30 um, amplitudes < 10 um; Kahraman & Singh (1990))
    for metrics in responses.values():
        assert max(metrics["floquet_multipliers_abs"]) < 1.0
        assert not metrics["contact_loss"]["detected"]
