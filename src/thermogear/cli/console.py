"""What the command line writes: text as written, whole when not on a terminal, one warning format.

* The consoles interpret no markup, no emoji codes and highlight nothing: ``[mm]``, ``[lubricant]``, ``a:b:n``
  and a case title print exactly as written. Styles are given as ``style=`` or :class:`rich.text.Text` parts.
* When stdout or stderr is not a terminal (a file, a pipe, a CI log) the console is :data:`PIPE_WIDTH` columns
  wide whatever ``COLUMNS`` says: tables keep every cell whole and messages stay on one line.
* Warnings, from the model or from Python's :mod:`warnings`, print as ``warning: <message>``, once per cause
  (:mod:`thermogear.warning_causes`), never with a file path and a source line.
"""

from __future__ import annotations

import re
import sys
import warnings
from contextlib import contextmanager
from typing import Iterator

from rich.cells import cell_len
from rich.console import Console, ConsoleDimensions
from rich.text import Text

from thermogear.warning_causes import WarningTally

__all__ = ["PIPE_WIDTH", "PlainConsole", "error_console", "output_console", "print_error", "print_notes",
           "print_warning",
           "install_warning_printer", "progress_enabled", "point_progress", "step_progress", "warning_text"]

#: Width of a console that is not a terminal: wider than any table or message thermogear prints, so nothing is
#: cut ("thermog…") or wrapped mid-sentence. Tables are not expanded to it (rich sizes them to their content).
PIPE_WIDTH = 100_000

_CATEGORY = re.compile(r"^\s*[A-Za-z_]*Warning:\s*")


class PlainConsole(Console):
    """A rich console that prints text as written (no markup, emoji or highlighting) and, when its file is not a
    terminal, as wide as :data:`PIPE_WIDTH`."""

    def __init__(self, **kwargs) -> None:
        for key in ("markup", "emoji", "highlight"):
            kwargs.setdefault(key, False)
        super().__init__(**kwargs)

    @property
    def size(self) -> ConsoleDimensions:
        dimensions = Console.size.fget(self)
        if self.is_terminal:
            return dimensions
        return ConsoleDimensions(PIPE_WIDTH, dimensions.height)

    @size.setter
    def size(self, new_size: tuple[int, int]) -> None:
        Console.size.fset(self, new_size)

    def print(self, *objects, **kwargs) -> None:  # noqa: A003  (rich's name)
        """As :meth:`rich.console.Console.print`; off a terminal, a table whose title is wider than the table
        gets the title on a line of its own (rich would wrap it to the table's width)."""
        if self.is_terminal or "rich.table" not in sys.modules:
            return super().print(*objects, **kwargs)
        from rich.measure import Measurement  # noqa: PLC0415
        from rich.table import Table  # noqa: PLC0415

        pending: list = []
        for item in objects:
            if isinstance(item, Table) and isinstance(item.title, str) and item.title:
                width = Measurement.get(self, self.options, item).maximum
                if cell_len(item.title) > width:
                    if pending:
                        super().print(*pending, **kwargs)
                        pending = []
                    title, item.title = item.title, None
                    try:
                        super().print(Text(title, style="italic"), soft_wrap=True)
                        super().print(item, **kwargs)
                    finally:
                        item.title = title
                    continue
            pending.append(item)
        if pending or not objects:
            super().print(*pending, **kwargs)


#: stdout: tables and results.
output_console = PlainConsole()
#: stderr: progress, warnings, errors.
error_console = PlainConsole(stderr=True)


def warning_text(message: str) -> str:
    """A warning message without the Python class name some callers put in front ("ExtrapolationWarning: …")."""
    return _CATEGORY.sub("", str(message), count=1).strip()


#: Every warning printed by this process, by cause: a message printed from a summary's list and raised again as
#: a Python warning shows once.
_PRINTED = WarningTally()


