"""The further stages of a case's gear train as operating points of their own pairs.

Each stage ([[drivetrain.stages]]) is a gear pair with its own pair model and mesh model, built like the case's
first pair from the case's material, lubricant, temperatures, thermal and damping models: its case is the case with
the stage's pair, its pinion's speed n_p = |ρ|·n_1 (ρ the signed speed ratio of the shaft its pinion sits on, an
exact fraction of the tooth counts) and the torque T_p = T_1/|ρ| that an ideal (lossless) train passes on, held as
the case holds its own load (constant torque or constant power). Its mesh frequency relative to the first stage's,
ν = z_p·|ρ|/z_1, is exact, and so is the common period of the train (:mod:`thermogear.drivetrain.train`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from fractions import Fraction

from thermogear.case_geometry import helical_pair_of
from thermogear.drivetrain.train import common_period_repeats
from thermogear.schema.drivetrain_topology import shaft_speed_ratios

__all__ = ["StageTrain", "stage_train"]


@dataclass(frozen=True)
class StageTrain:
    """The further stages of a train: ``cases`` (a case per stage, for its mesh models), ``speeds`` |ρ| of each
    stage's pinion per unit input speed, and over the common period the ``repeats`` L_m and ``phases`` γ_m of every
    mesh, the first included (one mesh: (1,), (0.0,))."""

    cases: tuple = ()
    speeds: tuple[float, ...] = ()
    repeats: tuple[int, ...] = (1,)
    phases: tuple[float, ...] = (0.0,)


def stage_train(case) -> StageTrain:
    """The resolver of a case's further stages (module docstring); an empty train without stages."""
    section = case.drivetrain
    if section is None or not case.stages:
        return StageTrain()
    first = case.gear_pair
    ratios = shaft_speed_ratios(section, (first.pinion.teeth, first.wheel.teeth))
    cases, speeds, relative = [], [], [Fraction(1)]
    operating = case.operating_point
    for stage, stage_section in zip(case.stages, section.stages):
        factor = abs(ratios[stage_section.pinion.shaft])
        speeds.append(float(factor))
        relative.append(Fraction(stage.gear_pair.pinion.teeth) * factor / first.pinion.teeth)
        stage_operating = replace(operating, speed_rpm=operating.speed_rpm * float(factor),
                                  torque=operating.torque / float(factor))
        helical = helical_pair_of(stage.gears_input)  # a stage's own helix (its mesh state and mesh element)
        cases.append(replace(case, gear_pair=stage.gear_pair, gears_input=stage.gears_input,
                             roughness_ra=stage.roughness_ra, operating_point=stage_operating, inertias=None,
                             drivetrain=None, stages=(), helical_pair=helical if helical.helix_angle > 0.0 else None))
    phases = (0.0, *(float(stage.mesh_phase) for stage in section.stages))
    return StageTrain(tuple(cases), tuple(speeds), common_period_repeats(relative), phases)
