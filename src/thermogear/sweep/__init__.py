"""Parameter studies at scale: grids over speed, load, temperature and geometry, run on Dask into zarr.

``Study.define(case, {"speed_rpm": "500:12000:240"})`` defines the grid, :func:`run_study` computes it (local
cluster, a scheduler address, or serially) into a resumable zarr store, :mod:`thermogear.sweep.plots` draws it.
A case with the nonlinear mesh is studied by :func:`branch_study` (the solution branches up and down in speed, one
pair per combination of the other parameters; optionally every stable orbit a multi-start search finds),
:func:`hysteresis_bands` and :func:`plot_branches`. The module itself is callable: ``thermogear.sweep(case,
vary={...}, out="study.zarr", scheduler=...)`` runs any kind of study and returns the store's dataset
(:func:`thermogear.sweep.api.study`). See docs/sweeps.md.
"""

import sys as _sys
import types as _types

from thermogear.sweep.branch_plots import plot_branches
from thermogear.sweep.branches import branch_study, write_branch_store
from thermogear.sweep.engine import StudyRun, run_study
from thermogear.sweep.hysteresis import hysteresis_bands
from thermogear.sweep.store import ResultStore, open_result
from thermogear.sweep.study import ALIASES, Parameter, Study, load_study_case, parse_values

__all__ = ["ALIASES", "Parameter", "ResultStore", "Study", "StudyRun", "branch_study", "hysteresis_bands",
           "load_study_case", "open_result", "parse_values", "plot_branches", "run_study", "write_branch_store"]


class _CallableModule(_types.ModuleType):
    """``thermogear.sweep(case, vary=..., out=...)``: the module called runs a study (:func:`~thermogear.sweep.api.
    study`)."""

    def __call__(self, *arguments, **options):
        """:func:`thermogear.sweep.api.study` (``case, vary, out, **options``), to which the call is forwarded."""
        from thermogear.sweep.api import study

        return study(*arguments, **options)


_sys.modules[__name__].__class__ = _CallableModule
