"""The schedulers of a study resolved once by name (issue 33): what each declares, and the worker counts it takes."""

from __future__ import annotations

import os

import pytest

from thermogear.errors import CaseError
from thermogear.sweep.schedulers import PROCESSES, SCHEDULERS, SERIAL, THREADS, Placement, check_dashboard, scheduler


def test_a_name_resolves_to_its_entry_an_empty_or_local_name_to_the_default_and_anything_else_to_an_address():
    assert scheduler("serial") is SERIAL and scheduler("threads") is THREADS and scheduler("processes") is PROCESSES
    for name in (None, "", "local"):
        assert scheduler(name, default=PROCESSES) is PROCESSES
    assert scheduler(THREADS, default=PROCESSES) is THREADS  # resolved once, passed on as it is
    remote = scheduler("tcp://10.0.0.1:8786")
    assert remote.placement is Placement.REMOTE and remote.name == "tcp://10.0.0.1:8786" and not remote.in_this_process
    assert set(SCHEDULERS) == {"serial", "threads", "processes"}


def test_each_scheduler_declares_exactly_one_place_where_its_tasks_run():
    # one placement each (an enumeration: exactly one by construction), every placement used once
    places = [kind.placement for kind in (*SCHEDULERS.values(), scheduler("tcp://host:1"))]
    assert sorted(place.name for place in places) == sorted(place.name for place in Placement)
    assert SERIAL.in_this_process and THREADS.in_this_process and not PROCESSES.in_this_process
    assert [kind.name for kind in SCHEDULERS.values() if kind.serves_dashboard] == ["processes"]


def test_worker_counts_each_scheduler_takes_and_refuses():
    cores = os.cpu_count() or 1
    assert SERIAL.worker_count(None) == SERIAL.worker_count(1) == 1
    assert THREADS.worker_count(None) == PROCESSES.worker_count(None) == cores
    assert THREADS.worker_count(3) == PROCESSES.worker_count(3) == 3
    assert scheduler("tcp://host:1").worker_count(None) is None  # the remote scheduler's own workers
    with pytest.raises(CaseError, match="--workers"):
        SERIAL.worker_count(2)
    with pytest.raises(CaseError, match="--workers"):
        scheduler("tcp://host:1").worker_count(2)


def test_a_dashboard_is_refused_where_no_local_cluster_serves_it():
    check_dashboard(PROCESSES, ":0")
    for kind in (SERIAL, THREADS, scheduler("tcp://host:1")):
        check_dashboard(kind, None)
        with pytest.raises(CaseError, match="--dashboard") as caught:
            check_dashboard(kind, ":0")
        assert kind.name in str(caught.value)
