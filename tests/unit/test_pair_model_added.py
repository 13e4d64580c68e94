"""Adding a model through the registry only: a fourth pair model, registered inside the test, runs through
``Simulation(case, model=name)`` to a periodic response; nothing else in the package is edited (issue 26).

The model: a constant pair stiffness along the path of contact, k̄ = the mean of the elastic k_e(s) over the roll
distance [A, E], the rectangular-wave mesh stiffness of the simplest parametric gear models (the mesh stiffness
jumps between k̄ and 2k̄ as one or two pairs carry the load). Everything else is the elastic model's.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import ClassVar

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.errors import CaseError
from thermogear.mesh.pair_models import PAIR_MODELS, ElasticPair
from thermogear.simulation import Simulation


@dataclass(frozen=True, eq=False)
class ConstantPairStiffness(ElasticPair):
    """The elastic pair with its stiffness averaged along the path of contact [N/m]."""

    name: ClassVar[str] = "constant_pair_stiffness"

    @cached_property
    def mean_pair_stiffness(self) -> float:
        points = self.gear_pair.path_points
        roll = np.linspace(points["A"], points["E"], 2001)
        stiffness = self.elastic_pair_stiffness_at(roll)
        return float(np.sum(0.5 * (stiffness[1:] + stiffness[:-1]) * np.diff(roll)) / (roll[-1] - roll[0]))

    def pair_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        return np.full(np.shape(roll), self.mean_pair_stiffness)


@pytest.fixture
def registered(monkeypatch):
    monkeypatch.setitem(PAIR_MODELS, ConstantPairStiffness.name, ConstantPairStiffness)  # the one registry line
    return ConstantPairStiffness.name


@pytest.fixture(scope="module")
def luo2019():
    return load_case("luo2019")


def test_an_unregistered_name_is_refused(luo2019):
    with pytest.raises(CaseError, match="constant_pair_stiffness"):
        Simulation(luo2019, ConstantPairStiffness.name)


def test_a_registered_model_runs_to_a_periodic_response(luo2019, registered):
    simulation = Simulation(luo2019, registered)
    pair = simulation.mesh_model.pair_model
    assert isinstance(pair, ConstantPairStiffness) and not simulation.mesh_model.thermal
    state = simulation.state
    stiffness = pair.mean_pair_stiffness
    # the mesh stiffness is k̄ times the pairs in contact: 1 or 2 for a contact ratio between 1 and 2 (exact up to
    # the summation's rounding, hence 1e-12)
    contact_ratio = pair.gear_pair.contact_ratio
    assert 1.0 < contact_ratio < 2.0
    counts = state.mesh_stiffness / stiffness
    np.testing.assert_allclose(counts, np.round(counts), rtol=0, atol=1e-12)
    assert set(np.round(counts).astype(int)) == {1, 2}
    # its time mean is k̄ ε: the grid's intervals end at every contact change, so the time weights are exact; the
    # contact ratio is the geometry's, computed apart from the grid (1e-9: rounding of the interval lengths)
    assert state.mean_mesh_stiffness == pytest.approx(stiffness * contact_ratio, rel=1e-9)

    response = simulation.run("periodic")
    assert response.label == registered
    # a periodic orbit: stable (Floquet multipliers inside the unit circle) and closing on itself over one period
    assert np.all(np.abs(response.multipliers) < 1.0)
    scale = np.ptp(response.displacement)
    assert scale > 0.0  # the parametric stiffness (k̄ ↔ 2k̄) excites a response
    assert abs(response.displacement[-1] - response.displacement[0]) <= 1e-6 * np.max(np.abs(response.displacement))
    assert np.isfinite(response.metrics["kv"]) and response.metrics["kv"] >= 1.0


def test_the_added_model_differs_from_the_elastic_one_only_in_its_stiffness(luo2019, registered):
    # same mass, same static load, same friction damping law (the oil at the reference temperature): the mean mesh
    # stiffness of the two agree to the accuracy of averaging k_e along the path (the grid and the 2001-point mean
    # weight it differently: 1 %), while the shape of k(τ) differs
    added, elastic = Simulation(luo2019, registered).state, Simulation(luo2019, "elastic").state
    assert added.mass == elastic.mass and added.normal_load == elastic.normal_load
    assert added.mean_mesh_stiffness == pytest.approx(elastic.mean_mesh_stiffness, rel=1e-2)
    assert np.ptp(added.mesh_stiffness) != pytest.approx(np.ptp(elastic.mesh_stiffness), rel=1e-2)
