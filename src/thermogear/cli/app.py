"""The typer application shared by every command module, and the helpers every command uses."""

from __future__ import annotations

import json
import math
import sys
from typing import Any

import numpy as np
import typer
from rich.console import Console

app = typer.Typer(
    name="thermogear",
    help="Thermo-elastic dynamics of spur gear pairs: thermal mesh stiffness, friction damping, transmission "
         "error and dynamic load (after Luo & Li 2020).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)

#: Console for human-readable output (stdout) and for messages (stderr).
console = Console()
error_console = Console(stderr=True)


def _plain(value: Any) -> Any:
    """JSON-ready copy: NumPy scalars and arrays to Python, non-finite numbers refused."""
    if isinstance(value, dict):
        return {str(key): _plain(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(item) for item in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"non-finite number {value} in a JSON result")
    return value


def print_json(payload: dict[str, Any]) -> None:
    """One JSON object on stdout."""
    sys.stdout.write(json.dumps(_plain(payload), indent=2) + "\n")
    sys.stdout.flush()
