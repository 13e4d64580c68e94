"""The typer application shared by every command module, and the helpers every command uses.

Commands are loaded lazily: :data:`COMMANDS` names the module of each command and its one-line help, so that
``thermogear --help`` lists every command without importing any, and ``thermogear cases`` imports only
:mod:`thermogear.cli.cases` (not scipy, the FE code or Dask). A command module registers its function on
:data:`app` with ``@app.command()`` when it is imported, as before.

Help is plain click help (``rich_markup_mode=None``): ``[mm]``, ``a:b:n`` and every other character of a help
string print as written, and flags show no value type.
"""

from __future__ import annotations

import importlib
import json
import re
import sys
from dataclasses import dataclass
from difflib import get_close_matches
from typing import Any

import typer
from typer.core import TyperGroup

from thermogear.cli.console import error_console, output_console

__all__ = ["COMMANDS", "LazyGroup", "app", "console", "error_console", "print_json"]


@dataclass(frozen=True)
class CommandEntry:
    """Where a command lives and what ``thermogear --help`` says of it (the first sentence of its docstring:
    ``tests/integration/test_cli_finish_startup.py`` checks that the two agree)."""

    module: str
    help: str


#: Every command, in the order ``thermogear --help`` lists them.
COMMANDS: dict[str, CommandEntry] = {
    "cases": CommandEntry("thermogear.cli.cases", "List the built-in parameter sets with their sources."),
    "schema": CommandEntry("thermogear.cli.cases", "Print every case-file key with its unit, type, allowed range, "
                                                   "default and meaning (one table per section)."),
    "oils": CommandEntry("thermogear.cli.damping", "List the built-in oils with their viscosities, density, base "
                                                   "oil and source."),
    "check": CommandEntry("thermogear.cli.check", "Validate a case and print its gear-pair geometry (exit status "
                                                  "2 with one clear message if it is invalid)."),
    "stiffness": CommandEntry("thermogear.cli.stiffness", "Elastic mesh stiffness along the path of contact and "
                                                          "over one mesh period (per mm of face width)."),
    "damping": CommandEntry("thermogear.cli.damping", "Equivalent viscous damping of tooth friction: elastic (oil "
                                                      "at the reference temperature) and thermal (oil at the "
                                                      "local flank temperature), per pair along the path and "
                                                      "over the mesh cycle."),
    "run": CommandEntry("thermogear.cli.run", "Run the dynamics of a case and report Kv, loads, transmission "
                                              "error per region, frequencies and stability."),
    "reproduce": CommandEntry("thermogear.cli.reproduce", "Reproduce a paper: every figure, every number beside "
                                                          "the paper's, the assumptions and the differences, in "
                                                          "one self-contained report.html (+ figures/, results.nc, "
                                                          "summary.json)."),
    "sweep": CommandEntry("thermogear.cli.sweep", "Run a parameter study of a case (grid over speed, load, "
                                                  "temperatures, geometry) into a zarr store."),
    "export": CommandEntry("thermogear.cli.export", "Write a sweep store or a report's results file as CSV: one row "
                                                    "per point or per time sample, the units in the column names, "
                                                    "the case and the version in comment lines (# …) on top."),
    "fem": CommandEntry("thermogear.cli.fem", "Finite-element verification: bulk temperature, FE vs PEM tooth "
                                              "compliance, flank expansion, X_te."),
    "warmup": CommandEntry("thermogear.cli.warmup", "Warm-up of a test rig as a sequence of steady operating "
                                                    "states."),
    "gearbox": CommandEntry("thermogear.cli.gearbox", "Steady temperatures, power losses by source, efficiency "
                                                      "and backlash of the case's gearbox, at its operating point "
                                                      "or over speeds × torques, on the study executor (serial, "
                                                      "worker processes or a Dask scheduler)."),
    "vibration": CommandEntry("thermogear.cli.vibration", "Vibration analysis of a measured signal (Luo & Li "
                                                          "2020 Table 3 / Fig. 18 style)."),
}


