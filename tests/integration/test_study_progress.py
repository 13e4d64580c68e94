"""Progress per point and resume from the last completed point, for the pair's branch study and its multi-start
search (issue 34): every branch point (one model, one direction) and every point's search advances the progress by
one, and a study stopped part-way and resumed counts what it kept and computes only the rest, giving the store of
an uninterrupted run."""

from __future__ import annotations

import warnings
from contextlib import contextmanager

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.sweep import Study
from thermogear.sweep.branches import branch_study
from thermogear.sweep.task_store import open_task_store

pytestmark = pytest.mark.filterwarnings("ignore")


class _Stop(Exception):
    pass


def _recorder(calls: list, stop_after: int | None = None):
    """A progress(total, completed) context manager that records its start and every advance (and stops the study
    after ``stop_after`` advances, as an interruption would)."""

    @contextmanager
    def progress(total: int, completed: int):
        calls.append(("start", total, completed))

        def advance(points: int = 1) -> None:
            calls.append(("advance", points))
            if stop_after is not None and sum(1 for call in calls if call[0] == "advance") >= stop_after:
                raise _Stop

        yield advance

    return progress


@pytest.fixture(scope="module")
def study():
    # FZG type C's branches at three speeds and two torques: 2 groups × 1 model × 2 directions × 3 speeds = 12
    # branch points, and with two starts 6 point searches
    return Study.define(load_case("fzg_type_c"), {"torque_nm": [100, 200], "speed_rpm": "8000:24000:3"},
                        model="elastic")


@pytest.mark.parametrize("starts", [0, 2])
def test_progress_per_point_and_resume_from_the_last_point(study, starts, tmp_path):
    points = study.size * 2 + (study.size if starts else 0)
    whole: list = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        reference = branch_study(study, "both", workers=1, multistart=starts, out=tmp_path / "whole.zarr",
                                 progress=_recorder(whole))
    assert whole[0] == ("start", points, 0)
    assert [call for call in whole[1:]] == [("advance", 1)] * points  # one per point, never per group

    stopped: list = []
    with pytest.raises(_Stop), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        branch_study(study, "both", workers=1, multistart=starts, out=tmp_path / "part.zarr",
                     progress=_recorder(stopped, stop_after=4))  # inside the first group's up branch
    kept = int(np.asarray(open_task_store(tmp_path / "part.zarr", keep_record=True)["task_done"].values).sum())
    assert kept == 4
    resumed: list = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        data = branch_study(study, "both", workers=1, multistart=starts, out=tmp_path / "part.zarr", resume=True,
                            progress=_recorder(resumed))
    assert resumed[0] == ("start", points, kept)
    assert len(resumed) - 1 == points - kept  # only the rest computed, each point once
    for name in reference.data_vars:
        assert np.array_equal(np.asarray(data[name].values), np.asarray(reference[name].values),
                              equal_nan=data[name].dtype.kind == "f"), name


def test_a_store_and_no_store_give_the_same_numbers(study, tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        stored = branch_study(study, "both", workers=1, out=tmp_path / "s.zarr")
        memory = branch_study(study, "both", workers=1)
    assert "branch_state" not in memory
    for name in memory.data_vars:
        assert np.array_equal(np.asarray(memory[name].values), np.asarray(stored[name].values),
                              equal_nan=memory[name].dtype.kind == "f"), name
