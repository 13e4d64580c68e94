"""Heat to stiffness: tooth temperatures, thermal expansion of the flanks and the meshing thermal stiffness
(Luo & Li 2020 Eqs. 7–23).

- :mod:`~thermogear.thermal.temperature`: :class:`TemperatureField` and the case's temperature input;
- :mod:`~thermogear.thermal.expansion`: flank expansion along the line of action (Eqs. 8–12);
- :mod:`~thermogear.thermal.stiffness`: k_T, k_Ti, δ_T, δ_Ti, δ_Tp (Eqs. 13–23);
- :mod:`~thermogear.thermal.case_stiffness`: k_T of a case at a given normal load;
- :mod:`~thermogear.thermal.calibration`: X_te given, calibrated or from the FE model;
(The CLI's JSON object and Fig. 4 are in :mod:`thermogear.summaries`.)
"""

from thermogear.thermal.calibration import Calibration, calibrate_x_te, register_x_te_provider, resolve_x_te
from thermogear.thermal.expansion import (base_circle_radial_expansion, flank_expansion_along_line_of_action,
                                          pair_flank_expansion)
from thermogear.thermal.case_stiffness import thermal_pair_stiffness_at, thermal_stiffness
from thermogear.thermal.stiffness import ThermalPairStiffness, ThermalStiffness, thermal_pair_stiffness
from thermogear.thermal.temperature import (TemperatureField, register_temperature_provider,
                                            temperature_field_from_case)

__all__ = ["Calibration", "TemperatureField", "ThermalPairStiffness", "ThermalStiffness",
           "base_circle_radial_expansion", "calibrate_x_te", "flank_expansion_along_line_of_action",
           "pair_flank_expansion", "register_temperature_provider", "register_x_te_provider", "resolve_x_te",
           "temperature_field_from_case", "thermal_pair_stiffness", "thermal_pair_stiffness_at",
           "thermal_stiffness"]
