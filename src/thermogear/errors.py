"""Errors and warnings of thermogear.

Every error about user input names the key, the value, the allowed range and the reason, so that a
gear engineer can fix the case file without reading the source.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class ThermogearError(Exception):
    """Base class of every error thermogear raises on purpose."""


class InputError(ThermogearError, ValueError):
    """An input refused: the message names it, shows the value given, the allowed range or set in words and the
    reason (the physics or the model limit behind it). The base of :class:`CaseError` and :class:`ProblemError`,
    which say what the name is; ``prefix`` opens the message."""

    prefix = ""

    def __init__(self, name: str, value: object, allowed: str, reason: str) -> None:
        self.value = value
        self.allowed = allowed
        self.reason = reason
        super().__init__(f"{self.prefix}{name} = {shown_value(value)}: allowed {allowed}; {reason}")


class CaseError(InputError):
    """A case (file or API input) that is invalid or outside what the model supports.

    Parameters
    ----------
    key:
        Dotted key of the offending input, as written in a case file (``"pinion.teeth"``).
    value:
        The value that was given.
    allowed:
        The allowed range or set, in words (``"> 1"``, ``"[0, 0.8]"``).
    reason:
        Why the value is refused (the physics or the model limit behind it).
    """

    def __init__(self, key: str, value: object, allowed: str, reason: str) -> None:
        self.key = key
        super().__init__(key, value, allowed, reason)


#: Longest representation of a value an error message shows [characters]: a 5000-character path or a whole
#: table is cut, saying how long it was.
SHOWN_VALUE_LENGTH = 160


def shown_value(value: object) -> str:
    """``repr(value)``, cut to :data:`SHOWN_VALUE_LENGTH` characters with its full length said."""
    text = repr(value)
    if len(text) <= SHOWN_VALUE_LENGTH:
        return text
    return f"{text[:SHOWN_VALUE_LENGTH - 40]}… ({len(text)} characters)"


class JammingError(CaseError):
    """A case whose gears jam: the thermal expansion closes the backlash at its operating temperatures. A study
    marks such points (``jammed``) and computes the others instead of refusing the whole grid."""


class ProblemError(InputError):
    """An invalid input to a solver: the arrays a mesh model hands over, or what a user passes to a solver
    directly. It names the solver's quantity (``"nodes"``, ``"stiffness"``), not a case-file key: a solver
    knows nothing of gears or case files.
    """

    prefix = "solver input "

    def __init__(self, quantity: str, value: object, allowed: str, reason: str) -> None:
        self.quantity = quantity
        super().__init__(quantity, value, allowed, reason)


class ModelLimitError(ThermogearError, RuntimeError):
    """The model cannot give a valid answer at this operating point (e.g. parametric instability)."""


class ExtrapolationWarning(UserWarning):
    """An empirical fit or formula is used outside the range of the data it was fitted to."""


class ModelAssumptionWarning(UserWarning):
    """The result rests on an assumption that the user should know about."""


class IneffectiveKeyWarning(UserWarning):
    """A case sets keys that have no effect under the model it chooses (they belong to another model)."""


def closest_key(key: str, valid: Iterable[str]) -> str | None:
    """Closest valid key to a misspelt one, or None when nothing is close."""
    matches = difflib.get_close_matches(key, list(valid), n=1, cutoff=0.5)
    return matches[0] if matches else None
