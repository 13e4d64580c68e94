"""The gear pair in its drivetrain: Timoshenko shaft elements, rigid disks, bearings, couplings, torsional supports
and the spur mesh element along the line of action, assembled into global matrices (6 DOF per node)."""

from thermogear.drivetrain.assembly import DOF_NAMES, AssembledDrivetrain, Drivetrain
from thermogear.drivetrain.layout import Shaft, ShaftSegment
from thermogear.drivetrain.mesh_element import GearMesh
from thermogear.drivetrain.point_elements import Bearing, Coupling, NodeLocation, RigidDisk, TorsionalSupport
from thermogear.drivetrain.section import (CrossSection, Material, cowper_shear_coefficient,
                                           hutchinson_shear_coefficient)
from thermogear.drivetrain.shaft_element import ShaftElement

__all__ = ["DOF_NAMES", "AssembledDrivetrain", "Bearing", "Coupling", "CrossSection", "Drivetrain", "GearMesh",
           "Material", "NodeLocation", "RigidDisk", "Shaft", "ShaftElement", "ShaftSegment", "TorsionalSupport",
           "cowper_shear_coefficient", "hutchinson_shear_coefficient"]
