"""Sweeps: progress counted in points, summaries and plots without the points where the linear model fails,
value lists checked quickly, absurd sizes refused, no dashboard unless asked (issue 15, part B)."""

from __future__ import annotations

import contextlib

import numpy as np
import pytest

from thermogear.case import Case, load_case
from thermogear.cli.sweep_summary import response_summary
from thermogear.errors import CaseError
from thermogear.sweep import engine
from thermogear.sweep.plots import linear_model_valid, plot_speed_response
from thermogear.sweep.study import CHECKED_VALUES, MAX_POINTS, Study


@pytest.fixture(scope="module")
def luo2019():
    return load_case("luo2019")


@pytest.fixture(scope="module")
def light_load_run(luo2019, tmp_path_factory):
    """luo2019 at 20 N·m from 6000 to 8000 rpm (chunks of 2 points): the light load loses contact at 7000 rpm in
    both models (the linear model's Kv there is no load factor). Returns (study, run, advances, total)."""
    study = Study.define(luo2019, ["torque_nm=20", "speed_rpm=6000:8000:5"], model="both", chunk_points=2)
    recorded: dict = {"advances": []}

    @contextlib.contextmanager
    def recording_progress(total, completed):
        recorded["total"], recorded["completed"] = total, completed
        yield recorded["advances"].append

    run = engine.run_study(study, tmp_path_factory.mktemp("sweep") / "light.zarr", scheduler="serial",
                           progress=recording_progress)
    return study, run, recorded


def test_progress_counts_points_not_chunks(light_load_run):
    study, _, recorded = light_load_run
    assert len(study.blocks()) == 3  # 5 points in chunks of 2: a chunk count would total 3
    assert recorded["total"] == study.size == 5 and recorded["completed"] == 0
    assert sorted(recorded["advances"]) == [1, 2, 2]


def test_summary_leaves_out_contact_loss(light_load_run):
    study, run, _ = light_load_run
    dataset = run.dataset
    valid = linear_model_valid(dataset)
    assert not bool(valid.all()), "the light load must lose contact somewhere, or this test checks nothing"
    summary = response_summary(run, study.models)  # read with zarr as NumPy; checked here against xarray
    for model in study.models:
        kv = np.asarray(dataset["kv"].sel(model=model), dtype=float)
        holds = np.asarray(valid.sel(model=model), dtype=bool)
        assert summary["valid_points"][model] == int(holds.sum())
        expected = float(kv[holds].max()) if holds.any() else None
        assert summary["kv_max"][model] == expected
        assert summary["kv_max_all_points"][model] == float(np.nanmax(kv))
    assert summary["contact_loss_points"] == int((dataset["contact_loss"] == 1).sum())


def test_speed_plot_draws_no_curve_through_invalid_points(light_load_run):
    import matplotlib.pyplot as plt

    _, run, _ = light_load_run
    dataset = run.dataset
    figure = plot_speed_response(dataset, quantities=("kv",))
    try:
        axis = figure.axes[0]
        for model in dataset["model"].values:
            line = next(line for line in axis.get_lines() if line.get_label() == str(model))
            holds = np.asarray(linear_model_valid(dataset).sel(model=model).squeeze(), dtype=bool)
            drawn = np.isfinite(np.asarray(line.get_ydata(), dtype=float))
            assert np.array_equal(drawn, holds)
        assert any("contact loss" in str(line.get_label()) for line in axis.get_lines())
    finally:
        plt.close(figure)


def test_a_million_values_are_checked_with_a_few_cases(luo2019, monkeypatch):
    built = []
    original = Case.with_changes

    def counting(self, **changes):
        built.append(changes)
        return original(self, **changes)

    monkeypatch.setattr(Case, "with_changes", counting)
    study = Study.define(luo2019, ["speed_rpm=500:12000:1000000"], model="thermal")
    assert study.size == 1_000_000
    assert len(built) <= CHECKED_VALUES + 1  # one case per checked value (+1 if the definition builds one)


def test_a_bad_value_at_the_end_of_a_long_list_is_still_found(luo2019):
    # the smallest and the largest value are always among the checked ones, wherever they stand in the list
    values = ",".join(str(v) for v in [*np.linspace(500.0, 12000.0, 500), -100.0])
    with pytest.raises(CaseError) as raised:
        Study.define(luo2019, [f"speed_rpm={values}"], model="thermal")
    assert "-100" in str(raised.value)


def test_absurd_sizes_are_refused_with_the_size(luo2019):
    with pytest.raises(CaseError) as raised:
        Study.define(luo2019, ["speed_rpm=500:12000:1000000000000"])
    assert "1,000,000,000,000" in str(raised.value)
    side = int(np.sqrt(MAX_POINTS)) + 1
    with pytest.raises(CaseError) as raised:
        Study.define(luo2019, [f"speed_rpm=500:12000:{side}", f"torque_nm=100:400:{side}"])
    assert f"{side * side:,} points" in str(raised.value)


def test_local_cluster_starts_no_dashboard_unless_asked(monkeypatch):
    import distributed

    from thermogear.sweep import executor

    started = []

    class FakeCluster:
        def __init__(self, **options):
            started.append(options)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            return False

    class FakeClient(FakeCluster):
        def __init__(self, cluster):
            self.cluster = cluster

        def register_plugin(self, plugin):
            pass

    monkeypatch.setattr(distributed, "LocalCluster", FakeCluster)
    monkeypatch.setattr(distributed, "Client", FakeClient)
    with executor._client("processes", 1, None):
        pass
    with executor._client("processes", 1, ":0"):
        pass
    assert started[0]["dashboard_address"] is None
    assert started[1]["dashboard_address"] == ":0"