"""What the finite-element verification reads of a case, resolved once (issue 26).

:func:`fem_inputs` is the one function of :mod:`thermogear.fem` that reads a whole case (besides the two
providers, whose protocol hands them the case); the heat, elastic and thermo-elastic tooth models and the
verification take the frozen :class:`FemInputs` it returns, or the gear pair, material and ``[fem]`` section in it.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from thermogear import warning_scope
from thermogear.errors import CaseError, ExtrapolationWarning

if TYPE_CHECKING:
    from thermogear.case import Case
    from thermogear.geometry import GearPair
    from thermogear.lubricant import Lubricant
    from thermogear.materials import Material
    from thermogear.mesh.model import MeshModel
    from thermogear.schema.fem import FemSection
    from thermogear.schema.lubricant import LubricantSection


@dataclass(frozen=True, eq=False)
class FemInputs:
    """The resolved inputs of the FE verification of one operating point (SI)."""

    name: str  # the case's name, reported in the summary
    gear_pair: "GearPair"
    material: "Material"
    normal_load: float  # external normal load F_n = T1/r_b1 [N], total over the face width
    settings: "FemSection"  # the case's [fem] section
    lubricant: "LubricantSection"  # the case's [lubricant] section (operating oil temperature, oil properties)
    oil: "Lubricant"  # the oil the [lubricant] section selects
    friction: "MeshModel"  # the elastic mesh model whose friction sees the oil at its operating temperature
    reference_c: float  # stress-free (assembly) temperature [°C] of [temperature].reference_c
    expansion_model: str  # the form of Luo & Li Eq. 9 ([thermal].expansion_model)
    #: The case document as canonical JSON. Every field above is resolved from that document (the FE model reads
    #: no file it names), so equal texts give equal analyses: it keys the memo of analyses
    #: (:func:`thermogear.fem.verification.cached_analysis`), which two loads of one case then share.
    document_key: str


def fem_inputs(case: "Case") -> FemInputs:
    """Resolve a case into the FE verification's inputs (reads the whole case: this is its job).

    The friction heat's mesh model (Luo & Li Eq. 27, DIN 3990-4 μ) must see the oil at the operating temperature
    ``[lubricant].operating_temperature_c``, the ambient of the heat model, whereas the mesh model's friction takes
    the oil at ``[lubricant].reference_temperature_c`` for the elastic model: the case is re-resolved with that
    temperature set to the operating one. Its speed and load are the case's operating point; its μ, load shares
    and unit loads are those of :meth:`~thermogear.mesh.model.MeshModel.pair_damping_at` (one computation of the
    friction for the damping and the heat)."""
    from thermogear.lubricant import lubricant_from_case  # noqa: PLC0415
    from thermogear.mesh.model import MeshModel  # noqa: PLC0415

    if case.helical_pair is not None:
        raise CaseError("gears.helix_angle_deg", round(math.degrees(case.helical_pair.helix_angle), 9),
                        "0 for the FE verification", "the FE tooth model is a spur tooth in plane strain; the "
                        "helical pair's tooth across the face is not modelled")
    oil_c = case.lubricant.operating_temperature_c
    with warning_scope.ignored(ExtrapolationWarning):  # the case as loaded reported its oil's range already
        changed = case.with_changes(**{"lubricant.reference_temperature_c": oil_c})
    return FemInputs(name=case.name, gear_pair=case.gear_pair, material=case.material,
                     normal_load=float(case.normal_load), settings=case.fem, lubricant=case.lubricant,
                     oil=lubricant_from_case(case), friction=MeshModel(changed, "elastic"),
                     reference_c=case.temperature.reference_c, expansion_model=case.thermal.expansion_model,
                     document_key=json.dumps(case.document, sort_keys=True, default=str))


__all__ = ["FemInputs", "fem_inputs"]
