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


def _take_until(counter, limit):
    taken = []
    while (number := counter.take()) < limit:
        taken.append(number)
    return taken


def test_a_shared_counter_hands_each_number_to_one_process_only(mode):
    """The report's two processes take their figures from one counter: every job is taken once, by one of them
    (forked: the child and the parent take turns on the shared value; serial: the inline child takes them all)."""
    counter = forked.SharedCounter()
    child = forked.start("taker", _take_until, counter, 200)
    mine = _take_until(counter, 200)
    theirs = child.result()
    assert sorted(mine + theirs) == list(range(200))
    if mode == "serial" or not forked._can_fork():
        assert mine == []  # the inline child ran to the end before the caller took any


def test_the_shared_and_the_fe_figures_are_every_figure_once():
    """Each report figure is drawn by exactly one of the two ways build_report draws them (no figure lost or
    drawn twice when the figures are shared between processes)."""
    from thermogear.report.figures import FE_FIGURES, FIGURES, SHARED_FIGURES

    drawn = [*SHARED_FIGURES, *FE_FIGURES]
    assert sorted(drawn) == sorted(FIGURES) and len(set(drawn)) == len(drawn)


def test_a_counter_that_cannot_be_shared_leaves_every_job_to_its_maker(monkeypatch):
    """Without shared memory or semaphores (some containers) the counter is not shared: the process that made it
    takes every job and a forked child none, so no job is done twice (two processes writing one figure file)."""
    import multiprocessing

    def no_shared_memory(self, *args, **options):
        raise OSError(38, "Function not implemented")

    monkeypatch.setattr(type(multiprocessing.get_context("fork")), "Value", no_shared_memory)
    monkeypatch.delenv("THERMOGEAR_SERIAL", raising=False)
    counter = forked.SharedCounter()
    child = forked.start("taker", _take_until, counter, 50)
    assert _take_until(counter, 50) + child.result() == list(range(50))
    if forked._can_fork():
        assert child.result() == []  # the forked child was told there was nothing left
