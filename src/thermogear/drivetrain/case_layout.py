"""The drivetrain of a case file: the validated ``[drivetrain]`` section, the case's gear pair and a mean mesh
stiffness → a :class:`~thermogear.drivetrain.assembly.Drivetrain`.

Units: the section's millimetres, GPa and kg/m³ become SI here. The shaft carrying the pinion is put first (the
reference speed is the pinion's). The gear bodies are not typed in: each is a uniform annulus (Friswell et al. 2010,
App. 1) of the gear's operating pitch diameter and face width (the teeth fill about half the tooth zone, so the pitch
circle stands for the toothed rim, as the 1-DOF model's discs do), around the larger of the gear's bore and its
shaft seat; where the case gives the gears' ``inertia_kg_m2``, that is the polar inertia. The ends: a constant
torque adds nothing (the train turns freely and the rigid rotation is removed by the solvers); a motor held at
speed is a :class:`~thermogear.drivetrain.point_elements.TorsionalSupport` at its point.
"""

from __future__ import annotations

import math

from thermogear.drivetrain.assembly import Drivetrain
from thermogear.drivetrain.layout import Shaft, ShaftSegment
from thermogear.drivetrain.mesh_contact import mesh_contact
from thermogear.drivetrain.mesh_element import GearMesh
from thermogear.drivetrain.point_elements import Bearing, Coupling, NodeLocation, RigidDisk, TorsionalSupport
from thermogear.drivetrain.section import CrossSection, Material
from thermogear.choices.drivetrain import END_KINDS, ROTATIONS
from thermogear.schema.drivetrain_topology import shaft_speed_ratios

__all__ = ["drivetrain_from_section", "MESH_NAME"]

#: Name of the mesh element in the drivetrain (energy shares, heat attribution).
MESH_NAME = "mesh"

_MM = 1e-3
_MICROMETRE = 1e-6


def _shaft(section, material) -> tuple[Material, tuple[ShaftSegment, ...]]:
    """The material and segments of one shaft: the shaft's own keys over the case's [material]."""
    youngs = (section.youngs_modulus_gpa * 1e9 if section.youngs_modulus_gpa is not None
              else material.youngs_modulus)
    poisson = section.poisson_ratio if section.poisson_ratio is not None else material.poisson_ratio
    density = section.density_kg_m3 if section.density_kg_m3 is not None else material.density
    shaft_material = Material(youngs_modulus=youngs, density=density, poisson_ratio=poisson)
    return shaft_material, tuple(ShaftSegment(segment.length_mm * _MM,
                                              CrossSection(segment.outer_diameter_mm * _MM,
                                                           segment.inner_diameter_mm * _MM), shaft_material)
                                 for segment in section.segments)


def _gear_body(name: str, point, gear, pitch_radius: float, seat_diameter: float, density: float,
               polar_inertia: float | None) -> RigidDisk:
    location = NodeLocation(point.shaft, point.position_mm * _MM)
    inner = max(2.0 * gear.bore_radius, seat_diameter)
    disk = RigidDisk.annulus(name, location, density, gear.face_width, 2.0 * pitch_radius, inner)
    if polar_inertia is None:
        return disk
    # the case's polar inertia; the diametral one of the same body: I_p/2 + m b²/12 (thin-disk relation)
    diametral = polar_inertia / 2.0 + disk.mass * gear.face_width**2 / 12.0
    return RigidDisk(name, location, disk.mass, polar_inertia, diametral)


