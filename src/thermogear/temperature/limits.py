"""The one set of temperature limits of thermogear: what each limit means and what every command does at it.

Two kinds of limit, kept apart on purpose:

* **Limits of the model** (a refusal or "not evaluated", because the data end there):
  :data:`MATERIAL_MAXIMUM_C` — the gear material data are room-temperature E, ν and a constant expansion
  coefficient with E(T) fitted on 21–204 °C (Roark's table); a mesh (stiffness, dynamics) is not evaluated with a
  gear above it. ``check``/``run``/``sweep`` refuse a case whose given or predicted gear temperature lies above it
  (naming the key or the gearbox prediction), ``warmup`` reports such states with temperatures and losses but
  "mesh not evaluated", ``gearbox`` reports the steady state with the flag ``above_material_data``.
  :data:`NETWORK_EVALUATION_RANGE_C` — the property laws of the gearbox network (air, oil, radiation) are
  evaluated inside it; a steady state outside it is not a result (reported as the end of the stable branch).
* **Plausibility flags** (a result, flagged, never a refusal): a stable steady state or warm-up state above these
  is reported with the flag, because the physics of the network still holds but the gearbox would not survive or
  the data are extrapolated:
  ``oil_above_usable`` (:data:`OIL_USABLE_C` per base oil), ``steel_above_tempering``
  (:data:`CASE_HARDENED_TEMPERING_C`), ``viscosity_extrapolated`` (the oil or shaft node more than
  :data:`VISCOSITY_EXTRAPOLATION_K` outside the viscosity fit's data).

Sources and assumptions:

* Case-hardened (carburised) gear steels are tempered at about 150–180 °C after quenching (e.g. J. R. Davis (ed.),
  Gear Materials, Properties, and Manufacture, ASM International 2005, ch. on carburising: "tempered at 150 to
  180 °C"; recalled [R], not re-read here): a gear body held above its tempering temperature loses surface
  hardness, so the lower end, 150 °C, is the flag.
* Usable oil temperatures: the long-term sump limits that oil makers and AGMA 9005 state are, as recalled [R],
  about 100 °C for mineral gear oils and 120–150 °C for synthetic ones; this project takes 100 °C (mineral), 130 °C
  (PAO, ester, PAG) and 150 °C (traction fluids): an ASSUMPTION of this project, to be replaced by the oil's own
  data sheet. The FZG scuffing test itself runs mineral oils well above 100 °C for 15-minute stages, which is why
  this is a flag, not a limit.
* ASTM D341's Walther line is used for extrapolation in practice but only its data points are measured:
  :data:`VISCOSITY_EXTRAPOLATION_K` = 20 K beyond the fitted range is taken as "far" (an assumption: at 120 °C a
  VG 100 line fitted at 40 and 100 °C is still within a few per cent of tabulated mineral oils; 50 K beyond it is
  not known).

This module imports nothing, so the case schema and every model may read it.
"""

from __future__ import annotations

#: Highest gear temperature the material data cover [°C] (module docstring).
MATERIAL_MAXIMUM_C = 200.0
#: Tempering temperature of case-hardened gears, the flag ``steel_above_tempering`` [°C] (module docstring).
CASE_HARDENED_TEMPERING_C = 150.0
#: Usable (long-term) sump temperature per base oil, the flag ``oil_above_usable`` [°C] (an assumption: module
#: docstring).
OIL_USABLE_C = {"mineral": 100.0, "pao": 130.0, "ester": 130.0, "pag_insoluble": 130.0, "pag_soluble": 130.0,
                "traction": 150.0}
#: How far beyond the viscosity fit's data the flag ``viscosity_extrapolated`` is raised [K].
VISCOSITY_EXTRAPOLATION_K = 20.0
#: Temperatures [°C] inside which the gearbox network's property laws are evaluated; a steady state outside it is
#: not a result.
NETWORK_EVALUATION_RANGE_C = (-100.0, 600.0)

#: The flags of a gearbox state and what each means (for reports and JSON).
FLAG_MEANINGS = {
    "oil_above_usable": "oil above its usable temperature",
    "steel_above_tempering": f"a gear above the tempering temperature of case-hardened gears "
                             f"({CASE_HARDENED_TEMPERING_C:g} °C)",
    "above_material_data": f"a gear above the {MATERIAL_MAXIMUM_C:g} °C the material data cover: mesh not "
                           "evaluated",
    "viscosity_extrapolated": f"oil viscosity extrapolated more than {VISCOSITY_EXTRAPOLATION_K:g} K beyond its "
                              "data",
}


def state_flags(gear_c: float, oil_c: float, base_oil: str, viscosity_range_c: tuple[float, float],
                viscous_c: tuple[float, float] | None = None) -> tuple[str, ...]:
    """The plausibility flags (:data:`FLAG_MEANINGS`) of a state: hottest gear ``gear_c``, sump ``oil_c`` [°C] of
    an oil of ``base_oil`` whose viscosity data span ``viscosity_range_c``; ``viscous_c`` (lowest, highest) of the
    temperatures the viscosity is read at (default the oil's)."""
    flags = []
    if oil_c > OIL_USABLE_C.get(base_oil, OIL_USABLE_C["mineral"]):
        flags.append("oil_above_usable")
    if gear_c > CASE_HARDENED_TEMPERING_C:
        flags.append("steel_above_tempering")
    if gear_c > MATERIAL_MAXIMUM_C:
        flags.append("above_material_data")
    low, high = (oil_c, oil_c) if viscous_c is None else viscous_c
    if low < viscosity_range_c[0] - VISCOSITY_EXTRAPOLATION_K or high > viscosity_range_c[1] + VISCOSITY_EXTRAPOLATION_K:
        flags.append("viscosity_extrapolated")
    return tuple(flags)


__all__ = ["CASE_HARDENED_TEMPERING_C", "FLAG_MEANINGS", "MATERIAL_MAXIMUM_C", "NETWORK_EVALUATION_RANGE_C",
           "OIL_USABLE_C", "VISCOSITY_EXTRAPOLATION_K", "state_flags"]
