"""ONE table of every number (and every checkable claim) of Luo & Li (2020), doi:10.1016/j.engfailanal.2020.104724.

Each :class:`PaperRow` holds the paper's value, its unit, its kind (prediction, qualitative, calibration, input),
how thermogear's value is compared with it (:class:`Check`), the argument for that tolerance, and — for a row
thermogear does not reproduce — the known cause (``gap``). The same table feeds the report, ``summary.json``
(``table_counts`` per kind), the validation tests (one test per row) and ``docs/validation.md``.

The comparison machinery is in :mod:`thermogear.luo2020.report.checks`, the rows in
:mod:`thermogear.luo2020.report.rows`. :func:`paper_reference` hands the commands (``fem``, ``damping``) and the
report's figures the paper's numbers they show beside a case's own, read from the rows: no paper number is
written anywhere else.
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.luo2020.report.checks import (KIND_MEANING, KINDS, Absolute, Bounds, Check, Claim, Exact, PaperRow,
                                              Range, Relative, Verdict, format_value, judge, known_gaps,
                                              known_gaps_text, table_counts)
from thermogear.luo2020.report.rows import paper_rows

__all__ = ["Check", "Relative", "Absolute", "Bounds", "Range", "Claim", "Exact", "PaperRow", "PAPER_ROWS", "row",
           "PaperReference", "paper_reference",
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


@dataclass(frozen=True)
class PaperReference:
    """The paper's numbers a command shows beside a case's own (read from the rows of the table).

    flank_temperature_c: (lowest, highest) flank temperature along the path [°C] (Fig. 3c);
    stiffness_drop_percent: drop of k_T below k_e at A, C, E [%] (Fig. 4);
    mean_damping_n_s_per_m: mean damping per model ("elastic" c_e, "thermal" c_r) and contact region ("single",
    "double") [N·s/m], totals over the face width (Figs. 7–8).
    """

    flank_temperature_c: tuple[float, float]
    stiffness_drop_percent: dict
    mean_damping_n_s_per_m: dict


def paper_reference(citation: str | None) -> PaperReference | None:
    """The paper's numbers for a case whose ``[case] citation`` is ``citation`` when the case is a parameter set of
    the paper (its citation carries the paper's DOI: :func:`thermogear.evaluation.is_paper_case`), else None: a pair of one's own is never compared with
    the paper's numbers."""
    from thermogear.evaluation import is_paper_case

    if not is_paper_case(citation):
        return None
    damping_keys = {"elastic": "fig7.ce", "thermal": "fig8.cr"}
    return PaperReference(
        flank_temperature_c=(float(row("fig3.flank_temperature_min").paper),
                             float(row("fig3.flank_temperature_max").paper)),
        stiffness_drop_percent={point: float(row(f"fig4.drop_at_{point}").paper) for point in "ACE"},
        mean_damping_n_s_per_m={model: {region: float(row(f"{prefix}_{region}").paper)
                                        for region in ("single", "double")}
                                for model, prefix in damping_keys.items()})