def drivetrain_from_section(section, pair, material, mesh_stiffness: float, mesh_damping: float = 0.0,
                            inertias: tuple[float, float] | None = None, stages: tuple = (),
                            helices: tuple[tuple[float, int], ...] = ()) -> Drivetrain:
    """The drivetrain of a ``[drivetrain]`` section (:class:`~thermogear.schema.drivetrain.DrivetrainSection`)
    around ``pair`` (a :class:`~thermogear.geometry.GearPair`: base radii, operating pressure angle and pitch radii,
    bores, face widths) with the case's ``material`` (E [Pa], ν, ρ [kg/m³]; the gear bodies' density and the
    shafts' default), the mean mesh stiffness [N/m] and damping [N·s/m], and the gears' polar ``inertias``
    [kg·m²] where the case gives them. ``stages``: per further stage of ``section.stages``, (its pair, mean mesh
    stiffness [N/m], mean damping [N·s/m]); its mesh is named after the stage, its gear bodies "<stage> pinion" and
    "<stage> wheel", and its turning sense follows from the shaft its pinion sits on. ``helices``: per mesh (the
    case's pair first, then the stages), its base helix angle β_b [rad] and its pinion's hand (+1 right, −1 left);
    missing ones are spur. Every mesh takes the section's ``helical_contact`` option
    (:data:`~thermogear.drivetrain.mesh_contact.MESH_CONTACTS`) and its pair's common face width."""
    contact = mesh_contact(section.helical_contact)
    helices = tuple(helices) + ((0.0, 1),) * (1 + len(stages) - len(helices))

    def helical(index: int, mesh_pair) -> dict:
        base_helix, hand = helices[index]
        return {"base_helix_angle": base_helix, "hand": hand, "contact": contact,
                "face_width": min(mesh_pair.pinion.face_width, mesh_pair.wheel.face_width)}

    ordered = sorted(section.shafts, key=lambda shaft: shaft.name != section.pinion.shaft)  # pinion shaft first
    shafts = []
    for shaft_section in ordered:
        _, segments = _shaft(shaft_section, material)
        shafts.append(Shaft(shaft_section.name, segments, section.maximum_element_length_mm * _MM,
                            material_damping=shaft_section.material_damping_s))
    by_name = {shaft.name: shaft for shaft in section.shafts}
    pitch_1, pitch_2 = pair.operating_pitch_radii
    bodies = []
    for index, (name, point, gear, pitch) in enumerate((("pinion", section.pinion, pair.pinion, pitch_1),
                                                        ("wheel", section.wheel, pair.wheel, pitch_2))):
        seat = by_name[point.shaft].outer_diameter_at(point.position_mm) * _MM
        bodies.append(_gear_body(name, point, gear, pitch, seat, material.density,
                                 None if inertias is None else inertias[index]))
    speeds = shaft_speed_ratios(section, (pair.pinion.teeth, pair.wheel.teeth)) if stages else {}
    sense = ROTATIONS[section.pinion_rotation].sense
    stage_meshes = []
    for number, (stage_section, (stage_pair, stiffness, damping)) in enumerate(zip(section.stages, stages)):
        pitch_1, pitch_2 = stage_pair.operating_pitch_radii
        for gear_name, point, gear, pitch in (("pinion", stage_section.pinion, stage_pair.pinion, pitch_1),
                                              ("wheel", stage_section.wheel, stage_pair.wheel, pitch_2)):
            seat = by_name[point.shaft].outer_diameter_at(point.position_mm) * _MM
            bodies.append(_gear_body(f"{stage_section.name} {gear_name}", point, gear, pitch, seat, material.density,
                                     None))
        stage_meshes.append(GearMesh(
            stage_section.name, NodeLocation(stage_section.pinion.shaft, stage_section.pinion.position_mm * _MM),
            NodeLocation(stage_section.wheel.shaft, stage_section.wheel.position_mm * _MM),
            stage_pair.pinion.base_radius, stage_pair.wheel.base_radius, stage_pair.operating_pressure_angle,
            stiffness, damping, math.radians(stage_section.centre_line_angle_deg),
            sense if speeds[stage_section.pinion.shaft] > 0 else -sense, **helical(number + 1, stage_pair)))
    disks = [RigidDisk(disk.name, NodeLocation(disk.shaft, disk.position_mm * _MM), disk.mass_kg,
                       disk.polar_inertia_kg_m2, disk.diametral_inertia_kg_m2
                       if disk.diametral_inertia_kg_m2 is not None else disk.polar_inertia_kg_m2 / 2.0)
             for disk in section.disks]
    bearings = [Bearing(b.name, NodeLocation(b.shaft, b.position_mm * _MM), b.stiffness_x_n_per_m,
                        b.stiffness_y_n_per_m, b.stiffness_z_n_per_m, b.damping_x_n_s_per_m, b.damping_y_n_s_per_m,
                        b.damping_z_n_s_per_m, radial_clearance=b.radial_clearance_um * _MICROMETRE,
                        tilting_stiffness=b.tilting_stiffness_n_m_per_rad)
                for b in section.bearings]
    couplings = [Coupling(c.name, NodeLocation(c.shaft_1, c.position_1_mm * _MM),
                          NodeLocation(c.shaft_2, c.position_2_mm * _MM), c.torsional_stiffness_n_m_per_rad,
                          c.torsional_damping_n_m_s_per_rad, c.lateral_stiffness_n_per_m,
                          c.angular_stiffness_n_m_per_rad) for c in section.couplings]
    supports = [TorsionalSupport(f"{end_name} motor", NodeLocation(end.shaft, end.position_mm * _MM),
                                 end.stiffness_n_m_per_rad, end.damping_n_m_s_per_rad)
                for end_name, end in (("driving", section.driving), ("driven", section.driven))
                if END_KINDS[end.kind].held_at_speed]
    mesh = GearMesh(MESH_NAME, NodeLocation(section.pinion.shaft, section.pinion.position_mm * _MM),
                    NodeLocation(section.wheel.shaft, section.wheel.position_mm * _MM), pair.pinion.base_radius,
                    pair.wheel.base_radius, pair.operating_pressure_angle, mesh_stiffness, mesh_damping,
                    math.radians(section.centre_line_angle_deg),
                    ROTATIONS[section.pinion_rotation].sense, **helical(0, pair))
    return Drivetrain(tuple(shafts), (*bodies, *disks), tuple(bearings), tuple(couplings), (mesh, *stage_meshes),
                      tuple(supports))
