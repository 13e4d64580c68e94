"""Common base of the case-file sections: frozen, unknown keys refused."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict


class Section(BaseModel):
    """A case-file section: immutable, strict about unknown keys, numbers given as ints accepted as floats."""

    model_config = ConfigDict(extra="forbid", frozen=True, validate_default=True)
