"""Recording and silencing warnings in a block of code, safely when several threads run thermogear at once.

``warnings.catch_warnings`` changes process-wide state (the filters and the display hook) and restores it on exit.
When two threads overlap in it, one thread's warnings land in the other's record, and the state restored last can
be a record hook that outlives both (before Python 3.14's context-aware warnings, which thermogear cannot assume).
A study run on threads (:mod:`thermogear.sweep.engine`) therefore installs one *router* for its whole duration
(:func:`routed`), in the driver thread, and the code its workers run records and silences warnings in scopes
kept per thread (:func:`recorded`, :func:`ignored`): the router hands each warning to the innermost scope of the
thread that raised it. Without a router (a script, the command line, a serial or a process run) the two scopes are
plain ``catch_warnings`` blocks, exactly as before.
"""

from __future__ import annotations

import threading
import warnings
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["ignored", "recorded", "routed"]

_local = threading.local()  # .scopes: this thread's open scopes, innermost last
_router = threading.Lock()  # held while a router is installed: one at a time
_routing = False


class _Record:
    def __init__(self) -> None:
        self.caught: list[warnings.WarningMessage] = []


class _Silence:
    def __init__(self, category: type[Warning]) -> None:
        self.category = category


def _scopes() -> list:
    scopes = getattr(_local, "scopes", None)
    if scopes is None:
        scopes = _local.scopes = []
    return scopes


@contextmanager
def recorded() -> Iterator[list[warnings.WarningMessage]]:
    """Record every warning raised in the block (none is shown); yields the list, filled when the block ends."""
    if not _routing:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            yield caught
        return
    scope = _Record()
    scopes = _scopes()
    scopes.append(scope)
    try:
        yield scope.caught
    finally:
        scopes.remove(scope)


@contextmanager
def ignored(category: type[Warning] = Warning) -> Iterator[None]:
    """Drop the warnings of ``category`` (and its subclasses) raised in the block."""
    if not _routing:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", category)
            yield
        return
    scope = _Silence(category)
    scopes = _scopes()
    scopes.append(scope)
    try:
        yield
    finally:
        scopes.remove(scope)


@contextmanager
def routed() -> Iterator[list[warnings.WarningMessage]]:
    """Install the router for the block (call it in the thread that starts and joins the workers): each warning
    goes to the innermost scope of the thread that raised it; one raised outside every scope is recorded in the
    yielded list. On exit the process's warning state is restored as ``catch_warnings`` leaves it."""
    global _routing
    with _router, warnings.catch_warnings(record=True) as unscoped:
        warnings.simplefilter("always")  # every warning reaches the router; the scopes decide

        def route(message, category, filename, lineno, file=None, line=None) -> None:
            item = warnings.WarningMessage(message, category, filename, lineno, file, line)
            for scope in reversed(getattr(_local, "scopes", ())):
                if isinstance(scope, _Record):
                    scope.caught.append(item)
                    return
                if issubclass(category, scope.category):
                    return
            unscoped.append(item)

        warnings.showwarning = route
        _routing = True
        try:
            yield unscoped
        finally:
            _routing = False
