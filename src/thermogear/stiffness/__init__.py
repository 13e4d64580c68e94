"""Elastic mesh stiffness: potential energy method (Yang & Lin (1987), Tian 2004; Chaari et al. 2009), ISO 6336-1 cross-check, cached tables."""

from thermogear.stiffness.iso6336 import iso6336_mesh_stiffness, iso6336_single_stiffness, iso6336_stiffness
from thermogear.stiffness.potential_energy import (PairCompliance, ToothCompliance, hertz_compliance,
                                                   pair_compliance, tooth_compliance)
from thermogear.stiffness.table import pair_compliance_table, pair_stiffness_at, tooth_compliance_at

__all__ = ["PairCompliance", "ToothCompliance", "hertz_compliance", "iso6336_mesh_stiffness",
           "iso6336_single_stiffness", "iso6336_stiffness", "pair_compliance", "pair_compliance_table",
           "pair_stiffness_at", "tooth_compliance", "tooth_compliance_at"]
