"""The pieces of a case a plug-in receives: its checks and providers name what they read, the case hands it over.

The load-time checks, the temperature and X_te providers and the drivetrain's heat provider of
:mod:`thermogear.composition` (and those a user registers) used to receive the whole :class:`~thermogear.case.Case`
and each picked its sections out of it. Now a plug-in's parameters name the pieces it reads, and
:func:`call_with_pieces` resolves each from the case (the dataflow style of Hamilton's functions or pytest's
fixtures: a parameter's name is the input it asks for):

* a part of the case as loaded: a field of the Case (``gear_pair``, ``operating_point``, ``material``, a section:
  ``gearbox``, ``drivetrain``, ``temperature``, ``damping``, ...) or one of its properties (``directory``,
  ``normal_load``, ``equivalent_mass``);
* a derived piece, resolved once per case by its resolver named in
  :data:`thermogear.composition.CASE_PIECES` (``oil``: the lubricant model; ``gearbox_model``: the gearbox thermal
  network, None for a case without ``[gearbox]``; ``fem_inputs``: the finite-element model's inputs);
* a provided piece, the answer of the plug-in a section chooses by name (:data:`thermogear.composition.CHOSEN_PIECES`:
  ``provided_temperature_field``, the tooth temperatures of the ``[temperature] model``'s provider;
  ``provided_x_te``, the X_te of the ``[thermal] x_te_source``'s provider), the plug-in called with its own pieces;
* any of these asked for later: a parameter named ``<piece>_of`` receives a function of no arguments that resolves
  ``<piece>`` when it is called (``temperature_field_of``: a resolver that needs the field only on some paths
  neither computes it nor raises its warnings on the others);
* ``case``: the whole case, for a plug-in that resolves the case itself (a resolver that writes a new case; and a
  provider written as ``provider(case)`` before the pieces).

So a check or provider states its inputs in its signature, is tested with those inputs alone, and the case is read
in one place. This module imports nothing of thermogear but :mod:`thermogear.composition` (which imports none), so
every layer may read it.
"""

from __future__ import annotations

import dataclasses
import functools
import inspect
from collections.abc import Callable
from typing import Any

from thermogear.composition import CASE_PIECES, CHOSEN_PIECES, resolve

__all__ = ["LATER", "WHOLE_CASE", "call_with_pieces", "piece_names"]

#: The name under which a plug-in asks for the whole case (module docstring).
WHOLE_CASE = "case"
#: The ending of a parameter that asks for a piece later (module docstring): ``temperature_field_of``.
LATER = "_of"


@functools.lru_cache(maxsize=None)
def piece_names(function: Callable) -> tuple[str, ...]:
    """The pieces ``function`` asks for: the names of its parameters, each passed by keyword (TypeError for
    ``*args``/``**kwargs``, which name no piece)."""
    names = []
    for parameter in inspect.signature(function, follow_wrapped=False).parameters.values():
        if parameter.kind in (parameter.VAR_POSITIONAL, parameter.VAR_KEYWORD, parameter.POSITIONAL_ONLY):
            raise TypeError(f"{getattr(function, '__qualname__', function)!s}: parameter '{parameter.name}' names no "
                            "piece of a case (a check or provider takes the pieces it reads by name)")
        names.append(parameter.name)
    return tuple(names)


@functools.lru_cache(maxsize=None)
def _case_parts(kind: type) -> frozenset[str]:
    """The names of the parts of a case as loaded (a ``kind`` of case): its fields and properties."""
    fields = {field.name for field in dataclasses.fields(kind)} if dataclasses.is_dataclass(kind) else set()
    return frozenset(fields | {name for name, value in vars(kind).items() if isinstance(value, property)})


def call_with_pieces(function: Callable, case: Any) -> Any:
    """``function`` called with the pieces of ``case`` its parameters name (module docstring); TypeError naming the
    allowed pieces for a parameter that names none."""
    arguments = {}
    for name in piece_names(function):
        later = name.endswith(LATER) and _is_piece(name[:-len(LATER)], type(case))
        piece = name[:-len(LATER)] if later else name
        if name == WHOLE_CASE:
            arguments[name] = case
        elif later:  # resolved when asked for: the same call, for a function that names this piece alone
            arguments[name] = functools.partial(call_with_pieces, _asking_for(piece), case)
        elif piece in CASE_PIECES:
            target, requires = CASE_PIECES[piece]
            resolver = resolve(target)
            if resolver is None:
                raise TypeError(f"the piece '{piece}' of a case is resolved by {target}, which is not installed")
            absent = requires is not None and getattr(case, requires) is None
            arguments[name] = None if absent else call_with_pieces(resolver, case)
        elif piece in CHOSEN_PIECES:
            chooser = resolve(CHOSEN_PIECES[piece])
            if chooser is None:
                raise TypeError(f"the piece '{piece}' of a case is chosen by {CHOSEN_PIECES[piece]}, which is not "
                                "installed")
            arguments[name] = call_with_pieces(call_with_pieces(chooser, case), case)  # the plug-in, its pieces
        elif piece in _case_parts(type(case)):
            arguments[name] = getattr(case, piece)
        else:
            allowed = sorted(_case_parts(type(case)) | set(CASE_PIECES) | set(CHOSEN_PIECES) | {WHOLE_CASE})
            raise TypeError(f"{getattr(function, '__qualname__', function)!s}: '{name}' is not a piece of a case "
                            f"(allowed: {', '.join(allowed)}; each also as '<piece>{LATER}', to ask for it later)")
    return function(**arguments)


def _is_piece(name: str, kind: type) -> bool:
    """True where ``name`` is a piece of a case of ``kind`` (module docstring), the whole case aside."""
    return name in CASE_PIECES or name in CHOSEN_PIECES or name in _case_parts(kind)


@functools.lru_cache(maxsize=None)
def _asking_for(piece: str) -> Callable:
    """A function whose one parameter names ``piece`` and which returns it: what a ``<piece>_of`` parameter calls."""
    def asking(**pieces: Any) -> Any:
        return pieces[piece]

    asking.__signature__ = inspect.Signature([inspect.Parameter(piece, inspect.Parameter.KEYWORD_ONLY)])
    asking.__qualname__ = f"asking for {piece}"
    return asking
