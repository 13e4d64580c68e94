"""What is left of a study whose tasks form chains (a branch followed point by point, each point from its
neighbour's state) after some finished: the unfinished tasks, each chain continued from its first unfinished task,
started from the state its last finished task stored. Independent tasks are chains of one."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["pending_chains"]


def pending_chains(tasks: Sequence[tuple], follows: Sequence[int | None], done: set[int],
                   stored_state: Callable[[int], Any]) -> tuple[list[tuple[int, tuple]], list[int | None]]:
    """The tasks still to compute as ``(number, task)`` and whom each follows (an index into that list, or None).

    ``follows[i]``: the task (< i) task i continues from. A chain's finished tasks are skipped; its first unfinished
    task, where it has a finished predecessor, gets ``stored_state(predecessor)`` appended to its tuple (the state
    the predecessor carried, read back from the store), so the chain goes on exactly as if uninterrupted; the first
    task of a chain gets None appended."""
    chains: list[list[int]] = []
    chain_of: dict[int, int] = {}
    for number, follow in enumerate(follows):
        if follow is None:
            chain_of[number] = len(chains)
            chains.append([number])
        else:
            chain_of[number] = chain_of[follow]
            chains[chain_of[follow]].append(number)
    pending: list[tuple[int, tuple]] = []
    pending_follows: list[int | None] = []
    for chain in chains:
        first = next((position for position, number in enumerate(chain) if number not in done), None)
        if first is None:
            continue
        stored = stored_state(chain[first - 1]) if first > 0 else None
        for position in range(first, len(chain)):
            number = chain[position]
            pending_follows.append(None if position == first else len(pending) - 1)
            pending.append((number, tuple(tasks[number]) + ((stored,) if position == first else ())))
    return pending, pending_follows
