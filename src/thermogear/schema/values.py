"""Values of a study parameter as written on the command line or in a case's ``[sweep]`` section.

Parsing only (no case, no study): the case schema validates ``[sweep]`` with it and the study builds its grid
from it, so it sits below both.
"""

from __future__ import annotations

import math

import numpy as np

from thermogear.errors import CaseError

#: Largest study accepted: 10⁸ grid points take hours per core and tens of GB of results; refused up front.
MAX_POINTS = 100_000_000


def parse_values(text: str | float | int | list | tuple, name: str = "vary") -> np.ndarray:
    """Values of a parameter from ``"a:b:n"``, ``"v1,v2,..."``, one number or a list of numbers.

    ``a:b:n`` gives n evenly spaced values from a to b, both ends included (``np.linspace``). Raises CaseError
    naming ``name`` on anything else, on non-finite numbers and on repeated values.
    """
    allowed = "'a:b:n' (n >= 2 values from a to b), 'v1,v2,...' or one number"
    if isinstance(text, (list, tuple)):
        items = list(text)
    elif isinstance(text, (int, float)) and not isinstance(text, bool):
        items = [text]
    elif isinstance(text, str):
        stripped = text.strip()
        if ":" in stripped:
            parts = stripped.split(":")
            if len(parts) != 3:
                raise CaseError(name, text, allowed, "a range needs start, stop and count: 'a:b:n'")
            try:
                start, stop = float(parts[0]), float(parts[1])
                count_value = float(parts[2])
            except ValueError:
                raise CaseError(name, text, allowed, "start, stop and count must be numbers") from None
            if count_value != int(count_value) or count_value < 2:
                raise CaseError(name, text, allowed, "the count n of 'a:b:n' must be an integer >= 2")
            if count_value > MAX_POINTS:
                raise CaseError(name, text, f"n <= {MAX_POINTS:,}", f"{int(count_value):,} values is too many")
            if not (math.isfinite(start) and math.isfinite(stop)) or start == stop:
                raise CaseError(name, text, allowed, "start and stop must be finite and different")
            return np.linspace(start, stop, int(count_value))
        items = [part for part in stripped.split(",") if part.strip()]
        if not items:
            raise CaseError(name, text, allowed, "no values given")
    else:
        raise CaseError(name, text, allowed, "not a value specification")
    if not items:
        raise CaseError(name, text, allowed, "no values given")
    try:
        values = np.array([float(item) for item in items], dtype=float)
    except (TypeError, ValueError):
        raise CaseError(name, text, allowed, "every value must be a number") from None
    if not np.all(np.isfinite(values)):
        raise CaseError(name, text, "finite numbers", "a sweep over NaN or infinity has no meaning")
    if np.unique(values).size != values.size:
        raise CaseError(name, text, "distinct values", "a value repeated in a sweep computes the same point twice")
    return values


__all__ = ["MAX_POINTS", "parse_values"]
