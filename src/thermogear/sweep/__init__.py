"""Parameter studies at scale: grids over speed, load, temperature and geometry, run on Dask into zarr.

``Study.define(case, {"speed_rpm": "500:12000:240"})`` defines the grid, :func:`run_study` computes it (local
cluster, a scheduler address, or serially) into a resumable zarr store, :mod:`thermogear.sweep.plots` draws it.
See docs/sweeps.md.
"""

from thermogear.sweep.engine import StudyRun, run_study
from thermogear.sweep.store import ResultStore, open_result
from thermogear.sweep.study import ALIASES, Parameter, Study, load_study_case, parse_values

__all__ = ["ALIASES", "Parameter", "ResultStore", "Study", "StudyRun", "load_study_case", "open_result",
           "parse_values", "run_study"]
