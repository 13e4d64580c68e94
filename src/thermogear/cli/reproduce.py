"""`thermogear reproduce luo2019`: run the paper's whole chain and write the report beside the paper's numbers."""

from __future__ import annotations

from pathlib import Path

import typer

from thermogear.cli.app import app, console, error_console
from thermogear.report.terminal import interruptible
from thermogear.errors import CaseError

#: Papers thermogear reproduces: name → built-in parameter set.
PAPERS = {"luo2019": "luo2019"}
#: The first step of the progress bar: the imports and the case.
LOADING = "loading the model"


@app.command()
def reproduce(
    paper: str = typer.Argument(..., metavar="PAPER", help="the paper to reproduce: luo2019"),
    out: Path = typer.Option(None, "--out", help="output folder (default ./thermogear-<paper>/)"),
    force: bool = typer.Option(False, "--force", help="replace an existing output folder"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="no progress bar and no summary (for scripts)"),
) -> None:
    """Reproduce a paper: every figure, every number beside the paper's, the assumptions and the differences,
    in one self-contained report.html (+ figures/, results.nc, summary.json)."""
    import atexit  # noqa: PLC0415
    import gc  # noqa: PLC0415
    import time  # noqa: PLC0415

    from thermogear.cli.console import step_progress  # noqa: PLC0415
    from thermogear.cli.timing import seconds_since_import  # noqa: PLC0415
    from thermogear.report.steps import steps_of_report  # noqa: PLC0415

    start_up = seconds_since_import()
    # at the interpreter's exit its last full collections would walk every object once more only to free memory
    # the system takes back anyway: 0.3-0.5 s CPU, over a second of wall on a loaded machine. Frozen first, they
    # are skipped (atexit runs before those collections, and only when the process really ends)
    atexit.register(gc.freeze)
    if paper not in PAPERS:
        from thermogear.errors import closest_key

        suggestion = closest_key(paper, list(PAPERS))
        raise CaseError("paper", paper, ", ".join(PAPERS),
                        "no such paper" + (f" (did you mean '{suggestion}'?)" if suggestion else ""))
    from thermogear.ownership import check_output_folder, is_owned

    target = out if out is not None else Path(f"thermogear-{paper}")
    check_output_folder(target, "--out")  # before any work
    # a second run replaces its own previous report (only the files it wrote; a user's files stay): the README's
    # first command works twice. A folder thermogear did not write is still refused.
    force = force or is_owned(target, "report")
    from thermogear.report.writer import OutputFolder

    OutputFolder(target, force=force).check()  # before any work
    # the bar shows from the first second: loading the model (NumPy, SciPy, numba's compiled code) is a step
    steps = [LOADING, *steps_of_report(paper=True)]
    with interruptible(target), step_progress(steps, quiet, error_console) as advance:
        advance(LOADING)
        begin = time.perf_counter()
        from thermogear.case import load_case
        from thermogear.report.build import build_report

        case = load_case(PAPERS[paper])
        # the modules, the schema and the case outlive the report: out of the collector's sight, its full
        # collections do not walk their ~10^5 objects again and again while the figures are drawn (~0.2 s CPU)
        gc.freeze()
        try:
            outcome = build_report(case, target, force=force, paper=True, progress=advance,
                                   timings={"start-up": start_up, "imports": time.perf_counter() - begin})
        finally:
            gc.unfreeze()  # a caller that goes on (a test running the command in its process) gets them back
    if not quiet:
        from thermogear.report.terminal import print_summary

        print_summary(outcome, console)
