"""The typer application shared by every command module, and the helpers every command uses."""

from __future__ import annotations

import json
import sys
from typing import Any

import typer
from rich.console import Console

from thermogear.serialization import json_ready

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


def print_json(payload: dict[str, Any]) -> None:
    """One JSON object on stdout."""
    sys.stdout.write(json.dumps(json_ready(payload), indent=2) + "\n")
    sys.stdout.flush()
