"""The FZG back-to-back test rig (ISO 14635-1 / DIN 51354): load stages.

Pinion torques of the load stages KS 1–14 for the standard 0.5 m load lever, as tabulated in the GEARpie
project's ``LOAD_STAGES.py``; ISO 14635-1 defines the same stages.
"""

from __future__ import annotations

from thermogear.errors import CaseError

#: Pinion torque T1 [N m] of each FZG load stage (0.5 m lever arm).
FZG_LOAD_STAGE_TORQUE_NM: dict[int, float] = {
    1: 3.3, 2: 13.7, 3: 35.25, 4: 60.75, 5: 94.1, 6: 135.3, 7: 183.35,
    8: 239.25, 9: 302.0, 10: 372.6, 11: 450.1, 12: 534.5, 13: 626.9, 14: 714.2,
}


def fzg_load_stage_torque(stage: int) -> float:
    """Pinion torque [N m] of FZG load stage ``stage`` (1–14)."""
    try:
        return FZG_LOAD_STAGE_TORQUE_NM[stage]
    except KeyError:
        raise CaseError("operating.fzg_load_stage", stage, "1..14", "the FZG rig has load stages 1 to 14") from None
