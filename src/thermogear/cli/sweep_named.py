"""`thermogear sweep CASE --kind NAME`: a kind of study that is named rather than picked from the case (the warm-ups
of a gearbox case over a grid of keys: ``--kind warmup``), run through the study registry
(:data:`thermogear.sweep.api.STUDY_KINDS`) and summarised."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from thermogear.cli.app import console, print_json
from thermogear.cli.sweep_summary import load_held_line, load_held_summary


def run_named_sweep(chosen, study, out: Path, options: dict, progress, as_json: bool) -> None:
    """Run ``study`` as the kind ``chosen`` (a :class:`~thermogear.sweep.api.StudyKind`) into ``out`` and print
    what was computed: the points, how many hold a result and why the others do not."""
    start = time.perf_counter()
    data = chosen.run(study, out, {**options, "progress": progress})
    elapsed = time.perf_counter() - start
    status = np.asarray(data["status"].values).astype(str).ravel() if "status" in data else np.array([], dtype=str)
    failed = sorted({text for text in status if text != "computed"})
    summary = {"out": str(out), "kind": chosen.name, "dims": {name: int(size) for name, size in
                                                               zip(study.dims, study.shape)},
               "models": list(study.models), "points": study.size, **load_held_summary(study), "seconds": elapsed,
               "computed_points": int(np.sum(status == "computed")), "not_computed": failed[:20]}
    if as_json:
        print_json(summary)
        return
    console.print(f"{chosen.name} study written to {summary['out']}: {summary['points']} points "
                  f"({', '.join(f'{name} {size}' for name, size in summary['dims'].items())}), "
                  f"{summary['computed_points']} computed, in {elapsed:.1f} s ({', '.join(study.models)} mesh)")
    console.print(load_held_line(summary), highlight=False)
    for text in failed:
        console.print(f"  {text}", highlight=False)
