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

#: Public name -> the module that defines it, imported when first asked for (PEP 562): a worker process that
#: unpickles one task function (e.g. the gearbox grid's block) imports that module alone, not every study kind.
_PUBLIC = {"plot_branches": "branch_plots", "branch_study": "branches", "write_branch_store": "branches",
           "StudyRun": "engine", "run_study": "engine", "hysteresis_bands": "hysteresis", "ResultStore": "store",
           "open_result": "store", "ALIASES": "study", "Parameter": "study", "Study": "study",
           "load_study_case": "study", "parse_values": "study"}

__all__ = sorted(_PUBLIC)


def __getattr__(name: str):
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import importlib

    return getattr(importlib.import_module(f"{__name__}.{_PUBLIC[name]}"), name)


class _CallableModule(_types.ModuleType):
    """``thermogear.sweep(case, vary=..., out=...)``: the module called runs a study (:func:`~thermogear.sweep.api.
    study`)."""

    def __call__(self, *arguments, **options):
        """:func:`thermogear.sweep.api.study` (``case, vary, out, **options``), to which the call is forwarded."""
        from thermogear.sweep.api import study

        return study(*arguments, **options)


_sys.modules[__name__].__class__ = _CallableModule
