"""`thermogear reproduce luo2019` as a new user runs it: default folder, every file, one row per paper number,
no silent overwrite, and an interrupted run leaves the previous output or none."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import inprocess_cli

import thermogear
from thermogear.luo2020.report.table import PAPER_ROWS

FIGURES = ("fig3c", "fig4", "fig6", "fig7", "fig8", "fig9", "fig10", "fig11", "fig12", "fig15")
FIELDS = ("quantity", "paper", "thermogear", "unit", "deviation", "tolerance", "within", "note", "status", "reason")
# one test worker runs the module, so that the README command runs once for the tests of its output (pytest-xdist
# --dist loadgroup)
pytestmark = pytest.mark.xdist_group(name="reproduce-default-run")


def _command(*args: str) -> list[str]:
    return [sys.executable, "-m", "thermogear", *args]


@pytest.fixture(scope="module")
def default_run(tmp_path_factory):
    """One run with no --out, in an empty working folder (the README's first command)."""
    folder = tmp_path_factory.mktemp("user")
    result = subprocess.run(_command("reproduce", "luo2019", "--quiet"), cwd=folder, capture_output=True, text=True,
                            timeout=300)
    assert result.returncode == 0, result.stderr
    return folder / "thermogear-luo2019", result


def test_default_folder_has_every_file(default_run):
    out, _ = default_run
    assert (out / "report.html").is_file() and (out / "summary.json").is_file() and (out / "results.nc").is_file()
    for name in FIGURES:
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000, name
        assert (out / "figures" / f"{name}.svg").is_file(), name
    assert not list(out.parent.glob(".thermogear-luo2019.*")), "temporary folders left behind"


def test_summary_has_one_row_per_paper_number(default_run):
    out, _ = default_run
    summary = json.loads((out / "summary.json").read_text())
    assert summary["thermogear_version"] == thermogear.__version__
    keys = [row["key"] for row in summary["table"]]
    # none missing, none added, same order: the paper's rows, then the rig's temperatures predicted (one per
    # Table 3 temperature; thermogear.luo2020.report.rig_section)
    rig = [key for key in keys if key.startswith("rig.")]
    assert keys == [row.key for row in PAPER_ROWS] + rig and len(rig) == 9
    for row in summary["table"]:
        for field in FIELDS:
            assert field in row, (row["key"], field)
        if row["status"] == "not computed":
            assert row["reason"], row["key"]
            # a crashed stage fails its rows, optional or not: only the run duration cannot be computed by nature
            assert row["key"] == "sec5.run_duration", f"row not computed: {row['key']}: {row['reason']}"
        else:
            assert row["within"] in (True, False)
    # counts per kind; the headline counts predictions only: no input or calibration row in it
    counts = summary["table_counts"]
    assert set(counts) == {"prediction", "qualitative", "calibration", "input"}
    for kind, numbers in counts.items():
        rows = [row for row in summary["table"] if row["kind"] == kind]
        assert numbers["total"] == len(rows), kind
        assert numbers["within"] == sum(row["status"] == "within" for row in rows), kind
    assert summary["headline"]["predictions"] == counts["prediction"]
    assert counts["prediction"]["total"] >= 25 and counts["calibration"]["total"] >= 1
    for gap in summary["headline"]["known_gaps"]:
        assert gap["kind"] in ("prediction", "qualitative") and gap["cause"], gap
    fe = summary["fig15_fe_versus_analytical"]  # Fig. 15 stated as it is: FE drop against the analytical one
    assert fe["fe_drop_percent"][0] > fe["analytical_drop_percent"][1]
    assert {"elastic", "thermal"} <= set(summary["models"])
    assert any("Luo" in ref["text"] for ref in summary["references"])


def test_results_file_carries_curves_case_and_version(default_run):
    import xarray as xr

    out, _ = default_run
    with xr.open_dataset(out / "results.nc", engine="h5netcdf") as root:
        assert root.attrs["thermogear_version"] == thermogear.__version__
        assert "[gears]" in root.attrs["case_toml"] and root.attrs["case_name"] == "luo2019"
        assert root["thermal_pair_stiffness"].size > 100
        assert float((root["thermal_pair_stiffness"] < root["elastic_pair_stiffness"]).mean()) == 1.0
    for group in ("elastic_steady", "thermal_steady", "elastic_transient", "thermal_transient"):
        with xr.open_dataset(out / "results.nc", engine="h5netcdf", group=group) as data:
            assert data["displacement"].size > 10, group


def test_report_is_self_contained(default_run):
    out, _ = default_run
    page = (out / "report.html").read_text()
    assert page.count("<figure id=") == len(FIGURES)  # each figure once in the figures section ...
    assert page.count("src='data:image/png;base64,") == len(FIGURES) + 3  # ... and three key figures up front
    assert page.index("id='headline'") < page.index("id='case'") < page.index("id='paper'")
    assert "<script" not in page and "src='http" not in page and 'href="http' not in page
    assert "References" in page and "Assumptions" in page


def test_a_folder_thermogear_did_not_write_is_not_overwritten(tmp_path):
    out = tmp_path / "mine"
    out.mkdir()
    (out / "summary.json").write_text("my own", encoding="utf-8")
    result = inprocess_cli.run("reproduce", "luo2019", "--out", str(out), "--quiet")
    assert result.returncode == 2
    assert "did not write" in result.stderr
    assert (out / "summary.json").read_text(encoding="utf-8") == "my own"


def _interrupt(out: Path, signum: int, extra: tuple[str, ...] = ()) -> int:
    """Start a run into ``out`` and send ``signum`` once its temporary folder exists (mid-write)."""
    process = subprocess.Popen(_command("reproduce", "luo2019", "--out", str(out), "--quiet", *extra),
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and process.poll() is None:
        if list(out.parent.glob(f".{out.name}.partial-*")):
            break
        time.sleep(0.02)
    if process.poll() is None:
        os.kill(process.pid, signum)
    process.communicate(timeout=120)
    return process.returncode


def test_sigint_keeps_previous_output(default_run, tmp_path):
    source, _ = default_run
    out = tmp_path / "report"
    out.mkdir()
    (out / "summary.json").write_text((source / "summary.json").read_text())
    before = (out / "summary.json").read_text()
    code = _interrupt(out, signal.SIGINT, ("--force",))
    assert code != 0
    assert (out / "summary.json").read_text() == before, "the previous output was changed"
    assert not (out / "report.html").exists()
    assert not list(tmp_path.glob(".report.*")), "temporary folder left behind"


def test_sigterm_leaves_no_output(tmp_path):
    out = tmp_path / "fresh"
    code = _interrupt(out, signal.SIGTERM)
    assert code != 0
    assert not out.exists(), "an interrupted first run must leave no folder"
    assert not list(tmp_path.glob(".fresh.*")), "temporary folder left behind"


def test_unknown_paper_is_refused():
    result = inprocess_cli.run("reproduce", "luo2018")
    assert result.returncode == 2
    assert "luo2019" in result.stderr


def test_timings_cover_the_whole_command(default_run):
    """timings_s list the stages one after the other from the process's start to the files (issue 24): start-up
    and imports first, the figures and the files last; what ran beside them is in timings_background_s."""
    out, _ = default_run
    summary = json.loads((out / "summary.json").read_text())
    stages = list(summary["timings_s"])
    assert stages[:3] == ["start-up", "imports", "elastic model"]
    assert stages[-3:] == ["figures", "FE verification", "files"]
    assert all(seconds >= 0.0 for seconds in summary["timings_s"].values())
    assert set(summary["timings_background_s"]) == {"FE verification", "figures and results file", "rig prediction"}


def test_the_collector_skips_the_long_lived_objects_during_the_report_and_gets_them_back(monkeypatch, tmp_path):
    """The modules and the case are frozen out of the collector's full collections while the report is built
    (they outlive it); a caller that goes on afterwards (this test process) has them back in its collector."""
    import gc

    import thermogear.report.build
    from inprocess_cli import invoke

    frozen = []

    def record_and_skip(case, out, **options):  # the report itself is not what this test checks
        frozen.append(gc.get_freeze_count())

    monkeypatch.setattr(thermogear.report.build, "build_report", record_and_skip)
    before = gc.get_freeze_count()
    code, _, stderr = invoke("reproduce", "luo2019", "--out", str(tmp_path / "report"), "--quiet")
    assert code == 0, stderr
    assert frozen and frozen[0] > before  # frozen while the report was built
    assert gc.get_freeze_count() == before  # and given back


def test_the_readme_command_twice_replaces_its_own_report_and_keeps_the_users_files(default_run):
    # issue 25: the second `thermogear reproduce luo2019` exited 2 asking for --force; --force deleted the user's
    # files inside the folder. Now it replaces what it wrote and nothing else. (Last in this file: it rewrites the
    # module's report folder.)
    out, _ = default_run
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    (out / "figures" / "mine").mkdir()
    (out / "figures" / "mine" / "sketch.txt").write_text("mine too", encoding="utf-8")
    (out / "summary.json").write_text("{}", encoding="utf-8")  # thermogear's file, edited: it is replaced
    result = subprocess.run(_command("reproduce", "luo2019", "--quiet"), cwd=out.parent, capture_output=True,
                            text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert (out / "notes.txt").read_text(encoding="utf-8") == "mine"
    assert (out / "figures" / "mine" / "sketch.txt").read_text(encoding="utf-8") == "mine too"
    assert json.loads((out / "summary.json").read_text(encoding="utf-8"))  # rewritten, not the user's "{}"
