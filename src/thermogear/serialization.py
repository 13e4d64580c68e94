"""JSON-ready copies of results: NumPy scalars and arrays to Python, non-finite numbers handled explicitly."""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np


def json_ready(value: Any, non_finite: Literal["raise", "null"] = "raise") -> Any:
    """A copy of ``value`` that :func:`json.dumps` accepts.

    Dicts (keys as strings), lists, tuples and arrays are converted recursively, NumPy scalars to Python ones.
    A NaN or infinity raises ``ValueError`` (``non_finite="raise"``: a result must never carry one silently) or
    becomes ``null`` (``"null"``: for files whose readers expect a missing value).
    """
    if isinstance(value, dict):
        return {str(key): json_ready(item, non_finite) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_ready(item, non_finite) for item in value]
    if isinstance(value, np.ndarray):
        return json_ready(value.tolist(), non_finite)
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        if non_finite == "null":
            return None
        raise ValueError(f"non-finite number {value} in a JSON result")
    return value
