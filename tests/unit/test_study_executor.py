"""The one executor of the studies (issue 34): tasks and chains of tasks, serial and on Dask's threads, results
handed back in the calling thread; options it cannot act on refused."""

from __future__ import annotations

import threading

import pytest

from thermogear.errors import CaseError
from thermogear.sweep.executor import check_scheduler_address, execute


def _step(shared: int, task: int, *previous: tuple) -> tuple:
    """A task: its own value plus the running total of the task it follows (a branch carrying its state)."""
    carried = previous[0][1] if previous else 0
    return task, carried + task * shared, threading.get_ident()


@pytest.mark.parametrize("scheduler, workers", [("serial", None), ("threads", 2), ("threads", 1)])
def test_chains_carry_their_state_and_results_come_back_in_the_calling_thread(scheduler, workers):
    results: dict[int, tuple] = {}
    caller = threading.get_ident()
    handed: list[int] = []

    def on_result(index: int, result: tuple) -> None:
        handed.append(threading.get_ident())
        results[index] = result

    # two chains (0 → 1 → 2 and 3 → 4) and one task alone (5)
    execute(_step, 10, [1, 2, 3, 4, 5, 6], on_result, scheduler, workers, follows=[None, 0, 1, None, 3, None])
    assert {index: total for index, (_, total, _) in results.items()} == {0: 10, 1: 30, 2: 60, 3: 40, 4: 90, 5: 60}
    assert set(handed) == {caller}


def test_a_task_can_only_follow_an_earlier_one():
    with pytest.raises(ValueError):
        execute(_step, 1, [1, 2], lambda index, result: None, "serial", follows=[1, None])


def test_options_a_scheduler_cannot_act_on_are_refused():
    with pytest.raises(CaseError, match="--workers"):
        execute(_step, 1, [1], lambda index, result: None, "serial", workers=2)
    with pytest.raises(CaseError, match="no scheduler answers"):
        check_scheduler_address("tcp://127.0.0.1:1", timeout=2.0)


def _settings(names: tuple[str, ...]) -> list:
    import dask

    return [dask.config.get(name) for name in names]


def test_a_study_s_local_cluster_runs_dask_s_background_work_less_often_in_every_process_and_only_there():
    """Without a dashboard, the quiet settings reach the worker processes (their nannies hand over the settings
    of their creation) and the scheduler in this process, and the settings of this process are back afterwards."""
    import dask
    import distributed  # noqa: F401  (its settings join Dask's on import)

    from thermogear.sweep.executor import QUIET_LOCAL_CLUSTER, _client

    names = tuple(QUIET_LOCAL_CLUSTER)
    before = _settings(names)
    assert before != list(QUIET_LOCAL_CLUSTER.values())  # Dask's defaults differ, else the test shows nothing
    with _client("processes", 1, None) as client:
        assert list(client.run(_settings, names).values()) == [list(QUIET_LOCAL_CLUSTER.values())]
        scheduler = client.cluster.scheduler
        assert scheduler.periodic_callbacks["monitor"].callback_time == 5000  # [ms]
        assert scheduler.periodic_callbacks["tick"].callback_time == 1000  # [ms]
    assert _settings(names) == before
    assert dask.config.get("distributed.worker.profile.enabled") is True
