"""thermogear.forked: a function run in a forked child (or inline where fork is unavailable) gives the same
result, failure and warnings as a call in the caller."""

from __future__ import annotations

import os
import warnings

import numpy as np
import pytest

from thermogear import forked


def _square_sum(values):
    warnings.warn("from the child", UserWarning)
    return {"sum": float(np.sum(np.asarray(values) ** 2)), "pid": os.getpid()}


def _fails():
    raise ValueError("no such thing")


@pytest.fixture(params=["fork", "serial"])
def mode(request, monkeypatch):
    if request.param == "serial":
        monkeypatch.setenv("THERMOGEAR_SERIAL", "1")
    else:
        monkeypatch.delenv("THERMOGEAR_SERIAL", raising=False)
    return request.param


def test_result_warnings_and_process(mode):
    background = forked.start("squares", _square_sum, [1.0, 2.0, 3.0])
    with pytest.warns(UserWarning, match="from the child"):
        result = background.result()
    assert result["sum"] == 14.0
    # forked where Linux offers fork, else (or with THERMOGEAR_SERIAL) in this process
    assert (result["pid"] != os.getpid()) == (mode == "fork" and forked._can_fork())
    assert background.seconds >= 0.0
    assert background.result()["sum"] == 14.0  # asked again: the same answer, no second wait


def test_a_failure_keeps_its_type_and_message(mode):
    background = forked.start("fails", _fails)
    with pytest.raises(forked.ChildFailed, match="^ValueError: no such thing$"):
        background.result()
