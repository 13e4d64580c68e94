"""Case-file sections [damping] and [dynamics]."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from thermogear.schema.base import Section


class DampingSection(Section):
    """Equivalent viscous damping of tooth friction (Luo & Li Eqs. 26–28).

    ``rule``: how the pairs in contact combine into c(τ): ``"paper"`` (Luo & Li Fig. 7: the value of the pair
    at the contact position, double-pair value below single-pair value) or ``"parallel"`` (dampers of the pairs
    in contact add, the physically consistent reading of the same energy argument).
    """

    rule: Literal["paper", "parallel"] = "parallel"
    lubricant_factor: Annotated[float, Field(gt=0.0, le=3.0, description="X_L; default from the base oil")] | None = None


class DynamicsSection(Section):
    """Solver settings of the torsional model me·ẍ + c(τ)ẋ + k(τ)x = w."""

    method: Literal["periodic", "transient"] = "periodic"
    points_per_period: Annotated[int, Field(ge=64, le=100000)] = 1024
    transient_periods: Annotated[int, Field(ge=1, le=100000)] = 60
    include_damping_force: bool = Field(False, description="dynamic load k·x + c·ẋ instead of the paper's k·x")
