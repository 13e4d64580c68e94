"""A drivetrain bearing's loss-model data (``loss`` of a ``[[drivetrain.bearings]]`` table) and the rule that each
bearing is described once.

With a ``[drivetrain]``, a bearing is one ``[[drivetrain.bearings]]`` table: its stiffness, damping and clearance,
and, for the gearbox thermal model, the data of its frictional moment (SKF model)::

    [[drivetrain.bearings]]
    name = "pinion bearing A"
    shaft = "pinion shaft"
    position_mm = 0.0
    stiffness_x_n_per_m = 5.4e8
    stiffness_y_n_per_m = 5.4e8
    loss = { designation = "NJ406" }    # or type, bore_mm, outside_mm, width_mm and the SKF constants

Its radial load for the loss is then the drivetrain's static bearing force (not an assumed share of the tooth
force). ``[[gearbox.bearings]]`` (per shaft, with load fractions) stays the way for a gearbox without a drivetrain;
a case with both sections describes its bearings in ``[[drivetrain.bearings]]`` only.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from thermogear.errors import CaseError
from thermogear.schema.base import Section

#: The keys of the SKF constants that a designation sets.
CONSTANT_KEYS = ("type", "bore_mm", "outside_mm", "width_mm", "rolling_constant", "sliding_constants",
                 "geometry_constant")


class SkfBearingData(Section):
    """The SKF frictional-moment data of one rolling bearing: a built-in designation or the type, the size and the
    constants in catalogue units (shared by ``[[gearbox.bearings]]`` and a drivetrain bearing's ``loss``)."""

    designation: Literal["NJ406"] | None = Field(None, description="built-in bearing constants (size and SKF "
                                                                   "constants)")
    type: Literal["cylindrical_roller", "deep_groove_ball"] | None = Field(None, description="bearing type (the "
                                                                                              "SKF model's form)")
    bore_mm: Annotated[float, Field(gt=0.0, le=2000.0, allow_inf_nan=False)] | None = Field(
        None, description="bore d [mm]")
    outside_mm: Annotated[float, Field(gt=0.0, le=3000.0, allow_inf_nan=False)] | None = Field(
        None, description="outside diameter D [mm]")
    width_mm: Annotated[float, Field(gt=0.0, le=1000.0, allow_inf_nan=False)] | None = Field(
        None, description="width B [mm]")
    rolling_constant: Annotated[float, Field(gt=0.0, le=1e-3, allow_inf_nan=False)] | None = Field(
        None, description="R1 of the SKF model [catalogue units]")
    sliding_constants: tuple[Annotated[float, Field(ge=0.0, allow_inf_nan=False)],
                             Annotated[float, Field(ge=0.0, allow_inf_nan=False)]] | None = Field(
        None, description="(S1, S2) of the SKF model (ball bearings: S2 = 0)")
    geometry_constant: Annotated[float, Field(gt=0.0, le=20.0, allow_inf_nan=False)] | None = Field(
        None, description="K_Z of the SKF model")
    drag_variable: Annotated[float, Field(ge=0.0, le=1e-2, allow_inf_nan=False)] | None = Field(
        None, description="V_M of the SKF drag loss (default 0: above the oil); set by a designation")


class BearingLossSection(SkfBearingData):
    """A drivetrain bearing's loss data: the SKF data and, optionally, the outer raceway diameter for the thermal
    change of its clearance."""

    outer_raceway_diameter_mm: Annotated[float, Field(gt=0.0, le=3000.0, allow_inf_nan=False)] | None = Field(
        None, description="outer-ring raceway diameter E [mm] for the thermal change of the clearance; default "
                          "(d + 3D)/4 (rolling elements filling half the radial section)")


def check_loss_data(loss: BearingLossSection, key: str) -> None:
    """A designation alone, or the type, size and every SKF constant, with the outer raceway inside the ring;
    errors name ``key`` (the bearing's ``loss`` table)."""
    if loss.designation is not None:
        given = [name for name in (*CONSTANT_KEYS, "drag_variable") if getattr(loss, name) is not None]
        if given:
            raise CaseError(f"{key}.{given[0]}", getattr(loss, given[0]), "absent with a designation",
                            "the designation sets the bearing's size and constants")
        return
    for name in CONSTANT_KEYS:
        if getattr(loss, name) is None:
            raise CaseError(f"{key}.{name}", None, "a value (or designation = 'NJ406')",
                            "the SKF model of the bearing's frictional moment needs it")
    if loss.outside_mm <= loss.bore_mm:
        raise CaseError(f"{key}.outside_mm", loss.outside_mm, f"> bore_mm = {loss.bore_mm}",
                        "the outside diameter is larger than the bore")
    if loss.outer_raceway_diameter_mm is not None and not loss.bore_mm < loss.outer_raceway_diameter_mm < loss.outside_mm:
        raise CaseError(f"{key}.outer_raceway_diameter_mm", loss.outer_raceway_diameter_mm,
                        f"between bore_mm {loss.bore_mm} and outside_mm {loss.outside_mm}",
                        "the outer raceway lies inside the outer ring")


def check_bearings_described_once(gearbox, drivetrain) -> None:
    """With both ``[gearbox]`` and ``[drivetrain]``, the bearings are the drivetrain's: a ``[[gearbox.bearings]]``
    entry would describe a bearing a second time (its loss from an assumed load share beside the drivetrain's
    static force). Refused, naming the drivetrain bearings of that shaft."""
    if gearbox is None or drivetrain is None or not gearbox.bearings:
        return
    shafts = {"pinion": drivetrain.pinion.shaft, "wheel": drivetrain.wheel.shaft}
    for entry in gearbox.bearings:
        shaft = shafts[entry.shaft]
        named = [bearing.name for bearing in drivetrain.bearings if bearing.shaft == shaft]
        with_loss = [bearing.name for bearing in drivetrain.bearings if bearing.shaft == shaft
                     and bearing.loss is not None]
        reason = (f"the bearings of '{shaft}' are described in [[drivetrain.bearings]] ({', '.join(named)})"
                  + (f"; {', '.join(with_loss)} already carry loss data: each bearing is described once"
                     if with_loss else "; give each its loss data there as loss = { designation = ... } or the SKF "
                                       "constants"))
        raise CaseError(f"gearbox.bearings (shaft = '{entry.shaft}')", entry.designation or entry.type,
                        "absent in a case with a [drivetrain]", reason)


__all__ = ["BearingLossSection", "SkfBearingData", "CONSTANT_KEYS", "check_bearings_described_once", "check_loss_data"]
