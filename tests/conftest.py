"""Shared fixtures."""

from __future__ import annotations

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(scope="session")
def luo2019():
    from thermogear import load_case

    return load_case("luo2019")


@pytest.fixture(scope="session")
def fzg_type_c():
    from thermogear import load_case

    return load_case("fzg_type_c")
