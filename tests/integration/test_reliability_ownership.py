"""thermogear only ever replaces, resumes or deletes what it wrote itself (issue 15, data loss).

A directory thermogear did not write (no ownership marker) given to ``sweep --resume``, ``sweep --overwrite``,
``run --force`` or ``reproduce --force`` is refused with exit status 2 and one line naming the path, and its
contents are left exactly as they were. The report writer's corner cases (a symbolic link as the target, ``..``
in the path, stale partial folders of a killed run) are checked on :class:`OutputFolder` directly.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import inprocess_cli

from thermogear.errors import CaseError
from thermogear.ownership import MARKER, is_owned, write_marker
from thermogear.report.writer import OutputFolder


def _thermogear(*args: str, cwd=None) -> subprocess.CompletedProcess:
    return inprocess_cli.run(*args, cwd=cwd, env={**os.environ, "COLUMNS": "200"})


def _foreign_folder(path: Path) -> dict[str, bytes]:
    """A folder with someone else's files (one of them looks like a zarr store), returned as a snapshot."""
    path.mkdir()
    (path / "thesis.tex").write_text("six years of work\n")
    (path / "zarr.json").write_text('{"zarr_format": 3, "node_type": "group"}')
    (path / "data").mkdir()
    (path / "data" / "measurement.csv").write_text("1,2,3\n")
    return _snapshot(path)


def _snapshot(path: Path) -> dict[str, bytes]:
    return {str(p.relative_to(path)): p.read_bytes() for p in sorted(path.rglob("*")) if p.is_file()}


def _assert_refused(result: subprocess.CompletedProcess, path: Path) -> None:
    """Exit 2 and one message naming the path. (How stderr is wrapped is the console's business, issue 15 part B:
    the message is counted by its ``error:`` prefix and read with line breaks removed.)"""
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr
    assert result.stderr.count("error:") == 1 and result.stderr.lstrip().startswith("error:"), result.stderr
    assert str(path) in result.stderr.replace("\n", ""), result.stderr


SWEEP = ("sweep", "luo2019", "--vary", "speed_rpm=1000,2000", "--scheduler", "serial", "--no-progress")


@pytest.mark.parametrize("option", ["--resume", "--overwrite"])
def test_sweep_refuses_a_folder_it_did_not_write(tmp_path, option):
    target = tmp_path / "mine"
    before = _foreign_folder(target)
    result = _thermogear(*SWEEP, "--out", str(target), option)
    _assert_refused(result, target)
    assert _snapshot(target) == before


@pytest.mark.parametrize("command", [("run", "luo2019"), ("reproduce", "luo2019")])
def test_report_force_refuses_a_folder_it_did_not_write(tmp_path, command):
    target = tmp_path / "mine"
    before = _foreign_folder(target)
    result = _thermogear(*command, "--out", str(target), "--force", "--quiet")
    _assert_refused(result, target)
    assert _snapshot(target) == before


def test_sweep_writes_a_marker_and_resume_and_overwrite_accept_its_own_store(tmp_path):
    target = tmp_path / "study.zarr"
    assert _thermogear(*SWEEP, "--out", str(target)).returncode == 0
    assert is_owned(target, "sweep-store")
    resumed = _thermogear(*SWEEP, "--out", str(target), "--resume", "--json")
    assert resumed.returncode == 0, resumed.stderr
    assert json.loads(resumed.stdout)["chunks_kept"] == 1  # resumed, not recreated
    overwritten = _thermogear(*SWEEP, "--out", str(target), "--overwrite", "--json")
    assert overwritten.returncode == 0, overwritten.stderr
    assert json.loads(overwritten.stdout)["chunks_computed"] == 1
    assert is_owned(target, "sweep-store")


def test_sweep_overwrite_through_a_symlink_replaces_the_store_and_keeps_the_link(tmp_path):
    real = tmp_path / "real.zarr"
    assert _thermogear(*SWEEP, "--out", str(real)).returncode == 0
    link = tmp_path / "link.zarr"
    link.symlink_to(real)
    result = _thermogear(*SWEEP, "--out", str(link), "--overwrite")
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and link.resolve() == real.resolve() and is_owned(real, "sweep-store")


def test_sweep_overwrite_through_a_symlink_to_a_foreign_folder_is_refused(tmp_path):
    real = tmp_path / "theirs"
    before = _foreign_folder(real)
    link = tmp_path / "link.zarr"
    link.symlink_to(real)
    _assert_refused(_thermogear(*SWEEP, "--out", str(link), "--overwrite"), real)
    assert _snapshot(real) == before and link.is_symlink()


