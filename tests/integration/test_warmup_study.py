"""Warm-ups over a family of cases (issue 34, `thermogear sweep --kind warmup`): each point is the warm-up
`thermogear warmup --model gearbox` gives for that point's case, and the kind is named, never picked by a case
that cannot run it. Serial, workers, a scheduler and SIGKILL + resume: tests/integration/test_study_kinds.py."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from thermogear.errors import CaseError

CASE = Path(__file__).resolve().parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"
pytestmark = pytest.mark.filterwarnings("ignore")


def test_each_point_is_the_warmup_of_its_case_and_progress_counts_warmups(tmp_path):
    from contextlib import contextmanager

    from thermogear.case import load_case
    from thermogear.experiment.gearbox_warmup import gearbox_warmup
    from thermogear.sweep import Study
    from thermogear.sweep.warmup_study import WarmupSettings, run_warmup_study

    calls: list = []

    @contextmanager
    def progress(total: int, completed: int):
        calls.append(("start", total, completed))
        yield lambda points=1: calls.append(("advance", points))

    settings = WarmupSettings(600.0, 300.0, start_c=25.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        study = Study.define(load_case(CASE), {"torque_nm": [60, 160]}, model="thermal", chunk_points=1)
        data = run_warmup_study(study, tmp_path / "w.zarr", settings, "serial", progress=progress)
        alone = gearbox_warmup(load_case(CASE), duration_s=600.0, interval_s=300.0, start_c=25.0, torque=160.0)
    assert calls == [("start", 2, 0), ("advance", 1), ("advance", 1)]  # one per warm-up
    point = data.sel(torque_nm=160)
    assert list(data["time"].values) == [0.0, 300.0, 600.0] and str(point["status"].values) == "computed"
    # the same computation on the same case: equal to round-off (the store keeps float64)
    np.testing.assert_allclose(point["oil_c"].values, alone.history.node("oil"), rtol=1e-12)
    np.testing.assert_allclose(point["mesh_loss_w"].values, alone.history.mesh_loss, rtol=1e-12)
    np.testing.assert_allclose(point["kv"].values, [state.kv for state in alone.states], rtol=1e-12)
    assert float(point["warmup_start_c"]) == 25.0 and float(point["warmup_torque_nm"]) == 160.0
    # the heavier load heats the oil faster, from the same start
    oil = data["oil_c"].values
    assert oil[0, 0] == oil[1, 0] == 25.0 and oil[1, -1] > oil[0, -1] > 25.0


def test_the_kind_is_named_and_refused_where_it_cannot_run(tmp_path):
    import thermogear
    from thermogear.case.pieces import call_with_pieces
    from thermogear.sweep.api import StudySubject, study_kind
    from thermogear.case import load_case

    assert study_kind(call_with_pieces(StudySubject.of, load_case(CASE))).name != "warmup"  # a gearbox case's own study is its steady one
    with pytest.raises(CaseError, match=r"\[gearbox\]"):  # luo2019 has no thermal network to integrate
        thermogear.sweep("luo2019", vary={"torque_nm": [100]}, out=tmp_path / "a.zarr", kind="warmup")
    with pytest.raises(CaseError, match="one gear model"):
        thermogear.sweep(CASE, vary={"torque_nm": [100]}, out=tmp_path / "b.zarr", kind="warmup", model="both")
    with pytest.raises(CaseError, match="multistart"):
        thermogear.sweep(CASE, vary={"torque_nm": [100]}, out=tmp_path / "c.zarr", kind="warmup", multistart=4)
    with pytest.raises(CaseError, match="unknown kind"):
        thermogear.sweep(CASE, vary={"torque_nm": [100]}, out=tmp_path / "d.zarr", kind="warm-up")
    assert not any((tmp_path / name).exists() for name in ("a.zarr", "b.zarr", "c.zarr", "d.zarr"))
