"""The case-file schema: one pydantic model per TOML section, assembled in :class:`CaseFile`."""

from __future__ import annotations

import re

from pydantic import Field, field_validator, model_validator

from thermogear.errors import CaseError
from thermogear.schema.base import Section
from thermogear.schema.bearing_loss import check_bearings_described_once
from thermogear.schema.drivetrain import DrivetrainSection
from thermogear.schema.dynamics import DampingSection, DynamicsSection
from thermogear.schema.fem import FemSection
from thermogear.schema.gearbox import GearboxSection
from thermogear.schema.housing import HousingSection
from thermogear.schema.gears import GearSection, GearsSection, MaterialSection, OperatingSection
from thermogear.schema.lubricant import LubricantSection
from thermogear.schema.sweep import SweepSection
from thermogear.schema.temperature import TemperatureSection
from thermogear.schema.thermal import ThermalSection


#: Control characters (Unicode category Cc: U+0000–U+001F and U+007F–U+009F), and the same but tab and newline.
_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f]")
_CONTROL_BUT_LAYOUT = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f]")


class CaseInfo(Section):
    """[case]: what this case is and where its numbers come from."""

    name: str
    title: str = ""
    citation: str = ""
    assumptions: list[str] = Field(default_factory=list)

    @field_validator("name", "title", "citation", "assumptions")
    @classmethod
    def _printable(cls, value, info):
        """Text that is printed to a terminal and into reports: no control characters (an escape sequence in a
        name was printed raw and drove the terminal, issue 25). Tabs and line breaks stay in the long texts."""
        control = _CONTROL if info.field_name == "name" else _CONTROL_BUT_LAYOUT
        for text in value if isinstance(value, list) else [value]:
            found = control.search(text)
            if found is not None:
                bad = found.group()
                raise CaseError(f"case.{info.field_name}", text, "printable text (no control characters)",
                                f"it holds the control character {bad!r}, which a terminal would act on")
        return value


class CaseFile(Section):
    """A whole case file."""

    case: CaseInfo
    gears: GearsSection
    material: MaterialSection = MaterialSection()
    operating: OperatingSection
    lubricant: LubricantSection = LubricantSection(name="iso_vg_100_mineral")
    temperature: TemperatureSection = TemperatureSection()
    thermal: ThermalSection = ThermalSection()
    housing: HousingSection = HousingSection()
    damping: DampingSection = DampingSection()
    dynamics: DynamicsSection = DynamicsSection()
    fem: FemSection = FemSection()
    sweep: SweepSection | None = None
    gearbox: GearboxSection | None = None
    drivetrain: DrivetrainSection | None = None

    @model_validator(mode="after")
    def _bearings_once(self):
        """Each bearing described once: with a [drivetrain], in [[drivetrain.bearings]] only."""
        check_bearings_described_once(self.gearbox, self.drivetrain)
        return self


__all__ = ["CaseFile", "CaseInfo", "DampingSection", "DrivetrainSection", "DynamicsSection", "FemSection", "GearboxSection", "GearSection", "GearsSection", "HousingSection",
           "LubricantSection", "MaterialSection", "OperatingSection", "SweepSection", "TemperatureSection", "ThermalSection"]
