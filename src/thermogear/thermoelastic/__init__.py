"""The thermo-elastic mesh model (``[thermal] model = "thermoelastic"``): what heat does to a gear mesh with no
fitted factor (docs/thermal.md).

- :mod:`~thermogear.thermoelastic.materials`: E(T) and expansion coefficients with their sources;
- :mod:`~thermogear.thermoelastic.operating`: gears and housing at temperature, operating geometry, backlash,
  jamming;
- :mod:`~thermogear.thermoelastic.deviations`: tip relief, base-pitch and thermal flank deviations;
- :mod:`~thermogear.thermoelastic.load_sharing`: loaded static transmission error and load share;
- :mod:`~thermogear.thermoelastic.inputs`: the case's inputs resolved with their defaults, load-time checks;
- :mod:`~thermogear.thermoelastic.mesh`: the component :class:`~thermogear.thermoelastic.mesh.ThermoelasticMesh`
  (``ThermoelasticMesh.from_case(case)``), the one the mesh model plugs in;
(Its CLI outputs and figures are in :mod:`thermogear.summaries`.)

This package's ``__init__`` imports no module that imports :mod:`thermogear.case` (the case builder calls the
load-time checks), so import the component from :mod:`thermogear.thermoelastic.mesh`.
"""

from thermogear.thermoelastic.load_sharing import LoadedTransmissionError, loaded_transmission_error
from thermogear.thermoelastic.materials import youngs_modulus_at
from thermogear.thermoelastic.operating import normal_backlash, operating_gear_pair

__all__ = ["LoadedTransmissionError", "loaded_transmission_error", "normal_backlash", "operating_gear_pair",
           "youngs_modulus_at"]
