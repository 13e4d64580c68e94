"""Shared fixtures."""

from __future__ import annotations

import os

import matplotlib
import pytest

matplotlib.use("Agg")

_BLAS_THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def pytest_configure(config):
    """A pytest-xdist worker (one per core) computes on one BLAS thread, as the study engine's workers do: with a
    worker on every core, more BLAS threads only contend for the cores (the small matrices of the drivetrain tests
    ran several times slower multi-threaded on a busy machine). The variables reach the commands and Dask workers
    the tests start; threadpoolctl limits the BLAS libraries already loaded. A thread count the user set wins."""
    if not os.environ.get("PYTEST_XDIST_WORKER") or any(name in os.environ for name in _BLAS_THREAD_VARIABLES):
        return
    for name in _BLAS_THREAD_VARIABLES:
        os.environ[name] = "1"
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=1, user_api="blas")


@pytest.fixture(scope="session")
def luo2019():
    from thermogear import load_case

    return load_case("luo2019")


@pytest.fixture(scope="session")
def fzg_type_c():
    from thermogear import load_case

    return load_case("fzg_type_c")


def mesh_stiffness_of(pair, material, speed_rpm: float, count: int):
    """(grid, per-pair k (slots, n), k(τ)) of a bare gear pair (no case) from the primitives the mesh model uses:
    for the stiffness tests of pairs that exist only as GearPair objects."""
    import numpy as np

    from thermogear.geometry.mesh_cycle import MeshCycle
    from thermogear.stiffness.table import pair_stiffness_at

    grid = MeshCycle(pair, speed_rpm).grid(count)
    per_pair = np.zeros(grid.roll.shape)
    end = pair.path_points["E"]
    per_pair[grid.in_contact] = pair_stiffness_at(pair, material, np.minimum(grid.roll[grid.in_contact], end))
    return grid, per_pair, MeshCycle.total(per_pair, grid.in_contact)


@pytest.fixture(scope="session")
def mesh_stiffness():
    return mesh_stiffness_of


def load_script(path, name: str | None = None):
    """A script outside the package (a benchmark, docs/generate.py, an example) imported as a module by its path."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(name or path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def script_module():
    """:func:`load_script`, for tests that drive a benchmark's or the docs' own functions."""
    return load_script

