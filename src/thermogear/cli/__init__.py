"""Command line of thermogear. Each command lives in its own module, imported only when the command runs
(:data:`thermogear.cli.app.COMMANDS`), and registers itself on ``app``."""

from __future__ import annotations

import os
import sys

import typer

from thermogear.cli.app import app
from thermogear.cli.console import error_console, install_warning_printer, print_error
from thermogear.errors import ThermogearError


def main() -> None:
    """Console-script entry point: run the app, turn thermogear errors into one clear line and exit 2."""
    install_warning_printer()
    # the command line only writes figures to files: a non-interactive backend, chosen here and never by the
    # library (a notebook user's backend stays theirs); an explicit MPLBACKEND wins
    os.environ.setdefault("MPLBACKEND", "Agg")
    try:
        status = app(standalone_mode=False, prog_name="thermogear")
    except ThermogearError as error:
        print_error(str(error))
        sys.exit(2)
    except KeyboardInterrupt:
        print_error("interrupted")
        sys.exit(130)
    except typer.Exit as error:
        sys.exit(error.exit_code)
    except typer.Abort:
        sys.exit(130)
    except Exception as error:
        # click's usage errors (typer vendors click, so they are matched by what they offer, not by class)
        if callable(getattr(error, "show", None)) and isinstance(getattr(error, "exit_code", None), int):
            _show_usage_error(error)
            sys.exit(error.exit_code)
        raise
    # without standalone mode click returns the exit code of an Exit/Abort instead of exiting with it
    sys.exit(status if isinstance(status, int) else 0)


def _show_usage_error(error) -> None:
    """A usage error as click shows it (usage line, where to find help) but in the one format, ``error: …``."""
    context = getattr(error, "ctx", None)
    format_message = getattr(error, "format_message", None)
    if context is None or not callable(format_message) or type(error).__name__ == "NoArgsIsHelpError":
        error.show()  # no context, or the help of a command given without arguments: click's own output
        return
    error_console.print(context.get_usage(), soft_wrap=True)
    if context.command.get_help_option(context) is not None:
        error_console.print(f"Try '{context.command_path} {context.help_option_names[0]}' for help.", soft_wrap=True)
    print_error(format_message())


__all__ = ["app", "main"]
