"""Progress: the FE command names its steps; bars show on a terminal only (issue 15, part B)."""

from __future__ import annotations

import io
import subprocess
import sys
from types import SimpleNamespace

from thermogear.cli import fem as fem_command
from thermogear.cli.console import PlainConsole, point_progress, step_progress


def test_fem_summary_reports_each_step(monkeypatch):
    import thermogear.fem.verification as verification

    class Analysis(SimpleNamespace):
        def summary(self):
            return {"case": "luo2019", "flank_temperature_c": {"C": 80.0}, "stiffness_drop_percent": {"C": 14.5},
                    "x_te": 1.6, "x_te_line_of_action": -0.9}  # what the summary's interpretation reads

    heated = SimpleNamespace(reference_c=20.0, table_flank_c=(80.0,), wheel_flank_offset_c=1.0, pinion_base_c=70.0,
                             pinion_bore_c=60.0, wheel_base_c=70.0, wheel_bore_c=60.0)  # fem refuses cold teeth
    monkeypatch.setattr(verification, "cached_analysis",
                        lambda inputs: Analysis(refinement=1.0, temperature_field=heated))
    monkeypatch.setattr(verification, "fem_analysis",
                        lambda inputs, refinement: Analysis(refinement=refinement, temperature_field=heated))
    monkeypatch.setattr(verification, "refinement_change_percent", lambda coarse, fine: {"max": 0.5})
    steps = []
    summary, _ = fem_command.fem_summary("luo2019", refine=True, progress=steps.append)
    assert steps == list(fem_command.FEM_STEPS[:2])
    assert summary["refinement_compared"] == [1.0, 2.0]


def test_bars_show_on_a_terminal_only():
    terminal = PlainConsole(file=io.StringIO(), force_terminal=True, width=100)
    with point_progress("sweep", total=10, console=terminal) as advance:
        advance(4)
        advance(6)
    assert "10/10" in terminal.file.getvalue() and "points" in terminal.file.getvalue()
    pipe = PlainConsole(file=io.StringIO())
    with point_progress("sweep", total=10, console=pipe) as advance, \
            step_progress(["one", "two"], console=pipe) as step:
        advance(10)
        step("one")
    assert pipe.file.getvalue() == ""
    quiet = PlainConsole(file=io.StringIO(), force_terminal=True)
    with step_progress(["one"], quiet=True, console=quiet) as step:
        step("one")
    assert quiet.file.getvalue() == ""


def test_fem_has_a_quiet_option():
    result = subprocess.run([sys.executable, "-m", "thermogear", "fem", "--help"], capture_output=True, text=True)
    assert "--quiet" in result.stdout


def test_reproduce_progress_starts_before_the_model_loads_and_counts_every_step(monkeypatch, tmp_path):
    """`reproduce` shows its bar from the first second (loading NumPy, SciPy and numba's code is its first step)
    and the bar's total is every step the report announces (issue 24)."""
    from contextlib import contextmanager

    import thermogear.report.build as build
    from thermogear.case import load_case
    from thermogear.cli import reproduce as command

    shown: dict = {}

    @contextmanager
    def recording_progress(steps, quiet=False, console=None):
        shown["total"] = list(steps)
        shown["started"] = []
        yield shown["started"].append

    def fake_build_report(case, target, *, progress, timings, **options):
        for name in build.report_steps(case.citation):
            progress(name)
        shown["timings"] = timings

    monkeypatch.setattr(command, "step_progress", recording_progress, raising=False)
    monkeypatch.setattr("thermogear.cli.console.step_progress", recording_progress)
    monkeypatch.setattr(build, "build_report", fake_build_report)
    command.reproduce("luo2019", out=tmp_path / "report", force=False, quiet=True)
    assert shown["started"][0] == command.LOADING
    assert shown["started"] == shown["total"] == [command.LOADING, *build.report_steps(load_case("luo2019").citation)]
    assert set(shown["timings"]) == {"start-up", "imports"} and shown["timings"]["start-up"] > 0.0
