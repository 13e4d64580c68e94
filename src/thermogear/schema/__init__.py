"""The case-file schema: one pydantic model per TOML section, assembled in :class:`CaseFile`."""

from __future__ import annotations

from pydantic import Field

from thermogear.schema.base import Section
from thermogear.schema.dynamics import DampingSection, DynamicsSection
from thermogear.schema.fem import FemSection
from thermogear.schema.gearbox import GearboxSection
from thermogear.schema.housing import HousingSection
from thermogear.schema.gears import GearSection, GearsSection, MaterialSection, OperatingSection
from thermogear.schema.lubricant import LubricantSection
from thermogear.schema.sweep import SweepSection
from thermogear.schema.temperature import TemperatureSection
from thermogear.schema.thermal import ThermalSection


class CaseInfo(Section):
    """[case]: what this case is and where its numbers come from."""

    name: str
    title: str = ""
    citation: str = ""
    assumptions: list[str] = Field(default_factory=list)


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


__all__ = ["CaseFile", "CaseInfo", "DampingSection", "DynamicsSection", "FemSection", "GearboxSection", "GearSection", "GearsSection", "HousingSection",
           "LubricantSection", "MaterialSection", "OperatingSection", "SweepSection", "TemperatureSection", "ThermalSection"]
