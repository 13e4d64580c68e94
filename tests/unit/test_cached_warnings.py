"""Per-case caching never swallows a warning the second time: cached components record their warnings and raise
them again on every later call (issue 12)."""

from __future__ import annotations

import warnings

import pytest

from thermogear.case import cached_per_case, load_case
from thermogear.errors import ExtrapolationWarning


def test_a_cached_function_raises_its_warning_on_every_call():
    calls = []

    @cached_per_case
    def derived(case):
        calls.append(case)
        warnings.warn("the fit is extrapolated", ExtrapolationWarning)
        return 42

    case = load_case("luo2019")
    for _ in range(3):
        with pytest.warns(ExtrapolationWarning, match="extrapolated"):
            assert derived(case) == 42
    assert len(calls) == 1  # computed once, warned three times


def test_the_stiffness_table_warns_again_from_its_cache():
    # a thin-rimmed, small pinion puts the Sainsot fillet-foundation fit outside its data; the cached PEM table
    # must say so every time it is used, not only the first
    from thermogear.stiffness.table import clear_cache, pair_stiffness_at

    case = load_case("fzg_type_c")
    clear_cache()
    pair = case.gear_pair
    rolls = pair.path_points["C"]
    for _ in range(2):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            pair_stiffness_at(pair, case.material, rolls)
        assert any(issubclass(item.category, ExtrapolationWarning) for item in caught)
