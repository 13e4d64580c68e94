"""Build the whole report folder of one case: evaluate, draw, write (atomically).

    outcome = build_report(load_case("luo2019"), Path("thermogear-luo2019"))

writes ``report.html``, ``figures/<fig>.png|svg``, ``results.nc`` and ``summary.json`` into the folder, which
appears complete or not at all (:class:`~thermogear.report.writer.OutputFolder`).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from thermogear.citations import citations_used, clear_citations
from thermogear.report.evaluate import (Evaluation, evaluate_case, is_paper_case, key_results, model_messages,
                                        paper_verdicts)
from thermogear.luo2020.report.rig_section import rig_section, rig_verdicts, with_rig_section
from thermogear.report.steps import steps_of_report
from thermogear.report.writer import OutputFolder

__all__ = ["ReportOutcome", "build_report", "report_steps"]


@dataclass
class ReportOutcome:
    """What was written and what the terminal summary shows."""

    folder: Path
    evaluation: Evaluation
    verdicts: list
    results: list[dict]
    messages: list[str]
    figures: list[str]
    missing_figures: dict[str, str]
    seconds: float
    timings: dict = field(default_factory=dict)

    @property
    def report(self) -> Path:
        return self.folder / "report.html"


def report_steps(citation: str | None, models=("elastic", "thermal"), drivetrain: bool = False) -> list[str]:
    """The progress steps of :func:`build_report` for a case whose ``[case] citation`` is ``citation`` (for a
    progress bar's total); ``drivetrain``: the case has a ``[drivetrain]``."""
    return steps_of_report(is_paper_case(citation), models, drivetrain)


def build_report(case, out: Path | str, *, force: bool = False, method: str = "periodic", paper: bool | None = None,
                 progress: Callable[[str], None] | None = None, timings: dict | None = None) -> ReportOutcome:
    """Run the chain of ``case`` and write its report folder ``out`` (see module docstring).

    ``paper``: add the paper column (default: for the paper's own case). An existing ``out`` is refused before
    any work unless ``force``. ``progress(step)`` is called before each step. ``timings``: seconds of what the
    caller did before (start-up, imports), listed first in ``timings_s`` so that the stages add up to the whole
    command. The results file is written in a second process, which then shares the figures with this one: each
    takes the next figure not yet taken (:class:`thermogear.forked.SharedCounter`).
    """
    begin = time.perf_counter()
    from thermogear import __version__, forked
    from thermogear.evaluation import finish_evaluation
    from thermogear.report.figures import FE_FIGURES, FIGURES, write_figures
    from thermogear.report.drivetrain_section import drivetrain_json
    from thermogear.report.html import render_report
    from thermogear.report.results_file import case_toml_text, summary_document, write_summary_json

    before = dict(timings or {})
    before["imports"] = before.get("imports", 0.0) + time.perf_counter() - begin
    start = time.perf_counter()
    step = progress or (lambda name: None)
    folder = OutputFolder(Path(out), force=force)
    folder.check()
    clear_citations()
    paper = is_paper_case(case.citation) if paper is None else paper
    # FE verification and the paper's rig: still in their children
    evaluation = evaluate_case(case, method=method, progress=step, wait=False, rig_prediction=paper)
    evaluation.timings = {**before, **evaluation.timings}
    rig = evaluation.rig
    with folder:
        step("figures")
        figure_start = time.perf_counter()
        figure_folder = folder.path / "figures"
        figure_folder.mkdir()
        import matplotlib.pyplot  # noqa: F401, PLC0415  (once, before the fork: both processes draw with it)

        counter = forked.SharedCounter()  # both processes take the next figure from it
        second = forked.start("figures and results file", _second_process_work, evaluation, folder.path, counter)
        try:
            missing = _draw_shared_figures(evaluation, figure_folder, counter)
            evaluation.timings["figures"] = time.perf_counter() - figure_start
            if evaluation.pending:
                step("FE verification")
                finish_evaluation(evaluation)
            figure_start = time.perf_counter()
            missing.update(write_figures(evaluation, figure_folder, FE_FIGURES))
            missing.update(second.result())
        finally:
            second.cancel()
        evaluation.timings["figures"] += time.perf_counter() - figure_start
        evaluation.background_timings["figures and results file"] = second.seconds
        step("files")
        write_start = time.perf_counter()
        missing = {name: missing[name] for name in FIGURES if name in missing}
        figures = [name for name in FIGURES  # a picture with nothing to draw (no [drivetrain]) is neither
                   if name not in missing and (figure_folder / f"{name}.png").is_file()]
        pngs = {name: (figure_folder / f"{name}.png").read_bytes() for name in figures}
        verdicts = paper_verdicts(evaluation) + rig_verdicts(rig) if paper else []
        results = key_results(evaluation)
        messages = [text for model, response in evaluation.responses.items()
                    for text in model_messages(response, model)]
        citations = citations_used()
        page = render_report(evaluation, version=__version__, toml_text=case_toml_text(case.source, case.document), pngs=pngs,
                             missing_figures=missing, results=results, verdicts=verdicts, messages=messages,
                             citations=citations)
        if paper:
            page = with_rig_section(page, rig_section(rig))
            evaluation.background_timings["rig prediction"] = rig.seconds
        (folder.path / "report.html").write_text(page, encoding="utf-8")
        evaluation.timings["files"] = time.perf_counter() - write_start  # summary.json, written last, is ~1 ms
        document = summary_document(evaluation, verdicts, results, messages, figures, missing, citations)
        drivetrain = drivetrain_json(evaluation.drivetrain, evaluation.problems.get("drivetrain"))
        if drivetrain is not None:
            document["drivetrain"] = drivetrain
        write_summary_json(document, folder.path / "summary.json")
    return ReportOutcome(folder=folder.target, evaluation=evaluation, verdicts=verdicts, results=results,
                         messages=messages, figures=sorted(figures), missing_figures=missing,
                         seconds=time.perf_counter() - start + sum(before.values()), timings=dict(evaluation.timings))


def _draw_shared_figures(evaluation, folder: Path, counter) -> dict[str, str]:
    """Draw and save the figures of :data:`~thermogear.report.figures.SHARED_FIGURES` this process takes from
    ``counter`` (the other process takes the rest); returns the missing ones with their reasons."""
    from thermogear.report.figures import SHARED_FIGURES, write_figures

    missing: dict[str, str] = {}
    while (index := counter.take()) < len(SHARED_FIGURES):
        missing.update(write_figures(evaluation, folder, [SHARED_FIGURES[index]]))
    return missing


def _second_process_work(evaluation, folder: Path, counter) -> dict[str, str]:
    """What the second process does while the first draws figures: results.nc, then the figures it takes from
    ``counter``. Returns the missing figures with their reasons."""
    from thermogear.report.results_file import write_results_netcdf

    write_results_netcdf(evaluation, folder / "results.nc")
    return _draw_shared_figures(evaluation, folder / "figures", counter)
