"""Terminal side of the report commands: a progress bar over the steps and the short rich summary."""

from __future__ import annotations

from contextlib import contextmanager
from typing import Iterator

from rich.console import Console
from rich.table import Table
from rich.text import Text

from thermogear.luo2020.report.table import format_value

__all__ = ["interruptible", "print_summary", "print_messages"]


@contextmanager
def interruptible(target) -> Iterator[None]:
    """Turn Ctrl-C / SIGTERM during a report into one line on stderr and exit status 130 (the output folder is
    left as it was: see :class:`~thermogear.report.writer.OutputFolder`)."""
    import signal
    import sys

    from thermogear.report.writer import Terminated

    def terminate(signum, frame):
        raise Terminated(f"terminated by signal {signum}")

    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        yield
    except KeyboardInterrupt:
        Console(stderr=True, markup=False, emoji=False, highlight=False).print(
            f"interrupted: {target} was not written or replaced", soft_wrap=True)
        sys.exit(130)
    finally:
        signal.signal(signal.SIGTERM, previous)


def print_messages(messages: list[str], console: Console) -> None:
    for message in messages:
        console.print(Text(message, style="bold red"), soft_wrap=True)


def print_summary(outcome, console: Console) -> None:
    """The short summary: the paper table (predictions, statements and the calibration; inputs counted) or
    the results table, the messages, and the report's path."""
    if outcome.verdicts:
        table = Table(title="Luo & Li (2020) vs thermogear", show_lines=False, header_style="bold")
        # the quantity wraps on a narrow terminal rather than being cut; off a terminal nothing wraps
        table.add_column("quantity", overflow="fold", max_width=max(24, console.width - 58))
        for name in ("paper", "thermogear", "unit", "deviation", "status"):
            table.add_column(name, justify="left" if name in ("unit", "status") else "right", overflow="fold")
        style = {"within": Text("within", style="green"), "outside": Text("outside", style="red"),
                 "not computed": Text("not computed", style="yellow")}
        for verdict in outcome.verdicts:
            if verdict.row.kind not in ("prediction", "qualitative", "calibration"):
                continue
            row = verdict.row
            table.add_row(row.quantity, row.paper_text, format_value(verdict.value), row.unit, verdict.deviation_text,
                          style[verdict.status] + ("" if not row.gap else " (known gap)"))
        console.print(table)
        from thermogear.luo2020.report.table import known_gaps_text, table_counts

        counts = table_counts(outcome.verdicts)
        for kind, label in (("input", "inputs and rig data transcribed (not counted)"),
                            ("calibration", "calibration (matches by construction, not counted)")):
            rows = [v for v in outcome.verdicts if v.row.kind == kind]
            console.print(f"{label}: {counts[kind]['within']}/{counts[kind]['total']} within"
                          + ("" if counts[kind]["within"] == len(rows) else
                             " (" + ", ".join(f"{v.row.key}: {v.status}" for v in rows if v.status != "within") + ")"),
                          highlight=False)
        prediction, statement = counts["prediction"], counts["qualitative"]
        console.print(Text.assemble((f"predictions: {prediction['within']} of {prediction['total']} within", "bold"),
                                    ", ", (known_gaps_text(outcome.verdicts), "red"),
                                    f" (causes in report.html); statements: {statement['within']} of "
                                    f"{statement['total']} reproduced"))
    else:
        table = Table(title=f"thermogear results: {outcome.evaluation.case.name}", header_style="bold")
        table.add_column("quantity", overflow="fold", max_width=max(24, console.width - 40))
        for name in ("elastic", "thermal", "unit"):
            table.add_column(name, justify="left" if name == "unit" else "right", overflow="fold")
        for row in outcome.results:
            table.add_row(row["quantity"], format_value(row["elastic"]) if row["elastic"] is not None else "—",
                          format_value(row["thermal"]) if row["thermal"] is not None else "—", row["unit"])
        console.print(table)
    print_messages(outcome.messages, console)
    if outcome.missing_figures:
        console.print("figures not drawn: " + "; ".join(f"{k} ({v})" for k, v in outcome.missing_figures.items()),
                      highlight=False)
    console.print(Text.assemble("report: ", (str(outcome.report), "bold"), f"  ({outcome.seconds:.1f} s)"))
