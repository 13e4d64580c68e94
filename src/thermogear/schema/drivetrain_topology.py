"""The drivetrain of a case as a train: which shafts turn at which speed, checked at load.

The speed of every shaft relative to the first stage's pinion follows from the meshes (an external mesh: −z_p/z_w)
and the couplings (equal speeds) as exact fractions of the tooth counts. A shaft that no mesh or coupling joins to the
train, a link that contradicts the ratios the others fix (a coupling between two meshing shafts), a stage whose pinion
the train does not drive and a disk far heavier than the gears are refused here, by the checks every command runs.
"""

from __future__ import annotations

from fractions import Fraction

from thermogear.errors import CaseError
from thermogear.schema.drivetrain import DrivetrainSection

__all__ = ["MAXIMUM_DISK_INERTIA_RATIO", "check_drivetrain_train", "shaft_speed_ratios"]


#: Largest polar inertia of a disk over the smallest gear's [-]. Beyond it the disk turns less than a millionth of
#: the gears' angle at every mesh frequency — a fixed end — while the mass matrix spans more than six decades, so the
#: shooting of the backlash orbit loses its Newton steps (a 1e6 kg·m² disk gave "no orbit" where the linear solver
#: said "stable", issue 36). A limit chosen here: model such an end as held at speed (drivetrain.driving/driven).
MAXIMUM_DISK_INERTIA_RATIO = 1e6


def check_drivetrain_train(section: DrivetrainSection, first_teeth: tuple[int, int],
                           gear_inertias: list[tuple[str, float]]) -> None:
    """The train as a whole: every shaft joined to the first stage's pinion shaft through meshes and couplings,
    each stage's pinion on a shaft the train already drives, no coupling (or mesh) between shafts whose speeds the
    meshes already fix to differ (the ratios are exact fractions of the tooth counts ``first_teeth`` and the
    stages'), and no disk with more than :data:`MAXIMUM_DISK_INERTIA_RATIO` times the smallest gear's polar
    inertia (``gear_inertias``: (gear, kg·m²))."""
    ratios = {section.pinion.shaft: Fraction(1)}
    links = [("drivetrain.wheel", section.pinion.shaft, section.wheel.shaft, Fraction(-first_teeth[0], first_teeth[1]))]
    links += [(f"drivetrain.stages '{stage.name}'", stage.pinion.shaft, stage.wheel.shaft,
               Fraction(-stage.gears.pinion.teeth, stage.gears.wheel.teeth)) for stage in section.stages]
    links += [(f"drivetrain.couplings '{coupling.name}'", coupling.shaft_1, coupling.shaft_2, Fraction(1))
              for coupling in section.couplings]
    couplings = links[1 + len(section.stages):]
    for index, stage in enumerate(section.stages):  # stages in order: each pinion on a shaft already driven
        reached = _propagate(dict(ratios), links[:1 + index] + couplings)
        if stage.pinion.shaft not in reached:
            raise CaseError(f"drivetrain.stages '{stage.name}'.pinion.shaft", stage.pinion.shaft,
                            f"a shaft the train already drives ({', '.join(sorted(reached))})",
                            "a stage's pinion is driven by the stages before it")
    reached = _propagate(ratios, links)
    loose = [shaft.name for shaft in section.shafts if shaft.name not in reached]
    if loose:
        raise CaseError("drivetrain.shafts", loose, "every shaft joined to the pinion's by meshes or couplings",
                        "a shaft joined to nothing neither turns with the train nor carries its load")
    smallest = min(gear_inertias, key=lambda item: item[1])
    for disk in section.disks:
        if disk.polar_inertia_kg_m2 > MAXIMUM_DISK_INERTIA_RATIO * smallest[1]:
            raise CaseError(f"drivetrain.disks '{disk.name}'.polar_inertia_kg_m2", disk.polar_inertia_kg_m2,
                            f"<= {MAXIMUM_DISK_INERTIA_RATIO:.0e} × the {smallest[0]}'s {smallest[1]:.3g} kg·m²",
                            "such a disk is a fixed end to the gears and beyond the solvers' precision: hold that "
                            "end at speed instead (drivetrain.driving or driven, kind = 'speed')")


def shaft_speed_ratios(section: DrivetrainSection, first_teeth: tuple[int, int]) -> dict[str, Fraction]:
    """Each shaft's speed over the first stage's pinion's, signed (an external mesh turns the other way), as exact
    fractions of the tooth counts (a checked section: every shaft reached, no conflict)."""
    links = [("drivetrain.wheel", section.pinion.shaft, section.wheel.shaft, Fraction(-first_teeth[0], first_teeth[1]))]
    links += [(f"drivetrain.stages '{stage.name}'", stage.pinion.shaft, stage.wheel.shaft,
               Fraction(-stage.gears.pinion.teeth, stage.gears.wheel.teeth)) for stage in section.stages]
    links += [(f"drivetrain.couplings '{coupling.name}'", coupling.shaft_1, coupling.shaft_2, Fraction(1))
              for coupling in section.couplings]
    return _propagate({section.pinion.shaft: Fraction(1)}, links)


def _propagate(ratios: dict, links: list) -> dict:
    """Spread the speed ratios (Fractions) over the links (key, shaft 1, shaft 2, ω₂/ω₁); refuse a link whose two
    shafts already turn at speeds it contradicts."""
    changed = True
    while changed:
        changed = False
        for key, one, two, ratio in links:
            if one in ratios and two not in ratios:
                ratios[two], changed = ratios[one] * ratio, True
            elif two in ratios and one not in ratios:
                ratios[one], changed = ratios[two] / ratio, True
            elif one in ratios and two in ratios and ratios[two] != ratios[one] * ratio:
                raise CaseError(key, f"{one} → {two}",
                                f"shafts turning at the ratio the link imposes ({ratio}; the meshes give "
                                f"{ratios[two] / ratios[one]})",
                                "a link between shafts whose speeds the gears already fix to differ would jam the "
                                "train (conflicting speed ratios)")
    return ratios
