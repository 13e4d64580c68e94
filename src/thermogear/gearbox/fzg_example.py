"""The FZG test gearbox for examples, tests and benchmarks: the built-in parameter set ``fzg_test_gearbox`` (FZG
type C gears, ISO 14635-1, in a dip-lubricated housing) resolved into a :class:`GearboxDescription`. One
description, one place: the parameter set (``src/thermogear/parameter_sets/fzg_test_gearbox.toml``) holds every
value with its source or as an assumption; this module only reads it. The gears and the oil fill are the rig's;
the housing, the masses of shafts and housing, the bearing arrangement and the internal heat-transfer coefficients
are ASSUMED (the set's assumptions, repeated in ``notes``): a plausible gearbox of that size, not a model of the
FZG rig calibrated on measurements.
"""

from __future__ import annotations

import math
from dataclasses import replace

from thermogear.gearbox.description import GearboxDescription
from thermogear.geometry import Gear, GearPair

#: The built-in parameter set of the FZG test gearbox.
PARAMETER_SET = "fzg_test_gearbox"


def fzg_type_c_pair() -> GearPair:
    """FZG type C: m 4.5 mm, z 16/24, x 0.1817/0.1715, b 14 mm, a 91.5 mm, α 20° (ISO 14635-1), tips with the
    ISO 21771 tip shortening; bores 15 mm (30 mm shafts) — the pair of the parameter set."""
    pinion = Gear(16, 4.5e-3, math.radians(20.0), 14e-3, 0.1817, bore_radius=15e-3)
    wheel = Gear(24, 4.5e-3, math.radians(20.0), 14e-3, 0.1715, bore_radius=15e-3)
    return GearPair.create(pinion, wheel, 91.5e-3)


def fzg_test_gearbox_case():
    """The parameter set ``fzg_test_gearbox`` as a loaded case."""
    from thermogear.case import load_case  # noqa: PLC0415

    return load_case(PARAMETER_SET)


def illustrative_fzg_gearbox(**changes) -> GearboxDescription:
    """The FZG test gearbox of the parameter set (module docstring); keyword arguments replace description
    fields."""
    from thermogear.gearbox.case_model import gearbox_model_from_case  # noqa: PLC0415

    case = fzg_test_gearbox_case()
    description = replace(gearbox_model_from_case(case).description, notes=tuple(case.assumptions))
    return replace(description, **changes) if changes else description
