"""Built-in oil library: the records of ``oils.toml`` (viscosity points, density, base oil, source).

This package only reads the data file; :mod:`thermogear.lubricant` turns a record into a
:class:`~thermogear.lubricant.Lubricant` (``builtin_lubricant(name)``).
"""

from __future__ import annotations

import tomllib
from functools import lru_cache
from importlib import resources
from types import MappingProxyType
from typing import Any, Mapping


@lru_cache(maxsize=1)
def oil_records() -> Mapping[str, Mapping[str, Any]]:
    """All oil records of ``oils.toml`` by name (read once, read-only)."""
    text = (resources.files("thermogear.lubricants") / "oils.toml").read_text(encoding="utf-8")
    document = tomllib.loads(text)
    return MappingProxyType({name: MappingProxyType(record) for name, record in document.items()})


__all__ = ["oil_records"]
