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

import sys
import threading
import warnings
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["ignored", "kept", "raise_again", "recorded", "routed"]

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


def kept(caught: list[warnings.WarningMessage]) -> tuple:
    """Recorded warnings as ``(message, category, filename, lineno)`` to keep beside a cached result."""
    return tuple((item.message, item.category, item.filename, item.lineno) for item in caught)


_registries: dict[str, dict] = {}


def _registry(filename: str) -> dict:
    """The warning registry of the module that ``filename`` is (Python's per-module "already shown" record)."""
    registry = _registries.get(filename)
    if registry is None:
        module = next((item for item in list(sys.modules.values())
                       if getattr(item, "__file__", None) == filename), None)
        registry = module.__dict__.setdefault("__warningregistry__", {}) if module is not None else {}
        _registries[filename] = registry
    return registry


#: Filter contexts seen by :func:`raise_again`, newest last: id → (the filter list, its contents, causes raised).
_raised: dict[int, tuple[list, tuple, set]] = {}
_RAISED_CONTEXTS = 32


def _raised_in_context() -> set:
    """The warnings already raised again under the current filter context. A context is the list object
    ``warnings.filters`` with its contents: every ``catch_warnings`` block (a test's, a recording scope's) has its
    own copy, and changing the filters in place starts afresh. The lists are kept referenced, so an id is never
    reused for another context while it is remembered."""
    context = warnings.filters
    contents = tuple(context)
    entry = _raised.get(id(context))
    if entry is None or entry[0] is not context or entry[1] != contents:
        entry = _raised[id(context)] = (context, contents, set())
        while len(_raised) > _RAISED_CONTEXTS:
            _raised.pop(next(iter(_raised)))
    return entry[2]


def raise_again(recorded: tuple) -> None:
    """Raise warnings kept with a cached result (:func:`kept`) again, attributed to where they were first raised
    (same file, line and module registry), each once per filter context: one call through the API that asks
    several cached components (two models, two stiffness tables of one gear) shows each cause once, while every
    new ``catch_warnings`` block (a recording scope, a test) receives them again."""
    raised = set() if _routing else _raised_in_context()  # under a router each thread's scope gets every one
    for message, category, filename, lineno in recorded:
        cause = (str(message), category)
        if cause in raised:
            continue
        raised.add(cause)
        warnings.warn_explicit(message, category, filename, lineno, registry=_registry(filename))


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
