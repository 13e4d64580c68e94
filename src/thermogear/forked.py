"""Run one function in a forked child process while the caller goes on, and collect its result later.

The report runs independent stages side by side on a second core this way (the FE verification while the
dynamics run; the netCDF file while the figures are drawn). A forked child inherits the parent's memory, so the
function's arguments are not pickled; only its result travels back (through a pipe, pickled).

Where ``fork`` is not available or not safe (Windows, macOS, where the default start method is ``spawn``) or when
the environment variable ``THERMOGEAR_SERIAL`` is set, :func:`start` runs the function at once in the caller:
same results, one core.
"""

from __future__ import annotations

import os
import sys
import time
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable

__all__ = ["NO_MORE", "Background", "ChildFailed", "SharedCounter", "start"]


class ChildFailed(RuntimeError):
    """The function raised in the child: its exception type and message (the traceback stays in the child)."""


def _can_fork() -> bool:
    return sys.platform.startswith("linux") and hasattr(os, "fork") and not os.environ.get("THERMOGEAR_SERIAL")


def _run(function: Callable, args: tuple) -> tuple:
    """("ok", value, warnings, seconds) or ("error", "Type: message", warnings, seconds)."""
    begin = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            value = function(*args)
            outcome = ("ok", value)
        except (KeyboardInterrupt, SystemExit):
            raise
        except Exception as error:  # noqa: BLE001 - handed to the parent, which reports it
            outcome = ("error", f"{type(error).__name__}: {error}")
    messages = [(str(item.message), item.category) for item in caught]
    return (*outcome, messages, time.perf_counter() - begin)


def _child(connection, function: Callable, args: tuple) -> None:
    import signal  # noqa: PLC0415

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle; it ends its children
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # not the parent's handlers (e.g. an output folder's clean-up)
    try:
        result = _run(function, args)
        try:
            connection.send(result)
        except Exception as error:  # noqa: BLE001 - a result that cannot be pickled
            connection.send(("error", f"{type(error).__name__}: {error}", [], result[3]))
    finally:
        connection.close()


@dataclass
class Background:
    """A function running in a child process (or already run in the caller): :meth:`result` waits for it."""

    name: str
    _process: Any = None
    _connection: Any = None
    _outcome: tuple | None = None
    seconds: float = 0.0  #: the function's own run time [s] (in the child)
    waited: float = 0.0  #: how long :meth:`result` waited for it [s]
    warnings: list = field(default_factory=list)

    def result(self) -> Any:
        """The function's return value; re-emits its warnings here; raises :class:`ChildFailed` if it raised."""
        if self._outcome is None:
            begin = time.perf_counter()
            try:
                self._outcome = self._connection.recv()
            except EOFError:  # the child died without answering (killed, out of memory)
                self._outcome = ("error", f"ChildFailed: the {self.name} process ended without a result "
                                          f"(exit code {self._process.exitcode})", [], 0.0)
            finally:
                self._connection.close()
                self._process.join()
                self.waited = time.perf_counter() - begin
            for message, category in self._outcome[2]:
                warnings.warn(message, category, stacklevel=2)
        status, value, _, self.seconds = self._outcome
        if status == "error":
            raise ChildFailed(value)
        return value

    def cancel(self) -> None:
        """Stop the child if it still runs (an interrupted command leaves no process behind)."""
        if self._process is not None and self._process.is_alive():
            self._process.terminate()
            self._process.join()


#: What :meth:`SharedCounter.take` answers a child when the counter could not be shared: more than any job count.
NO_MORE = sys.maxsize


class SharedCounter:
    """Hands out 0, 1, 2, … once each to the calls of :meth:`take` in this process and in the children forked
    after it was made (a counter in shared memory, under a lock). Processes that take their next job from one
    share a list of jobs evenly, whatever each job costs and however busy the machine is: a process that ends a
    short job early just takes the next one. Where :func:`start` does not fork, a plain counter; where the system
    offers no shared memory or semaphores (some containers), the process that made it takes every job and its
    children none (:data:`NO_MORE`), so a job is still done once."""

    def __init__(self) -> None:
        self._shared = None
        self._next = 0
        self._owner = os.getpid()
        if _can_fork():
            import multiprocessing  # noqa: PLC0415

            try:
                self._shared = multiprocessing.get_context("fork").Value("i", 0)
            except OSError:  # no /dev/shm or no POSIX semaphores: not shared, see the class docstring
                self._shared = None

    def take(self) -> int:
        """The next number not yet taken by any of the processes (:data:`NO_MORE` for a child when the counter
        could not be shared)."""
        if self._shared is None:
            if os.getpid() != self._owner:
                return NO_MORE
            self._next += 1
            return self._next - 1
        with self._shared.get_lock():
            value = self._shared.value
            self._shared.value = value + 1
        return value


def start(name: str, function: Callable, *args) -> Background:
    """Start ``function(*args)`` in a forked child and return at once (or run it now where forking is not
    available, see the module docstring)."""
    if not _can_fork():
        return _Inline(name, _outcome=_run(function, args))  # its warnings come out with its result, as a child's
    import multiprocessing  # noqa: PLC0415

    context = multiprocessing.get_context("fork")
    receiver, sender = context.Pipe(duplex=False)
    process = context.Process(target=_child, args=(sender, function, args), name=f"thermogear-{name}", daemon=True)
    process.start()
    sender.close()
    return Background(name, process, receiver)


class _Inline(Background):
    """A :class:`Background` whose function already ran in the caller."""

    def result(self) -> Any:
        status, value, messages, self.seconds = self._outcome
        for message, category in messages:
            warnings.warn(message, category, stacklevel=2)
        self._outcome = (status, value, [], self.seconds)
        if status == "error":
            raise ChildFailed(value)
        return value

    def cancel(self) -> None:
        return None
