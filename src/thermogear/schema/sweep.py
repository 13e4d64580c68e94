"""Case-file section [sweep]: a parameter study of the case (``thermogear sweep CASE`` runs it).

```toml
[sweep]
model = "both"                # elastic | thermal | both
chunk_points = 256            # grid points per task and per stored chunk (optional)

[sweep.vary]                  # one entry per parameter, in grid order (the last varies fastest)
oil_temperature_c = [30, 60, 90]
speed_rpm = "500:12000:240"   # 240 values from 500 to 12000, both included
```
Names are the aliases of :data:`thermogear.sweep.study.ALIASES` or dotted case keys; values ``"a:b:n"``, a list
of numbers or one number. The names are checked against the case schema when the study is defined.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, field_validator

from thermogear.schema.base import Section
from thermogear.schema.values import parse_values


class SweepSection(Section):
    """[sweep]: what to vary, which models to run, how to chunk the work."""

    model: Literal["elastic", "thermal", "both"] = "both"
    vary: dict[str, str | float | list[float]] = Field(
        default_factory=dict, description="parameter name → 'a:b:n', a list of values or one value")
    chunk_points: Annotated[int, Field(ge=1, le=1_000_000)] | None = Field(
        None, description="grid points per task and per stored chunk")

    @field_validator("vary")
    @classmethod
    def _values_parse(cls, vary: dict) -> dict:
        for name, spec in vary.items():
            try:
                parse_values(spec, name=f"vary.{name}")
            except ValueError as error:  # CaseError is a ValueError
                raise ValueError(str(error)) from None
        return vary