def print_warning(message: str, console: Console | None = None) -> None:
    """``warning: <message>`` on stderr (or ``console``), on one line however narrow the terminal; once per cause
    in a process (:mod:`thermogear.warning_causes`)."""
    if not _PRINTED.add(warning_text(message)):
        return
    target = console if console is not None else error_console
    target.print(Text.assemble(("warning:", "yellow"), " ", warning_text(message)), soft_wrap=True)


def print_notes(notes, console: Console | None = None) -> None:
    """``note: <text>`` for each of a case's notes (what thermogear assumed for keys the case left out), on stdout
    (or ``console``), each on one line."""
    target = console if console is not None else output_console
    for note in notes:
        target.print(Text.assemble(("note:", "cyan"), " ", str(note)), soft_wrap=True)


def print_error(message: str, console: Console | None = None) -> None:
    """``error: <message>`` on stderr (or ``console``), on one line however narrow the terminal."""
    target = console if console is not None else error_console
    target.print(Text.assemble(("error:", "bold red"), " ", str(message)), soft_wrap=True)


def _showwarning(message, category, filename, lineno, file=None, line=None) -> None:
    """``warnings.showwarning`` of the command line: ``warning: …`` once per cause, no path, no source line."""
    print_warning(str(message))


def _formatwarning(message, category, filename, lineno, line=None) -> str:
    return f"warning: {warning_text(str(message))}\n"


def install_warning_printer() -> None:
    """Route Python warnings to ``warning: <message>`` lines on stderr, once per cause (command line only: the
    library leaves :mod:`warnings` as Python has it). Python's filters still decide which warnings show (third-party
    deprecation notices stay hidden, ``-W`` options apply)."""
    warnings.showwarning = _showwarning
    warnings.formatwarning = _formatwarning


def progress_enabled(console: Console, quiet: bool = False) -> bool:
    """A progress display only on a terminal, and never with ``--quiet``/``--json``."""
    return not quiet and console.is_terminal


#: Redraws per second of a study's progress bar.
POINT_PROGRESS_REFRESH_PER_S = 2


@contextmanager
def point_progress(label: str, total: int, completed: int = 0, unit: str = "points",
                   enabled: bool = True, console: Console | None = None) -> Iterator:
    """A progress bar on stderr counting ``unit`` (e.g. sweep points); yields ``advance(count)``. Shown only when
    ``enabled`` and stderr is a terminal. It is redrawn twice a second (rich's default, ten times, took 2 % of a core
    in the driver, beside the study's workers; twice, 0.5 %)."""
    target = console if console is not None else error_console
    if not progress_enabled(target, not enabled):
        yield lambda count=1: None
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, \
        TimeRemainingColumn

    with Progress(TextColumn(label, style="bold", markup=False), BarColumn(), MofNCompleteColumn(),
                  TextColumn(unit, markup=False),
                  TimeElapsedColumn(), TimeRemainingColumn(), console=target, transient=False,
                  refresh_per_second=POINT_PROGRESS_REFRESH_PER_S) as progress:
        task = progress.add_task(label, total=total, completed=completed)
        yield lambda count=1: progress.advance(task, count)


@contextmanager
def step_progress(steps: list[str], quiet: bool = False, console: Console | None = None) -> Iterator:
    """A spinner with the current step, steps done / total and the time elapsed, on stderr; yields
    ``advance(step_name)`` (call it as each step starts). Shown only on a terminal and without ``quiet``."""
    target = console if console is not None else error_console
    if not progress_enabled(target, quiet):
        yield lambda name: None
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, SpinnerColumn, TextColumn, \
        TimeElapsedColumn

    with Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False), BarColumn(),
                  MofNCompleteColumn(), TimeElapsedColumn(), console=target, transient=True) as progress:
        task = progress.add_task(steps[0] if steps else "", total=len(steps))
        started: list[str] = []

        def advance(name: str) -> None:
            if started:
                progress.advance(task)
            started.append(name)
            progress.update(task, description=name)

        yield advance
        progress.update(task, completed=len(steps))