def first_sentence(text: str | None) -> str:
    """The first sentence of a docstring, on one line (what ``thermogear --help`` shows of a command)."""
    paragraph = " ".join((text or "").strip().split("\n\n")[0].split())
    end = re.search(r"\.\s(?=[A-Z])", paragraph)  # "Fig. 18", "e.g. this" do not end a sentence
    return paragraph if end is None else paragraph[:end.start() + 1]


class LazyGroup(TyperGroup):
    """A typer group that imports a command's module only when the command runs (or its help is asked for)."""

    def list_commands(self, ctx) -> list[str]:
        return list(COMMANDS) + [name for name in super().list_commands(ctx) if name not in COMMANDS]

    def get_command(self, ctx, cmd_name: str):
        command = super().get_command(ctx, cmd_name)
        if command is not None or cmd_name not in COMMANDS:
            return command
        importlib.import_module(COMMANDS[cmd_name].module)
        for info in app.registered_commands:
            name = info.name or (info.callback.__name__.replace("_", "-") if info.callback else None)
            if name == cmd_name:
                single = typer.Typer(rich_markup_mode=None, add_completion=False, pretty_exceptions_enable=False)
                single.registered_commands.append(info)
                command = typer.main.get_command(single)
                command.name = cmd_name
                self.add_command(command, cmd_name)
                return command
        return None

    def format_commands(self, ctx, formatter) -> None:
        """The command list of ``--help`` from :data:`COMMANDS`, without importing a command module."""
        rows = []
        for name in self.list_commands(ctx):
            if name in COMMANDS:
                rows.append((name, COMMANDS[name].help))
            else:
                command = super().get_command(ctx, name)
                if command is not None and not command.hidden:
                    rows.append((name, first_sentence(command.help)))
        if rows:
            with formatter.section("Commands"):
                formatter.write_dl(rows)

    def resolve_command(self, ctx, args):
        try:
            return super().resolve_command(ctx, args)
        except Exception as error:  # click's UsageError (typer vendors click: matched by what it offers)
            message = getattr(error, "message", None)
            if args and isinstance(message, str) and "Did you mean" not in message:
                matches = get_close_matches(args[0], self.list_commands(ctx))
                if matches:
                    error.message = (f"{message.rstrip('.')}. Did you mean "
                                     + ", ".join(repr(m) for m in matches) + "?")
            raise


app = typer.Typer(
    name="thermogear",
    cls=LazyGroup,
    help="Thermo-elastic dynamics of spur gear pairs: thermal mesh stiffness, friction damping, transmission "
         "error and dynamic load (after Luo & Li 2020).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)


def _print_version(value: bool) -> None:
    """``--version``: the installed thermogear version, then exit (reads package metadata only)."""
    if value:
        from thermogear import __version__  # noqa: PLC0415

        sys.stdout.write(f"thermogear {__version__}\n")
        raise typer.Exit()


@app.callback()
def _group(version: bool = typer.Option(False, "--version", is_eager=True, callback=_print_version,
                                        help="print the thermogear version and exit")) -> None:
    """Thermo-elastic dynamics of spur gear pairs: thermal mesh stiffness, friction damping, transmission error
    and dynamic load (after Luo & Li 2020)."""


#: Console for human-readable output (stdout) and for messages (stderr): text printed as written, never cut or
#: wrapped when not a terminal (see :mod:`thermogear.cli.console`).
console = output_console


def print_json(payload: dict[str, Any]) -> None:
    """One JSON object on stdout."""
    from thermogear.serialization import json_ready  # noqa: PLC0415  (NumPy: only when a command prints JSON)

    sys.stdout.write(json.dumps(json_ready(payload), indent=2) + "\n")
    sys.stdout.flush()


def result_payload(result, plot, as_json: bool, save) -> dict[str, Any] | None:
    """A study result's JSON (``result.as_dict()``) with its figure written to ``plot`` by ``save(figure, path)``
    (the path added as ``"plot"``); printed on stdout and None with ``--json`` (the command is done), else returned
    for the table."""
    payload = result.as_dict()
    if plot is not None:
        save(result.plot(), plot)
        payload["plot"] = str(plot)
    if as_json:
        print_json(payload)
        return None
    return payload
