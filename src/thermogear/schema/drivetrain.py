"""Case-file section [drivetrain]: the gear pair on its shafts, bearings and couplings (thermogear.drivetrain).

```toml
[drivetrain]
centre_line_angle_deg = 0.0             # direction from the pinion's centre to the wheel's, from +x towards +y
pinion_rotation = "counter-clockwise"   # the pinion's turning sense about +z (the shafts' axis)
pinion = { shaft = "pinion shaft", position_mm = 125.0 }
wheel = { shaft = "wheel shaft", position_mm = 150.0 }

[[drivetrain.shafts]]
name = "pinion shaft"
segments = [{ length_mm = 250.0, outer_diameter_mm = 40.0 }]

[[drivetrain.bearings]]
name = "pinion bearing A"
shaft = "pinion shaft"
position_mm = 0.0
stiffness_x_n_per_m = 2.5e8
stiffness_y_n_per_m = 2.5e8
```
Positions are measured along each shaft from its first end [mm]. A shaft's material is the case's ``[material]``
unless the shaft gives its own. The gear bodies are not typed in: they are annuli of the gears' operating pitch
diameter and face width around the bore (or the case's ``inertia_kg_m2``). The ends of the train are driven by a
constant torque (no torsional support: the train turns freely) or by a motor held at speed (a torsional spring and
dashpot to ground from the speed controller's gains). The full description: docs/drivetrain.md.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from thermogear.choices.drivetrain import END_KINDS
from thermogear.errors import CaseError
from thermogear.schema.base import Section
from thermogear.schema.bearing_loss import BearingLossSection, check_loss_data
from thermogear.schema.gears import GearsSection

#: Lengths and positions [mm]: from a 0.1 mm shim to a 20 m line shaft.
_LENGTH_MM = (0.1, 20_000.0)
#: Diameters [mm]: 1 mm pins to 3 m turbine rotors.
_DIAMETER_MM = (1.0, 3000.0)
#: Bearing and coupling translational stiffness [N/m]: from a soft elastomer mount (1e3) to 1e15, stiff enough to
#: stand for a rigid support in a limit check (a steel rolling bearing is 1e7–1e9 N/m).
_STIFFNESS_N_PER_M = (0.0, 1e15)
#: Torsional stiffness [N·m/rad] of couplings and speed-held motors: up to 1e12 (a rigid flange).
_TORSIONAL_N_M_PER_RAD = (0.0, 1e12)
#: Damping [N·s/m or N·m·s/rad]: a rolling bearing's is (0.25–2.5)e-5 s × its stiffness (Friswell et al. 2010).
_DAMPING = (0.0, 1e10)

_NAME = Annotated[str, Field(min_length=1, max_length=60, description="a name, unique in the drivetrain")]
_SHAFT = Annotated[str, Field(min_length=1, max_length=60, description="the name of a [[drivetrain.shafts]] table")]
_POSITION = Annotated[float, Field(ge=0.0, le=_LENGTH_MM[1], description="position along the shaft from its first "
                                                                         "end [mm]")]


class ShaftSegmentSection(Section):
    """One uniform piece of a shaft, in order from the shaft's first end."""

    length_mm: Annotated[float, Field(ge=_LENGTH_MM[0], le=_LENGTH_MM[1], description="segment length [mm]")]
    outer_diameter_mm: Annotated[float, Field(ge=_DIAMETER_MM[0], le=_DIAMETER_MM[1],
                                              description="outer diameter [mm]")]
    inner_diameter_mm: Annotated[float, Field(ge=0.0, le=_DIAMETER_MM[1], description="bore of a hollow shaft "
                                                                                       "[mm], 0 for a solid one")] = 0.0

    @model_validator(mode="after")
    def _bore_inside(self):
        if self.inner_diameter_mm >= self.outer_diameter_mm:
            raise CaseError("drivetrain.shafts.segments.inner_diameter_mm", self.inner_diameter_mm,
                            f"[0, {self.outer_diameter_mm:g}) mm", "the bore must be smaller than the outer diameter")
        return self


