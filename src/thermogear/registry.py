"""The one lookup of a registry of choices by name (issue 33: every choice resolved once, from a registry): the
registered object, or a CaseError naming the key, the value, the registered names and the reason. This module
imports nothing of thermogear but its errors, so every layer may read it."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TypeVar

from thermogear.errors import CaseError

__all__ = ["registered"]

Choice = TypeVar("Choice")


def registered(table: Mapping[str, Choice], name: str, key: str, reason: str, allowed: str | None = None) -> Choice:
    """``table[name]``; a CaseError naming ``key`` and ``name`` (allowed: ``allowed``, default the registered names
    joined by " | ", for ``reason``) where ``name`` is not registered."""
    choice = table.get(name)
    if choice is None:
        raise CaseError(key, name, " | ".join(table) if allowed is None else allowed, reason)
    return choice
