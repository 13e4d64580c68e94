"""How one row of the paper table is compared and counted: checks, :class:`PaperRow`, :class:`Verdict`, counts.

The rows themselves are in :mod:`thermogear.luo2020.report.rows`; :mod:`thermogear.luo2020.report.table` gathers both.

Every row has one *kind* (:data:`KINDS`):

* ``prediction``: a number of the paper that thermogear computes from the case without having been tuned to it;
* ``qualitative``: a yes/no statement of the paper that thermogear's results must also make;
* ``calibration``: a number a parameter of the case was tuned to: it matches by construction and proves only that
  the calibration works;
* ``input``: a number the case carries (Table 1, the rig data transcribed from Table 3 and Fig. 18, a figure
  setting): a transcription check.

Only predictions and qualitative statements are evidence for the model; the headline counts predictions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

__all__ = ["KINDS", "KIND_MEANING", "Check", "Relative", "Absolute", "Bounds", "Range", "Claim", "Exact",
           "PaperRow", "Verdict", "judge", "format_value", "table_counts", "known_gaps", "known_gaps_text"]

#: The kinds of row, in the order the report lists them.
KINDS = ("prediction", "qualitative", "calibration", "input")

KIND_MEANING = {
    "prediction": "a number thermogear computes from the case, not tuned to it",
    "qualitative": "a statement of the paper that thermogear's results must also make",
    "calibration": "a number a parameter was tuned to (matches by construction)",
    "input": "a number the case carries or a transcription of the paper's data (a copy check)",
}

STATUSES = ("within", "outside", "not computed")


# ----------------------------------------------------------------------------------------------- checks
@dataclass(frozen=True)
class Check:
    """How a thermogear value is compared with the paper's. ``within(paper, value) -> bool``."""

    #: True when the paper gives only a range or an order of magnitude: no deviation in % is shown
    range_only = False

    def within(self, paper, value) -> bool:  # pragma: no cover - abstract
        raise NotImplementedError

    def describe(self, paper) -> str:  # pragma: no cover - abstract
        raise NotImplementedError


@dataclass(frozen=True)
class Relative(Check):
    """|value/paper − 1| ≤ tolerance."""

    tolerance: float

    def within(self, paper, value) -> bool:
        return abs(float(value) / float(paper) - 1.0) <= self.tolerance

    def describe(self, paper) -> str:
        return f"±{self.tolerance * 100:g} %"


@dataclass(frozen=True)
class Absolute(Check):
    """|value − paper| ≤ tolerance (in the row's unit)."""

    tolerance: float

    def within(self, paper, value) -> bool:
        return abs(float(value) - float(paper)) <= self.tolerance

    def describe(self, paper) -> str:
        return f"±{self.tolerance:g}"


@dataclass(frozen=True)
class Bounds(Check):
    """low ≤ value ≤ high around a single value of the paper (``relative=True``: the bounds apply to
    value/paper). For an asymmetric, argued band."""

    low: float
    high: float
    relative: bool = False

    def within(self, paper, value) -> bool:
        quantity = float(value) / float(paper) if self.relative else float(value)
        return self.low <= quantity <= self.high

    def describe(self, paper) -> str:
        if self.relative:
            return f"{self.low:g}–{self.high:g} × paper"
        return f"in [{self.low:g}, {self.high:g}]"


@dataclass(frozen=True)
class Range(Check):
    """The paper gives only a range or an order of magnitude: low ≤ value ≤ high, reported as "inside the
    range" (a deviation in % from a made-up middle would mean nothing)."""

    low: float
    high: float
    range_only = True

    def within(self, paper, value) -> bool:
        return self.low <= float(value) <= self.high

    def describe(self, paper) -> str:
        return f"inside [{self.low:g}, {self.high:g}]"


@dataclass(frozen=True)
class Claim(Check):
    """A yes/no statement of the paper: thermogear must say the same."""

    def within(self, paper, value) -> bool:
        return bool(value) is bool(paper)

    def describe(self, paper) -> str:
        return "same statement"


@dataclass(frozen=True)
class Exact(Check):
    """Equal up to rounding (relative 1e-9): inputs and transcriptions."""

    def within(self, paper, value) -> bool:
        return math.isclose(float(value), float(paper), rel_tol=1e-9, abs_tol=1e-12)

    def describe(self, paper) -> str:
        return "exact"