class ShaftSection(Section):
    """A shaft along +z: its segments, its material (default the case's [material]) and its warm temperature."""

    name: _NAME
    segments: Annotated[list[ShaftSegmentSection], Field(min_length=1, max_length=100, description=(
        "uniform pieces from the first end, tables of length_mm, outer_diameter_mm, inner_diameter_mm (0: solid)"))]
    youngs_modulus_gpa: Annotated[float, Field(ge=1.0, le=1000.0, description=(
        "Young's modulus at 20 °C [GPa]; default the case's material"))] | None = None
    poisson_ratio: Annotated[float, Field(gt=0.0, lt=0.5, description=(
        "Poisson's ratio; default the case's material"))] | None = None
    density_kg_m3: Annotated[float, Field(ge=500.0, le=25_000.0, description=(
        "density [kg/m³]; default the case's material"))] | None = None
    material_damping_s: Annotated[float, Field(ge=0.0, le=1e-3, description=(
        "stiffness-proportional damping β of the shaft material [s] (ζ = βω/2 in each shaft mode)"))] = 0.0
    temperature_c: Annotated[float, Field(ge=-50.0, le=200.0, description=(
        "shaft temperature of the warm state [°C] (E(T) of the shaft); default the gears' mean tooth temperature"
    ))] | None = None

    @property
    def length_mm(self) -> float:
        """Total length [mm]."""
        return sum(segment.length_mm for segment in self.segments)

    def outer_diameter_at(self, position_mm: float) -> float:
        """Outer diameter [mm] at a position (the larger one at a segment boundary)."""
        start, found = 0.0, 0.0
        for segment in self.segments:
            if start - 1e-9 <= position_mm <= start + segment.length_mm + 1e-9:
                found = max(found, segment.outer_diameter_mm)
            start += segment.length_mm
        return found


class PointSection(Section):
    """A point on a shaft: the shaft's name and the position from its first end [mm]."""

    shaft: _SHAFT
    position_mm: _POSITION


class BearingSection(Section):
    """A linear bearing from a shaft point to the (rigid) housing: stiffness and damping per direction."""

    name: _NAME
    shaft: _SHAFT
    position_mm: _POSITION
    stiffness_x_n_per_m: Annotated[float, Field(ge=_STIFFNESS_N_PER_M[0], le=_STIFFNESS_N_PER_M[1],
                                                description="radial stiffness in x [N/m]")]
    stiffness_y_n_per_m: Annotated[float, Field(ge=_STIFFNESS_N_PER_M[0], le=_STIFFNESS_N_PER_M[1],
                                                description="radial stiffness in y [N/m]")]
    stiffness_z_n_per_m: Annotated[float, Field(ge=_STIFFNESS_N_PER_M[0], le=_STIFFNESS_N_PER_M[1], description=(
        "axial stiffness [N/m]; > 0 on the bearing that locates the shaft axially"))] = 0.0
    damping_x_n_s_per_m: Annotated[float, Field(ge=_DAMPING[0], le=_DAMPING[1],
                                                description="radial damping in x [N·s/m]")] = 0.0
    damping_y_n_s_per_m: Annotated[float, Field(ge=_DAMPING[0], le=_DAMPING[1],
                                                description="radial damping in y [N·s/m]")] = 0.0
    damping_z_n_s_per_m: Annotated[float, Field(ge=_DAMPING[0], le=_DAMPING[1],
                                                description="axial damping [N·s/m]")] = 0.0
    radial_clearance_um: Annotated[float, Field(ge=0.0, le=1000.0, description=(
        "radial clearance [μm]: the shaft moves freely within ± this of the bearing centre in x and in y (a "
        "square dead zone); 0 (the default) is the bearing in permanent contact; above 0 only with the nonlinear "
        "mesh (dynamics.mesh), whose backlash solver takes the clearance; with the gearbox thermal model it "
        "changes with the ring temperatures (docs/gearbox-temperature.md)"))] = 0.0
    tilting_stiffness_n_m_per_rad: Annotated[float, Field(ge=0.0, le=1e12, description=(
        "stiffness against the shaft's tilt at the bearing [N·m/rad], about x and about y (a wide or paired "
        "bearing); 0, the default, lets the shaft tilt freely there. Its moment is reported per bearing"))] = 0.0
    loss: BearingLossSection | None = Field(None, description=(
        "the bearing's loss-model data for the gearbox thermal model: { designation = 'NJ406' } or type, bore_mm, "
        "outside_mm, width_mm, rolling_constant, sliding_constants, geometry_constant, drag_variable; optional "
        "outer_raceway_diameter_mm. Its radial load is the drivetrain's static bearing force"))

    @model_validator(mode="after")
    def _loss_data(self):
        if self.loss is not None:
            check_loss_data(self.loss, f"drivetrain.bearings '{self.name}'.loss")
        return self


