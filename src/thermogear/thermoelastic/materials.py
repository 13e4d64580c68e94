"""Material data of the thermo-elastic mesh model: Young's modulus at temperature and expansion coefficients.

Young's modulus falls almost linearly with temperature over the range gears run at,

    E(T) = E(20 °C)·[1 + β_E·(T − 20 °C)],

with β_E the chord of Roark's table of E versus temperature (Young, Budynas & Sadegh, *Roark's Formulas for Stress
and Strain*, 8th ed., table "temperature effects on the modulus of elasticity", the ASME B31.3 Table C-6 values)
between 21 °C and 204 °C:

| class | E at 21 / 93 / 149 / 204 °C [GPa] | β_E [1/K] |
|---|---|---|
| carbon steel, C ≤ 0.3 % | 203.4 / 198.6 / 195.1 / 191.0 | −3.33e-4 |
| carbon-moly steel | 201.3 / 196.5 / 193.1 / 188.9 | −3.37e-4 |
| nickel steel, Ni 2–9 % | 191.7 / 186.8 / 184.1 / 180.0 | −3.34e-4 |

The table is linear to within 0.2 GPa over 21–204 °C, which is also the range the gear temperatures are allowed
(:data:`thermogear.temperature.field.MATERIAL_MAXIMUM_C` = 200 °C).

Housing expansion coefficients (room temperature, ASM International data as tabulated in Callister's *Materials
Science and Engineering*, App. B Table B.6): steel A36/1020 11.7e-6, grey cast iron G1800–G4000 11.4e-6, cast
aluminium alloy 356.0 21.5e-6 /K (wrought alloys 22.9–23.8e-6).
"""

from __future__ import annotations

import numpy as np

#: Temperature at which the case's Young's modulus is given [°C].
MODULUS_REFERENCE_C = 20.0

#: β_E [1/K] per steel class: chord of Roark's E(T) table from 21 to 204 °C (module docstring).
MODULUS_TEMPERATURE_COEFFICIENTS_PER_K = {
    "carbon_steel": -3.33e-4,
    "carbon_moly_steel": -3.37e-4,
    "nickel_steel": -3.34e-4,
}

#: Linear expansion coefficients of housing materials [1/K] (module docstring).
HOUSING_EXPANSION_PER_K = {
    "steel": 11.7e-6,
    "cast_iron": 11.4e-6,
    "aluminium": 21.5e-6,
}


def youngs_modulus_at(modulus_20c, coefficient_per_k, temperature_c):
    """E(T) = E(20 °C)·[1 + β_E (T − 20 °C)] [Pa] (linear fit of Roark's table; module docstring).

    ``modulus_20c`` E at 20 °C [Pa]; ``coefficient_per_k`` β_E [1/K]; ``temperature_c`` T [°C]. At T = 20 °C the
    result is ``modulus_20c`` exactly.
    """
    temperature_c = np.asarray(temperature_c, dtype=float)
    result = modulus_20c * (1.0 + coefficient_per_k * (temperature_c - MODULUS_REFERENCE_C))
    return result if np.ndim(result) else float(result)


def strain_of_rise(expansion_per_k: float, rise_k: float) -> float:
    """Uniform thermal strain ε = λ·ΔT [–] of a free body heated by ``rise_k`` above its stress-free state."""
    return expansion_per_k * rise_k
