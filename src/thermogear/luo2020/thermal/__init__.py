"""The thermal stiffness model of Luo & Li (2020), kept to reproduce the paper: the flanks' thermal expansion and
the secant meshing thermal stiffness k_T with the thermal-elastic ratio X_te (Eqs. 7–23).

It is the ``"luo2020"`` pair model (``[thermal] model = "luo2020"``); thermogear's predictive model is
:mod:`thermogear.thermoelastic`. The tooth temperatures both read come from :mod:`thermogear.temperature.source`.

- :mod:`~thermogear.luo2020.thermal.expansion`: flank expansion along the line of action (Eqs. 8–12);
- :mod:`~thermogear.luo2020.thermal.stiffness`: k_T, k_Ti, δ_T, δ_Ti, δ_Tp (Eqs. 13–23);
- :mod:`~thermogear.luo2020.thermal.case_stiffness`: k_T of a case at a given normal load and X_te of a case, from the
  :class:`~thermogear.luo2020.thermal.case_stiffness.PaperThermalModel` the case resolves into once
  (:func:`~thermogear.luo2020.thermal.case_stiffness.paper_thermal_model`);
- :mod:`~thermogear.luo2020.thermal.calibration`: X_te given, calibrated or from the FE model;
(The CLI's JSON object and Fig. 4 are in :mod:`thermogear.summaries`.)
"""

from thermogear.luo2020.thermal.calibration import Calibration, register_x_te_provider
from thermogear.luo2020.thermal.expansion import (base_circle_radial_expansion, flank_expansion_along_line_of_action,
                                                  pair_flank_expansion)
from thermogear.luo2020.thermal.case_stiffness import PaperThermalModel, paper_thermal_model
from thermogear.luo2020.thermal.stiffness import ThermalPairStiffness, ThermalStiffness, thermal_pair_stiffness

__all__ = ["Calibration", "PaperThermalModel", "ThermalPairStiffness", "ThermalStiffness", "base_circle_radial_expansion",
           "flank_expansion_along_line_of_action", "pair_flank_expansion", "paper_thermal_model",
           "register_x_te_provider", "thermal_pair_stiffness"]