class DiskSection(Section):
    """A rigid body on a shaft: a motor rotor, a load, a coupling hub (the gear bodies come from the gears)."""

    name: _NAME
    shaft: _SHAFT
    position_mm: _POSITION
    mass_kg: Annotated[float, Field(ge=0.0, le=1e6, description="mass [kg]")]
    polar_inertia_kg_m2: Annotated[float, Field(ge=0.0, le=1e6, description="polar moment of inertia [kg·m²]")]
    diametral_inertia_kg_m2: Annotated[float, Field(ge=0.0, le=1e6, description=(
        "diametral moment of inertia [kg·m²]; default half the polar one (a thin disk)"))] | None = None


class CouplingSection(Section):
    """A coupling between two shaft points: torsional spring and dashpot, optional lateral and angular springs."""

    name: _NAME
    shaft_1: _SHAFT
    position_1_mm: _POSITION
    shaft_2: _SHAFT
    position_2_mm: _POSITION
    torsional_stiffness_n_m_per_rad: Annotated[float, Field(gt=0.0, le=_TORSIONAL_N_M_PER_RAD[1],
                                                            description="torsional stiffness [N·m/rad]")]
    torsional_damping_n_m_s_per_rad: Annotated[float, Field(ge=0.0, le=_DAMPING[1],
                                                            description="torsional damping [N·m·s/rad]")] = 0.0
    lateral_stiffness_n_per_m: Annotated[float, Field(ge=0.0, le=_STIFFNESS_N_PER_M[1],
                                                      description="radial stiffness [N/m]")] = 0.0
    angular_stiffness_n_m_per_rad: Annotated[float, Field(ge=0.0, le=_TORSIONAL_N_M_PER_RAD[1], description=(
        "bending (tilt) stiffness [N·m/rad]"))] = 0.0


class EndSection(Section):
    """How one end of the train is driven or braked: ``"torque"`` (a constant torque, the train turns freely) or
    ``"speed"`` (a motor held at speed by its controller: a torsional spring and dashpot to ground at a point)."""

    kind: Literal["torque", "speed"] = Field("torque", description="'torque': constant torque; 'speed': a motor "
                                                                   "held at speed (torsional support)")
    shaft: _SHAFT | None = None
    position_mm: _POSITION | None = None
    stiffness_n_m_per_rad: Annotated[float, Field(gt=0.0, le=_TORSIONAL_N_M_PER_RAD[1], description=(
        "'speed': the speed loop as a torsional spring to ground [N·m/rad] (from the drive's controller gains)"
    ))] | None = None
    damping_n_m_s_per_rad: Annotated[float, Field(ge=0.0, le=_DAMPING[1], description=(
        "'speed': the speed loop's damping [N·m·s/rad]"))] = 0.0


class StageSection(Section):
    """A further gear pair (stage) of the train: its gears (the keys of [gears]), where its pinion (the driving
    gear) and wheel sit, its centre line and its mesh phase. Its pinion sits on a shaft the train already drives;
    its turning sense follows from that shaft's. Lubricant, temperatures, thermal and damping models are the case's."""

    name: _NAME
    gears: GearsSection = Field(description="the stage's gear pair: the keys of [gears] (module_mm, teeth, …)")
    pinion: PointSection = Field(description="where the stage's pinion (driving gear) sits (shaft and position [mm])")
    wheel: PointSection = Field(description="where the stage's wheel sits (shaft and position [mm])")
    centre_line_angle_deg: Annotated[float, Field(ge=-360.0, le=360.0, description=(
        "direction from the stage's pinion centre to its wheel's [°], from +x towards +y"))] = 0.0
    mesh_phase: Annotated[float, Field(ge=0.0, lt=1.0, description=(
        "fraction of its mesh cycle this stage has passed when the first stage's starts [-] (set by how the gears "
        "were clocked at assembly; 0 unless known)"))] = 0.0


