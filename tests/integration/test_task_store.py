"""The one store writer of the study kinds (issue 34) and what issue 36 asks of it: a user's file anywhere inside a
store (array folders, chunk folders) stops --overwrite; export says when a store is incomplete; one held load."""

from __future__ import annotations

import numpy as np
import pytest

from inprocess_cli import invoke
from thermogear.errors import CaseError
from thermogear.ownership import MARKER, foreign_store_entries
from thermogear.sweep.task_store import StoreLayout, StoreVariable, TaskStore


def _layout(definition: dict | None = None) -> StoreLayout:
    return StoreLayout(coords={"speed_rpm": np.array([1.0, 2.0, 3.0]), "model": ["elastic"]},
                       variables=(StoreVariable("kv", ("model", "speed_rpm")),
                                  StoreVariable("status", ("model", "speed_rpm"), "str", width=20)),
                       tasks=3, definition=definition or {"kind": "test"}, chunks={"speed_rpm": 1})


def _filled(path, tasks=(0, 1, 2)) -> TaskStore:
    store = TaskStore.open(path, _layout())
    for number in tasks:
        store.write(number, {"speed_rpm": number}, {"kv": np.array([1.0 + number]), "status": np.array(["valid"])})
    return store


def test_tasks_are_written_marked_and_read_back(tmp_path):
    store = _filled(tmp_path / "s.zarr", tasks=(0, 2))
    assert store.done_tasks() == {0, 2}
    data = store.dataset()
    np.testing.assert_array_equal(data["kv"].values, [[1.0, np.nan, 3.0]])
    assert data["status"].values.tolist() == [["valid", "", "valid"]] and data["status"].dtype.kind == "U"


def test_resume_continues_the_same_study_and_refuses_another(tmp_path):
    path = tmp_path / "s.zarr"
    _filled(path, tasks=(1,))
    assert TaskStore.open(path, _layout(), resume=True).done_tasks() == {1}
    with pytest.raises(CaseError, match="same study"):
        TaskStore.open(path, _layout({"kind": "another"}), resume=True)
    with pytest.raises(CaseError, match="--overwrite"):
        TaskStore.open(path, _layout())


@pytest.mark.parametrize("where", ["notes.txt", "kv/notes.txt", "kv/c/0/mine.csv", "status/c/notes"])
def test_overwrite_never_deletes_a_users_file_at_any_depth(tmp_path, where):
    path = tmp_path / "s.zarr"
    _filled(path)
    user = path / where
    user.parent.mkdir(parents=True, exist_ok=True)
    user.write_text("keep", encoding="utf-8")
    assert foreign_store_entries(path) == [where]
    with pytest.raises(CaseError, match=where.replace(".", r"\.")):
        TaskStore.open(path, _layout(), overwrite=True)
    assert user.read_text(encoding="utf-8") == "keep" and (path / MARKER).is_file()
    user.unlink()  # thermogear's own files alone: replaced
    assert TaskStore.open(path, _layout(), overwrite=True).done_tasks() == set()


_PARTIAL = "0.86d00ddec2f04c3ea427331abd24774a.partial"  # zarr's name for a chunk it is still writing


@pytest.mark.parametrize("where", [f"kv/c/0/{_PARTIAL}", "status/zarr.0123456789abcdef0123456789abcdef.partial"])
def test_a_killed_writers_half_written_chunk_is_zarrs_own_and_goes_on_resume(tmp_path, where):
    """A writer killed during a chunk leaves zarr's temporary NAME.<32 hex>.partial (its atomic write renames it once
    complete): not a user's file, and removed when the study resumes (the task was never marked done, so its chunks
    are written again); a file named like it without zarr's 32 hex digits stays foreign."""
    path = tmp_path / "s.zarr"
    _filled(path, tasks=(1,))
    left = path / where
    left.write_bytes(b"half a chunk")
    assert foreign_store_entries(path) == []
    assert TaskStore.open(path, _layout(), resume=True).done_tasks() == {1}
    assert not left.exists()
    user = path / "kv" / "c" / "0" / "0.notes.partial"
    user.write_text("keep", encoding="utf-8")
    assert foreign_store_entries(path) == ["kv/c/0/0.notes.partial"]
    TaskStore.open(path, _layout(), resume=True)
    assert user.read_text(encoding="utf-8") == "keep"


def test_export_says_a_store_is_incomplete(tmp_path):
    path = tmp_path / "s.zarr"
    _filled(path, tasks=(0,))
    code, _, stderr = invoke("export", str(path), "--out", str(tmp_path / "s.csv"))
    assert code == 0 and "incomplete" in stderr and "2 of 3 tasks unfinished" in stderr, stderr
    assert "# INCOMPLETE: 2 of 3 tasks unfinished" in (tmp_path / "s.csv").read_text(encoding="utf-8")
    complete = tmp_path / "c.zarr"
    _filled(complete)
    code, _, stderr = invoke("export", str(complete), "--out", str(tmp_path / "c.csv"))
    assert code == 0 and "incomplete" not in stderr and "INCOMPLETE" not in (tmp_path / "c.csv").read_text()


def test_export_says_an_all_nan_store_without_a_record_is_incomplete(tmp_path):
    import xarray as xr

    path = tmp_path / "nan.zarr"
    xr.Dataset({"kv": (("speed_rpm",), np.full(3, np.nan))}, coords={"speed_rpm": [1.0, 2.0, 3.0]}).to_zarr(path)
    code, _, stderr = invoke("export", str(path))
    assert code == 0 and "every value is NaN" in stderr, stderr


@pytest.mark.parametrize("hold, label", [("torque", "constant torque"), ("power", "constant power")])
def test_one_held_load_for_every_sweep(hold, label):
    from thermogear.case import load_case
    from thermogear.sweep import Study
    from thermogear.sweep.load_held import study_load_held

    case = load_case("luo2019")  # given by its power: 80 kW at 2000 rpm
    study = Study.define(case, {"speed_rpm": [1000.0, 4000.0]}, model="elastic", hold=hold)
    assert study_load_held(study)[0] == label
    fast, slow = (study.case_at((speed,)).operating_point for speed in (1000.0, 4000.0))
    if hold == "torque":
        assert fast.torque == pytest.approx(slow.torque) == pytest.approx(381.97, rel=1e-4)
    else:  # the torque P/ω1 falls with speed
        assert fast.torque == pytest.approx(4.0 * slow.torque)
    torque_case = load_case("fzg_type_c")  # given by its torque: --hold power turns it into the power at its speed
    held = Study.define(torque_case, {"speed_rpm": [1000.0, 4000.0]}, model="elastic", hold=hold)
    fast, slow = (held.case_at((speed,)).operating_point for speed in (1000.0, 4000.0))
    assert fast.torque == pytest.approx((4.0 if hold == "power" else 1.0) * slow.torque)
    with pytest.raises(CaseError, match="--hold"):
        Study.define(case, {"speed_rpm": [1000.0]}, hold="speed")
