"""Warning scopes: plain ``catch_warnings`` blocks without a router; per-thread records under one."""

from __future__ import annotations

import threading
import warnings

from thermogear import warning_scope


class FirstWarning(UserWarning):
    pass


class SecondWarning(UserWarning):
    pass


def _state():
    return warnings.showwarning, list(warnings.filters)


def test_without_a_router_the_scopes_are_catch_warnings_blocks():
    before = _state()
    with warning_scope.recorded() as outer:
        warnings.warn("kept", FirstWarning)
        with warning_scope.ignored(SecondWarning):
            warnings.warn("dropped", SecondWarning)
            warnings.warn("kept too", FirstWarning)
        with warning_scope.recorded() as inner:
            warnings.warn("inner", SecondWarning)
    assert [str(item.message) for item in outer] == ["kept", "kept too"]
    assert [str(item.message) for item in inner] == ["inner"]
    assert _state() == before


def _raise_in_threads(count: int, rounds: int):
    """Each thread records its own warnings in a scope while the others do the same, in lock step."""
    barrier = threading.Barrier(count)
    records: dict[int, list[str]] = {}

    def work(number: int) -> None:
        with warning_scope.recorded() as caught:
            for step in range(rounds):
                barrier.wait()  # every thread is inside its scope at once
                warnings.warn(f"thread {number} step {step}", FirstWarning)
                with warning_scope.ignored(SecondWarning):
                    warnings.warn(f"silenced {number}", SecondWarning)
        warnings.warn(f"outside {number}", FirstWarning)
        records[number] = [str(item.message) for item in caught]

    threads = [threading.Thread(target=work, args=(number,)) for number in range(count)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return records


def test_router_keeps_each_threads_warnings_in_its_own_scope():
    before = _state()
    with warning_scope.routed() as unscoped:
        records = _raise_in_threads(count=4, rounds=25)
    for number, messages in records.items():
        assert messages == [f"thread {number} step {step}" for step in range(25)]
    assert sorted(str(item.message) for item in unscoped) == [f"outside {number}" for number in range(4)]
    assert _state() == before  # nothing installed by the run outlives it
    with warning_scope.recorded() as after:  # and the plain blocks work again
        warnings.warn("after", FirstWarning)
    assert [str(item.message) for item in after] == ["after"]