class DrivetrainSection(Section):
    """The pair on its shafts, bearings, couplings and inertias; ends driven by torque or held at speed."""

    pinion: PointSection = Field(description="where the pinion sits (shaft and position [mm])")
    wheel: PointSection = Field(description="where the wheel sits (shaft and position [mm])")
    centre_line_angle_deg: Annotated[float, Field(ge=-360.0, le=360.0, description=(
        "direction from the pinion's centre to the wheel's [°], from +x towards +y"))] = 0.0
    pinion_rotation: Literal["counter-clockwise", "clockwise"] = Field(
        "counter-clockwise", description="the pinion's turning sense about +z")
    helical_contact: Literal["point", "spread"] = Field("point", description=(
        "where a mesh's stiffness acts across the face: 'point' (the default) a constant normal stiffness at the "
        "operating pitch point at mid-face, as other rotordynamics tools have; 'spread' the stiffness spread "
        "across the face: a helical mesh's load centre and tilting stiffness from its slices, varying over the "
        "mesh period (a spur face's are constant, k̄·b²/12 about mid-face) (docs/helical.md, 'The variation over "
        "the period in the drivetrain'); applies to every mesh, spur ones too"))
    maximum_element_length_mm: Annotated[float, Field(ge=1.0, le=2000.0, description=(
        "longest shaft element [mm] (nodes are also placed at every attachment)"))] = 25.0
    response_cutoff_hz: Annotated[float, Field(ge=100.0, le=1e7, description=(
        "the periodic response is solved on the modes up to this frequency [Hz] plus the static corrections "
        "(modal reduction; the mesh compliance stays exact)"))] = 60_000.0
    sweep_points_per_period: Annotated[int, Field(ge=16, le=100_000, description=(
        "mesh-grid intervals per mesh period in a speed sweep of the drivetrain (run uses [dynamics] "
        "points_per_period); the first mesh harmonics converge with far fewer than a run's 1024"))] = 128
    mode_count: Annotated[int, Field(ge=1, le=200, description="lowest modes reported")] = 12
    bearing_harmonics: Annotated[int, Field(ge=1, le=20, description=(
        "mesh harmonics of the bearing forces reported"))] = 3
    shafts: Annotated[list[ShaftSection], Field(min_length=2, max_length=50, description=(
        "[[drivetrain.shafts]] tables: name, segments (length_mm, outer_diameter_mm, inner_diameter_mm), optional "
        "youngs_modulus_gpa, poisson_ratio, density_kg_m3 (default the case's [material]), material_damping_s, "
        "temperature_c (warm state; default the gears' mean tooth temperature)"))]
    bearings: Annotated[list[BearingSection], Field(min_length=1, max_length=200, description=(
        "[[drivetrain.bearings]] tables: name, shaft, position_mm, stiffness_x_n_per_m, stiffness_y_n_per_m, "
        "optional stiffness_z_n_per_m (locates the shaft axially), damping_x_n_s_per_m, damping_y_n_s_per_m, "
        "damping_z_n_s_per_m, tilting_stiffness_n_m_per_rad, radial_clearance_um (≥ 0 μm, default 0; above 0 only with dynamics.mesh = "
        "'nonlinear'; with the gearbox thermal model it follows the ring temperatures), loss (the bearing's SKF "
        "loss data for the gearbox thermal model: { designation = 'NJ406' } or type, bore_mm, outside_mm, "
        "width_mm, rolling_constant, sliding_constants, geometry_constant, drag_variable, and optionally "
        "outer_raceway_diameter_mm; its radial load is the static bearing force); at least two bearing positions "
        "per shaft"))]
    disks: Annotated[list[DiskSection], Field(max_length=200, description=(
        "one table per rigid disk: name, shaft, position_mm, mass_kg, polar_inertia_kg_m2, optional "
        "diametral_inertia_kg_m2 (default half the polar one); motor rotors, loads, hubs"))] = []
    couplings: Annotated[list[CouplingSection], Field(max_length=100, description=(
        "[[drivetrain.couplings]] tables: name, shaft_1, position_1_mm, shaft_2, position_2_mm, "
        "torsional_stiffness_n_m_per_rad, optional torsional_damping_n_m_s_per_rad, lateral_stiffness_n_per_m, "
        "angular_stiffness_n_m_per_rad"))] = []
    stages: Annotated[list[StageSection], Field(max_length=10, description=(
        "[[drivetrain.stages]] tables, further gear pairs after the case's [gears] (the first stage): name, gears "
        "(the keys of [gears]), pinion and wheel {shaft, position_mm}, optional centre_line_angle_deg, mesh_phase"
    ))] = []
    driving: EndSection = Field(EndSection(), description="the driving end (the pinion's side)")
    driven: EndSection = Field(EndSection(), description="the driven end (the wheel's side)")

    @model_validator(mode="after")
    def _consistent(self):
        check_drivetrain_section(self)
        return self


