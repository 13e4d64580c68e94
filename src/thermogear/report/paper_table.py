"""ONE table of every number (and every checkable claim) of Luo & Li (2020), doi:10.1016/j.engfailanal.2020.104724.

Each :class:`PaperRow` holds the paper's value, its unit, its kind (prediction, qualitative, calibration, input),
how thermogear's value is compared with it (:class:`Check`), the argument for that tolerance, and — for a row
thermogear does not reproduce — the known cause (``gap``). The same table feeds the report, ``summary.json``
(``table_counts`` per kind), the validation tests (one test per row) and ``docs/validation.md``.

The comparison machinery is in :mod:`thermogear.report.paper_checks`, the rows in
:mod:`thermogear.report.paper_rows`.
"""

from __future__ import annotations

from thermogear.report.paper_checks import (KIND_MEANING, KINDS, Absolute, Bounds, Check, Claim, Exact, PaperRow,
                                            Range, Relative, Verdict, format_value, judge, known_gaps, known_gaps_text,
                                            table_counts)
from thermogear.report.paper_rows import paper_rows

__all__ = ["Check", "Relative", "Absolute", "Bounds", "Range", "Claim", "Exact", "PaperRow", "PAPER_ROWS", "row",
           "Verdict", "judge", "format_value", "KINDS", "KIND_MEANING", "table_counts", "known_gaps",
           "known_gaps_text"]

#: Every row, in the order of the paper.
PAPER_ROWS: tuple[PaperRow, ...] = tuple(paper_rows())

_BY_KEY = {item.key: item for item in PAPER_ROWS}
if len(_BY_KEY) != len(PAPER_ROWS):  # pragma: no cover - a programming error in paper_rows
    raise RuntimeError("duplicate row keys in the paper table")


def row(key: str) -> PaperRow:
    """The row of ``key``."""
    return _BY_KEY[key]