# ------------------------------------------------------------------------------------------------- rows
@dataclass(frozen=True)
class PaperRow:
    """One number or claim of the paper.

    key: stable identifier (used in summary.json and the tests); section: where in the paper; quantity: what;
    paper: the paper's value (a float, or True for a claim); unit: the unit of paper and thermogear values;
    check: the comparison; argument: why that tolerance (the paper's precision and the model's uncertainty);
    note: context of the value; kind: one of :data:`KINDS`; required: True when the report of ``luo2019`` must
    compute it; scale: factor from the evaluation's value to ``unit``; gap: the known cause, for a row thermogear is known not to reproduce (a *known gap*).
    """

    key: str
    section: str
    quantity: str
    paper: float | bool
    unit: str
    check: Check
    argument: str
    note: str = ""
    kind: str = "prediction"
    required: bool = True
    figure: str = ""
    paper_display: str = ""  # how the paper states it, where that is not a single number ("1 < ε < 2")
    gap: str = ""
    scale: float = 1.0  # factor from the evaluation's SI-like value to the row's unit (e.g. N/m per m → N/mm)

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"{self.key}: kind {self.kind!r} is not one of {KINDS}")

    @property
    def tolerance_text(self) -> str:
        return self.check.describe(self.paper)

    @property
    def paper_text(self) -> str:
        return self.paper_display or format_value(self.paper)


def format_value(value) -> str:
    """Display form of a table value."""
    if value is None:
        return "not computed"
    if isinstance(value, bool):
        return "yes" if value else "no"
    value = float(value)
    if value == 0.0:
        return "0"
    if abs(value) >= 1e4 or abs(value) < 1e-2:
        return f"{value:.3g}"
    return f"{value:.4g}"


@dataclass(frozen=True)
class Verdict:
    """A row judged: thermogear value (or None with the reason), deviation and whether it is within."""

    row: PaperRow
    value: float | bool | None
    reason: str = ""
    deviation: float | None = None  # relative (fraction) for numbers, None for claims and ranges
    within: bool | None = None
    extra: dict = field(default_factory=dict)

    @property
    def computed(self) -> bool:
        return self.value is not None

    @property
    def deviation_text(self) -> str:
        if self.row.check.range_only and self.computed:
            return "inside the range" if self.within else "outside the range"
        if self.deviation is None:
            return "—"
        if abs(self.deviation) < 5e-4:
            return "0.0 %"
        return f"{self.deviation * 100:+.1f} %"

    @property
    def status(self) -> str:
        if not self.computed:
            return "not computed"
        return "within" if self.within else "outside"

    def as_dict(self) -> dict:
        value = self.value
        if value is not None and not isinstance(value, bool):
            value = float(value)
        paper = self.row.paper if isinstance(self.row.paper, bool) else float(self.row.paper)
        return {"key": self.row.key, "section": self.row.section, "quantity": self.row.quantity,
                "kind": self.row.kind, "paper": paper, "paper_text": self.row.paper_text, "thermogear": value,
                "unit": self.row.unit, "deviation": self.deviation, "deviation_text": self.deviation_text,
                "tolerance": self.row.tolerance_text, "tolerance_argument": self.row.argument,
                "within": self.within, "status": self.status, "reason": self.reason, "note": self.row.note,
                "known_gap": self.row.gap, "required": self.row.required}


def judge(row: PaperRow, value, reason: str = "") -> Verdict:
    """Compare thermogear's ``value`` (None: not computed, with ``reason``) with the row."""
    if value is None:
        return Verdict(row, None, reason or "no value", None, None)
    if isinstance(value, float) and not math.isfinite(value):
        return Verdict(row, None, f"non-finite value {value}", None, None)
    if row.scale != 1.0 and not isinstance(value, bool):
        value = float(value) * row.scale
    deviation = None
    if not isinstance(row.paper, bool) and not isinstance(value, bool) and not row.check.range_only:
        deviation = (float(value) - float(row.paper)) / abs(float(row.paper)) if row.paper != 0 else None
    return Verdict(row, value, reason, deviation, bool(row.check.within(row.paper, value)))


# ----------------------------------------------------------------------------------------------- counts
def table_counts(verdicts) -> dict:
    """Per kind: ``{"total", "within", "outside", "not computed"}``; the headline is ``["prediction"]``."""
    counts = {}
    for kind in KINDS:
        rows = [verdict for verdict in verdicts if verdict.row.kind == kind]
        counts[kind] = {"total": len(rows), **{status: sum(1 for v in rows if v.status == status)
                                               for status in STATUSES}}
    return counts


def known_gaps(verdicts) -> list:
    """The prediction and qualitative rows that are not within (outside or not computed), in table order.
    Each carries its cause in ``row.gap`` (empty: an undocumented difference, which the tests refuse)."""
    return [verdict for verdict in verdicts if verdict.row.kind in ("prediction", "qualitative")
            and verdict.status != "within"]


def known_gaps_text(verdicts) -> str:
    """How many known gaps the report lists, split by kind: ``"18 known gaps (13 predictions, 5 statements)"``.
    Every headline (report, terminal, docs) counts the same rows as the list beneath it (:func:`known_gaps`)."""
    gaps = known_gaps(verdicts)
    predictions = sum(verdict.row.kind == "prediction" for verdict in gaps)
    statements = len(gaps) - predictions
    parts = [f"{count} {word}{'' if count == 1 else 's'}"
             for count, word in ((predictions, "prediction"), (statements, "statement")) if count]
    return f"{len(gaps)} known gap{'' if len(gaps) == 1 else 's'}" + (f" ({', '.join(parts)})" if parts else "")