def _point_on_shaft(key: str, shaft_name: str, position_mm: float, shafts: dict[str, ShaftSection]) -> None:
    if shaft_name not in shafts:
        raise CaseError(f"{key}.shaft", shaft_name, f"one of {sorted(shafts)}",
                        "an element sits on a shaft named in [[drivetrain.shafts]]")
    length = shafts[shaft_name].length_mm
    if position_mm > length + 1e-9:
        raise CaseError(f"{key}.position_mm", position_mm, f"[0, {length:g}] mm (the length of '{shaft_name}')",
                        "the position must lie on the shaft")


def check_drivetrain_section(section: DrivetrainSection) -> None:
    """The checks that need several parts of [drivetrain]: names unique, every point on a named shaft and within
    its length, the gears on two shafts, every shaft held laterally, the speed-held ends complete."""
    shafts = {shaft.name: shaft for shaft in section.shafts}
    if len(shafts) != len(section.shafts):
        raise CaseError("drivetrain.shafts.name", [s.name for s in section.shafts], "unique names",
                        "elements find their shaft by name")
    names = [item.name for group in (section.bearings, section.disks, section.couplings, section.stages)
             for item in group]
    names += [f"{stage.name} {gear}" for stage in section.stages for gear in ("pinion", "wheel")]
    repeated = sorted({name for name in names if names.count(name) > 1} | (set(names) & set(shafts))
                      | (set(names) & {"pinion", "wheel", "mesh", "driving motor", "driven motor"}))
    if repeated:
        raise CaseError("drivetrain names", repeated,
                        "unique names, not a shaft's, and none of pinion, wheel, mesh, driving motor, driven motor "
                        "(nor a stage's name followed by pinion or wheel)",
                        "bearing forces and energy shares are reported by name")
    _point_on_shaft("drivetrain.pinion", section.pinion.shaft, section.pinion.position_mm, shafts)
    _point_on_shaft("drivetrain.wheel", section.wheel.shaft, section.wheel.position_mm, shafts)
    if section.pinion.shaft == section.wheel.shaft:
        raise CaseError("drivetrain.wheel.shaft", section.wheel.shaft, f"a shaft other than the pinion's",
                        "the mesh joins two shafts (parallel axes a centre distance apart)")
    for stage in section.stages:
        key = f"drivetrain.stages '{stage.name}'"
        _point_on_shaft(f"{key}.pinion", stage.pinion.shaft, stage.pinion.position_mm, shafts)
        _point_on_shaft(f"{key}.wheel", stage.wheel.shaft, stage.wheel.position_mm, shafts)
        if stage.pinion.shaft == stage.wheel.shaft:
            raise CaseError(f"{key}.wheel.shaft", stage.wheel.shaft, "a shaft other than the stage's pinion's",
                            "a mesh joins two shafts (parallel axes a centre distance apart)")
    for bearing in section.bearings:
        if bearing.stiffness_x_n_per_m == 0.0 and bearing.stiffness_y_n_per_m == 0.0:
            raise CaseError(f"drivetrain.bearings '{bearing.name}'.stiffness_x_n_per_m", 0.0,
                            "> 0 in x or in y (a rolling bearing: 1e7–1e9 N/m)",
                            "a bearing without radial stiffness holds nothing: remove it or give its stiffness")
        _point_on_shaft(f"drivetrain.bearings '{bearing.name}'", bearing.shaft, bearing.position_mm, shafts)
    for disk in section.disks:
        _point_on_shaft(f"drivetrain.disks '{disk.name}'", disk.shaft, disk.position_mm, shafts)
    for coupling in section.couplings:
        key = f"drivetrain.couplings '{coupling.name}'"
        _point_on_shaft(key, coupling.shaft_1, coupling.position_1_mm, shafts)
        _point_on_shaft(key, coupling.shaft_2, coupling.position_2_mm, shafts)
        if coupling.shaft_1 == coupling.shaft_2:
            raise CaseError(f"{key}.shaft_2", coupling.shaft_2, "a shaft other than shaft_1",
                            "a coupling joins two shafts")
    for shaft in section.shafts:
        coupled = any(c.lateral_stiffness_n_per_m > 0.0 and c.angular_stiffness_n_m_per_rad > 0.0
                      for c in section.couplings if shaft.name in (c.shaft_1, c.shaft_2))
        for direction in ("x", "y"):  # a bearing counts in a direction where it is stiff
            held = {round(b.position_mm, 6) for b in section.bearings
                    if b.shaft == shaft.name and getattr(b, f"stiffness_{direction}_n_per_m") > 0.0}
            if len(held) < 2 and not coupled:
                raise CaseError(f"drivetrain.bearings (shaft '{shaft.name}') stiffness_{direction}_n_per_m",
                                len(held), f">= 2 bearings stiff in {direction} at different positions (or a coupling "
                                "with lateral and angular stiffness)",
                                "with fewer the shaft could tilt or move sideways freely: no static state")
    for end_key, end in (("driving", section.driving), ("driven", section.driven)):
        key = f"drivetrain.{end_key}"
        if END_KINDS[end.kind].held_at_speed:
            if end.shaft is None or end.position_mm is None or end.stiffness_n_m_per_rad is None:
                raise CaseError(f"{key}.stiffness_n_m_per_rad", end.stiffness_n_m_per_rad,
                                "shaft, position_mm and stiffness_n_m_per_rad > 0 with kind = 'speed'",
                                "a motor held at speed is a torsional spring to ground at a point of a shaft")
            _point_on_shaft(key, end.shaft, end.position_mm, shafts)
        elif end.stiffness_n_m_per_rad is not None or end.damping_n_m_s_per_rad:
            raise CaseError(f"{key}.stiffness_n_m_per_rad", end.stiffness_n_m_per_rad, "absent with kind = 'torque'",
                            "a constant torque holds no speed: give kind = 'speed' for a motor held at speed")
        elif end.shaft is not None:
            _point_on_shaft(key, end.shaft, end.position_mm or 0.0, shafts)


