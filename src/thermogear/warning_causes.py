"""Warnings counted once per cause.

A model warning often carries the value that triggered it ("… at a unit load of 312.4 N/mm …"): a study of 10⁵
points would then list 10⁵ versions of one warning. The *cause* of a message is its text with every number
replaced by ``#``; messages with the same cause are listed once, the first one in full with how many more of
the same cause there were. Pure text functions: no console, no I/O (the command line and the sweep engine both
use them).
"""

from __future__ import annotations

import re
from collections.abc import Iterable

__all__ = ["distinct_warnings", "warning_cause", "warning_text", "WarningTally"]

# A number as printed by Python or NumPy: sign, digits, decimal point, exponent ("-1.5e+03", "312.4", "7").
_NUMBER = re.compile(r"[-+−]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def warning_text(item) -> str:
    """A recorded warning (``warnings.WarningMessage``) as one line: ``"Category: message"``."""
    return f"{item.category.__name__}: {item.message}"


def warning_cause(message: str) -> str:
    """The cause of a warning message: the message with its numbers replaced by ``#``."""
    return _NUMBER.sub("#", message.strip())


class WarningTally:
    """Distinct messages in the order they first appeared, counted by cause (see :func:`warning_cause`)."""

    def __init__(self) -> None:
        self._first: dict[str, str] = {}
        self._count: dict[str, int] = {}
        self._seen: set[str] = set()

    def add(self, message: str) -> bool:
        """Count ``message`` (a text seen before counts nothing); True when its cause is new."""
        text = message.strip()
        if text in self._seen:
            return False
        self._seen.add(text)
        cause = warning_cause(text)
        if cause in self._first:
            self._count[cause] += 1
            return False
        self._first[cause] = text
        self._count[cause] = 1
        return True

    def update(self, messages: Iterable[str]) -> None:
        for message in messages:
            self.add(message)

    def messages(self) -> list[str]:
        """One line per cause: the first message, with ``(and N more like it)`` when the cause recurred with
        other numbers."""
        lines = []
        for cause, first in self._first.items():
            more = self._count[cause] - 1
            lines.append(first if more == 0 else f"{first} (and {more} more like it with other values)")
        return lines


def distinct_warnings(messages: Iterable[str]) -> list[str]:
    """The messages once per cause, in order of first appearance (see :class:`WarningTally`)."""
    tally = WarningTally()
    tally.update(messages)
    return tally.messages()
