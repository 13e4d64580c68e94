"""The further stages of a case's gear train as operating points of their own pairs.

Each stage ([[drivetrain.stages]]) is a gear pair with its own pair model and mesh model, built like the case's
first pair from the case's material, lubricant, temperatures, thermal and damping models: its case is the case with
the stage's pair (the changes :func:`stage_train` resolves, written into the case by the drivetrain's resolver), its pinion's speed n_p = |ρ|·n_1 (ρ the signed speed ratio of the shaft its pinion sits on, an
exact fraction of the tooth counts) and the torque T_p = T_1/|ρ| that an ideal (lossless) train passes on, held as
the case holds its own load (constant torque or constant power). Its mesh frequency relative to the first stage's,
ν = z_p·|ρ|/z_1, is exact, and so is the common period of the train (:mod:`thermogear.drivetrain.train`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from thermogear.case.gears import helical_pair_of
from thermogear.drivetrain.train import common_period_repeats
from thermogear.schema.drivetrain_topology import shaft_speed_ratios

if TYPE_CHECKING:
    from thermogear.case import GearStage
    from thermogear.geometry import GearPair
    from thermogear.operating import OperatingPoint
    from thermogear.schema.drivetrain import DrivetrainSection

__all__ = ["StageTrain", "stage_train"]


@dataclass(frozen=True)
class StageTrain:
    """The further stages of a train: ``case_changes`` (per stage, the parts of the case its own case replaces:
    its pair, gears, roughness, operating point and helix, for its mesh models; ``replace(case, **changes)``),
    ``speeds`` |ρ| of each stage's pinion per unit input speed, and over the common period the ``repeats`` L_m and
    ``phases`` γ_m of every mesh, the first included (one mesh: (1,), (0.0,))."""

    case_changes: tuple[dict[str, Any], ...] = ()
    speeds: tuple[float, ...] = ()
    repeats: tuple[int, ...] = (1,)
    phases: tuple[float, ...] = (0.0,)


def stage_train(drivetrain: "DrivetrainSection | None", stages: "tuple[GearStage, ...]", gear_pair: "GearPair",
                operating_point: "OperatingPoint") -> StageTrain:
    """The further stages of a case's train (module docstring) from the pieces of the case it reads (its
    ``[drivetrain]`` section and built stages, first pair and operating point); an empty train without stages."""
    section = drivetrain
    if section is None or not stages:
        return StageTrain()
    first = gear_pair
    ratios = shaft_speed_ratios(section, (first.pinion.teeth, first.wheel.teeth))
    changes, speeds, relative = [], [], [Fraction(1)]
    for stage, stage_section in zip(stages, section.stages):
        factor = abs(ratios[stage_section.pinion.shaft])
        speeds.append(float(factor))
        relative.append(Fraction(stage.gear_pair.pinion.teeth) * factor / first.pinion.teeth)
        stage_operating = replace(operating_point, speed_rpm=operating_point.speed_rpm * float(factor),
                                  torque=operating_point.torque / float(factor))
        helical = helical_pair_of(stage.gears_input)  # a stage's own helix (its mesh state and mesh element)
        changes.append(dict(gear_pair=stage.gear_pair, gears_input=stage.gears_input, roughness_ra=stage.roughness_ra,
                            operating_point=stage_operating, inertias=None, drivetrain=None, stages=(),
                            helical_pair=helical if helical.helix_angle > 0.0 else None))
    phases = (0.0, *(float(stage.mesh_phase) for stage in section.stages))
    return StageTrain(tuple(changes), tuple(speeds), common_period_repeats(relative), phases)