def check_drivetrain_fits_gears(section: DrivetrainSection, bore_radii_mm: tuple[float, float],
                                root_radii_mm: tuple[float, float], extra: tuple = ()) -> None:
    """Each gear's shaft seat fits its bore (when the case gives a bore) and stays inside its root circle;
    ``extra``: (key, point, bore, root radius [mm]) of the further stages' gears."""
    shafts = {shaft.name: shaft for shaft in section.shafts}
    for key, point, bore, root in (("pinion", section.pinion, bore_radii_mm[0], root_radii_mm[0]),
                                   ("wheel", section.wheel, bore_radii_mm[1], root_radii_mm[1]),
                                   *extra):
        seat = shafts[point.shaft].outer_diameter_at(point.position_mm)
        limit = 2.0 * bore if bore > 0.0 else 2.0 * root
        if seat > limit * (1.0 + 1e-9):
            what = f"the bore diameter {limit:g} mm (gears.{key}.bore_radius_mm)" if bore > 0.0 else \
                f"the root diameter {limit:.3f} mm"
            raise CaseError(f"drivetrain.shafts '{point.shaft}' outer_diameter_mm", seat, f"<= {what}",
                            f"the {key} sits on this shaft at {point.position_mm:g} mm: its seat must fit the gear")


__all__ = ["BearingSection", "CouplingSection", "DiskSection", "DrivetrainSection", "EndSection", "PointSection",
           "ShaftSection", "ShaftSegmentSection", "StageSection", "check_drivetrain_fits_gears",
           "check_drivetrain_section"]