def test_sweep_resume_of_an_empty_foreign_folder_deletes_nothing(tmp_path):
    target = tmp_path / "empty"
    target.mkdir()
    _assert_refused(_thermogear(*SWEEP, "--out", str(target), "--resume"), target)
    assert target.is_dir() and list(target.iterdir()) == []


# ------------------------------------------------------------------------------------------- report writer
def _write(target, force=True) -> Path:
    with OutputFolder(target, force=force) as folder:
        (folder.path / "report.html").write_text("new")
    return folder.target


def test_force_replaces_only_its_own_report_folder(tmp_path):
    target = tmp_path / "report"
    _write(target, force=False)
    assert is_owned(target, "report")
    (target / "report.html").write_text("old")
    _write(target)
    assert (target / "report.html").read_text() == "new"
    foreign = tmp_path / "foreign"
    before = _foreign_folder(foreign)
    with pytest.raises(CaseError, match="did not write"):
        _write(foreign)
    assert _snapshot(foreign) == before


def test_force_through_a_symlink_leaves_no_dangling_link(tmp_path):
    real = tmp_path / "real"
    _write(real, force=False)
    link = tmp_path / "link"
    link.symlink_to(real)
    _write(link)
    assert link.is_symlink() and link.resolve() == real.resolve()
    assert (link / "report.html").read_text() == "new"
    leftovers = [p.name for p in tmp_path.iterdir() if p.name.startswith(".")]
    assert leftovers == [], leftovers


def test_force_through_a_symlink_to_a_foreign_folder_is_refused(tmp_path):
    foreign = tmp_path / "foreign"
    before = _foreign_folder(foreign)
    link = tmp_path / "link"
    link.symlink_to(foreign)
    with pytest.raises(CaseError, match="did not write"):
        _write(link)
    assert _snapshot(foreign) == before and link.is_symlink()


def test_dotdot_in_the_path_creates_no_intermediate_folder(tmp_path):
    _write(tmp_path / "a" / "sub" / ".." / "x", force=False)
    assert (tmp_path / "a" / "x" / "report.html").is_file()
    assert not (tmp_path / "a" / "sub").exists()


def _dead_pid() -> int:
    process = subprocess.Popen([sys.executable, "-c", "pass"])
    process.wait()
    return process.pid


def test_stale_partials_of_its_own_are_removed_and_nothing_else(tmp_path):
    target = tmp_path / "report"
    stale = tmp_path / ".report.partial-killed"
    stale.mkdir()
    write_marker(stale, "report")
    document = json.loads((stale / MARKER).read_text())
    (stale / MARKER).write_text(json.dumps({**document, "pid": _dead_pid()}))
    (stale / "figure.png").write_bytes(b"\0" * 1000)
    running = tmp_path / ".report.partial-running"  # a live writer (this process) must not lose its folder
    running.mkdir()
    write_marker(running, "report")
    foreign = tmp_path / ".report.partial-theirs"  # same name pattern, no marker: not ours
    foreign.mkdir()
    (foreign / "keep.txt").write_text("keep")
    other_target = tmp_path / ".other.partial-killed"
    other_target.mkdir()
    (other_target / MARKER).write_text((stale / MARKER).read_text())
    _write(target, force=False)
    assert not stale.exists()
    assert running.is_dir() and (foreign / "keep.txt").read_text() == "keep" and other_target.is_dir()


def test_unwritable_parent_is_one_clear_error(tmp_path, monkeypatch):
    # a read-only folder refuses the temporary folder with PermissionError (the tests may run as root, who may
    # write anywhere, so the refusal is injected where the writer meets the file system)
    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr("thermogear.report.writer.tempfile.mkdtemp", refuse)
    with pytest.raises(CaseError, match="cannot write there: Permission denied"):
        _write(tmp_path / "report", force=False)
    assert list(tmp_path.iterdir()) == []


def test_unwritable_parent_is_refused_before_any_work(tmp_path, monkeypatch):
    # the check runs before the computing starts (build_report calls it first): here it alone must refuse
    def refuse(*args, **kwargs):
        raise OSError(30, "Read-only file system")

    monkeypatch.setattr("thermogear.report.writer.tempfile.mkdtemp", refuse)
    with pytest.raises(CaseError, match="Read-only file system"):
        OutputFolder(tmp_path / "report").check()


@pytest.mark.parametrize("command", [("run", "luo2019"), SWEEP])
def test_out_below_a_file_is_one_clear_error(tmp_path, command):
    blocker = tmp_path / "file.txt"
    blocker.write_text("not a folder")
    target = blocker / "sub" / "out"
    _assert_refused(_thermogear(*command, "--out", str(target)), target)
    assert blocker.read_text() == "not a folder"
