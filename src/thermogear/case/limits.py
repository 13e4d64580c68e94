"""Load-time limits of what the model can compute: cases it would fail on, or take unbounded time for.

Each check raises :class:`~thermogear.errors.CaseError` naming the key, the value, the allowed range and why, so
that ``check`` refuses what ``stiffness``, ``run``, ``damping`` and ``sweep`` would fail on (issue 25):

- :func:`check_fillet_fit`: the fillet-foundation compliance of Sainsot et al. (2004) is a polynomial fit in the
  root half angle θ_f ≈ 3/z; for many teeth (θ_f below about 0.0075 rad: z above 418 with the ISO 53 rack and a
  solid gear) its coefficients P* and Q* turn negative and the tooth compliance with them. Such a gear is refused,
  with the largest tooth count of its rack that the fit still gives a positive compliance for.
- :func:`check_dynamic_range`: the ratio λ = f_mesh / f_n of the mesh frequency to the torsional natural frequency
  decides how much work one steady orbit takes. Below :data:`FREQUENCY_RATIO_RANGE` [0] (a crawl speed or a gear
  with almost no inertia) a mesh period holds more than 10⁵ natural oscillations, which the event-driven
  nonlinear solver integrates one by one (1 rpm on the FZG type C pair, λ ≈ 5·10⁻⁵: 2.5 s; 0.01 rpm: over
  40 s, growing without bound as the speed falls); above [1] (an inertia of a ship's wheel on a watch gear)
  the mass hardly moves and the equations lose every digit (an inertia of 10³⁰ kg m² gave NaN). f_n is estimated
  before any stiffness is computed from ISO 6336-1 Method B's mean mesh stiffness c_γα (clause 9), which is
  within about 30 % of the potential-energy value for the built-in cases: the bounds leave decades of margin.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError

if TYPE_CHECKING:
    from thermogear.geometry import GearPair
    from thermogear.materials import Material

#: Smallest line load F_bt / b [N/m] (0.01 N/mm). With a mesh stiffness near ISO 6336-1's c_γα ≈ 20 N/(mm·μm) it
#: deflects the teeth by 0.5 nm, a few atomic spacings and a hundredth of the finest ground flank's roughness:
#: below it the static transmission error has no physical meaning, and the solvers' tolerances (scaled to it)
#: lose the orbit (power_kw = 1e-12 gave a non-periodic response and NaN multipliers, issue 25). Idling gears
#: (rattle under drag torque) carry 0.1 to a few N/mm.
MINIMUM_LINE_LOAD = 10.0

#: Allowed range of λ = f_mesh / f_n [–] (module docstring). Ordinary gearboxes run at 0.01 to 5.
FREQUENCY_RATIO_RANGE = (1e-5, 1e3)

#: Largest centrifugal hoop stress ρ·v_a² at the tip circle [Pa] (v_a the tip speed). A thin ring spinning at
#: rim speed v carries the hoop stress σ = ρ·v² whatever its radius (Timoshenko, Strength of Materials II, §67),
#: the rim of a gear more than that with its teeth hanging on it. 1000 MPa is about the core yield strength of
#: case-hardened gear steels (18CrNiMo7-6: R_p0.2 ≈ 800–1050 MPa, stated as an assumption): above it the rim
#: would yield before any tooth load; steel turbo gears run to about 200 m/s (ρ v² ≈ 310 MPa).
MAXIMUM_RIM_HOOP_STRESS = 1.0e9

#: A tip relief deeper than this many static deflections of one tooth pair under the nominal load (F_bt / (b·c′),
#: ISO 6336-1 c′) is flagged: a relief is designed about equal to that deflection (Sigg 1965; Niemann & Winter
#: §21.2), and one several times deeper keeps the relieved flank out of contact at any load the case runs, so it
#: acts as a profile error, not as a correction.
TIP_RELIEF_DEFLECTIONS_FLAGGED = 5.0


def _fit_coefficients_positive(teeth: int, root_to_bore: float, pressure_angle: float, rack_dedendum: float,
                               rack_tip_radius: float) -> bool:
    """Whether L*, M*, P*, Q* of the Sainsot fit are all positive for this gear (plain floats: it runs for every
    case loaded, sweep points included)."""
    from thermogear.stiffness.fillet_foundation import (NOMINAL_SEAT_RATIO, SAINSOT_COEFFICIENTS,
                                                        SAINSOT_INPUT_RANGES, root_half_angle)

    theta_f = root_half_angle(teeth, pressure_angle, rack_dedendum, rack_tip_radius)
    h_f = min(max(root_to_bore, SAINSOT_INPUT_RANGES["h_f"][0]), 1.0 / NOMINAL_SEAT_RATIO)  # as evaluated
    return all(a / theta_f**2 + b * h_f**2 + c * h_f / theta_f + d / theta_f + e * h_f + f > 0.0
               for a, b, c, d, e, f in SAINSOT_COEFFICIENTS.values())


def check_fillet_fit(gear_pair: "GearPair") -> None:
    """Refuse a gear whose tooth count takes the Sainsot fillet-foundation fit to a non-positive coefficient
    (module docstring): its tooth compliance would be non-positive and no stiffness could be computed."""
    from thermogear.stiffness.fillet_foundation import root_to_bore_ratio

    for name in ("pinion", "wheel"):
        gear = getattr(gear_pair, name)
        h_f = root_to_bore_ratio(gear.root_radius, gear.bore_radius, name)
        arguments = (gear.pressure_angle, gear.dedendum_coefficient, gear.tool_tip_radius_coefficient)
        if _fit_coefficients_positive(gear.teeth, h_f, *arguments):
            continue
        largest = gear.teeth - 1
        while largest > 5 and not _fit_coefficients_positive(largest, h_f, *arguments):
            largest -= 1
        raise CaseError(f"gears.{name}.teeth", gear.teeth, f"<= {largest} with this rack and bore",
                        "the fillet-foundation compliance of Sainsot et al. (2004) is a fit over root half angles "
                        "θ_f >= 0.01 rad (θ_f ≈ 3/z); with this many teeth its coefficients turn negative and the "
                        "tooth compliance with them, so no mesh stiffness can be computed")


def estimated_frequency_ratio(pair: "GearPair", material: "Material", speed_rpm: float,
                              inertias: tuple[float, float] | None) -> float:
    """λ = f_mesh / f_n [–] at the pinion speed ``speed_rpm`` [rpm] with f_n = √(c_γα b / m_e) / 2π from ISO 6336-1
    Method B's c_γα (clause 9) and the equivalent mass m_e of the given inertias [kg m²] (None: solid discs)."""
    from thermogear.stiffness.iso6336 import iso6336_stiffness

    stiffness = iso6336_stiffness(pair, material)["c_gamma_alpha"] * pair.face_width  # [N/m]
    mass = pair.equivalent_mass(material.density, inertias)
    natural_frequency = math.sqrt(stiffness / mass) / (2.0 * math.pi)
    return pair.mesh_frequency(speed_rpm) / natural_frequency


def check_dynamic_range(pair: "GearPair", material: "Material", speed_rpm: float,
                        inertias: tuple[float, float] | None) -> None:
    """Refuse an operating point whose frequency ratio λ lies outside :data:`FREQUENCY_RATIO_RANGE` (module
    docstring), naming the inertias when they are what takes it out (the same speed with solid-disc inertias is
    inside), the speed otherwise."""
    low, high = FREQUENCY_RATIO_RANGE
    ratio = estimated_frequency_ratio(pair, material, speed_rpm, inertias)
    if low <= ratio <= high:
        return
    why = ("a mesh period would hold more than 10⁵ natural oscillations, which the dynamics solvers integrate one "
           "by one: it cannot be computed in reasonable time (the response is the static one)") if ratio < low else (
           "the gears would hardly move against the mesh (the inertia overwhelms the tooth stiffness), and the "
           "equations lose every digit")
    reason = f"the mesh-to-natural frequency ratio λ ≈ {ratio:.3g} is outside [{low:g}, {high:g}]: {why}"
    if inertias is not None and low <= estimated_frequency_ratio(pair, material, speed_rpm, None) <= high:
        raise CaseError("gears.pinion.inertia_kg_m2, gears.wheel.inertia_kg_m2", list(inertias),
                        "inertias that keep λ inside the range (solid discs of the gears do)", reason)
    raise CaseError("operating.speed_rpm", speed_rpm,
                    f"a speed giving λ in [{low:g}, {high:g}]", reason)


def load_key(operating: dict) -> str:
    """The case-file key the load was given by, from the case file's ``[operating]`` table."""
    return next((f"operating.{name}" for name in ("power_kw", "torque_nm", "fzg_load_stage")
                 if operating.get(name) is not None), "operating.torque_nm")


def check_load_range(normal_load: float, face_width: float, operating: dict) -> None:
    """Refuse a normal load [N] on a face width [m] below :data:`MINIMUM_LINE_LOAD`, naming the key of the case
    file's ``[operating]`` table it was given by."""
    line_load = normal_load / face_width
    if line_load >= MINIMUM_LINE_LOAD:
        return
    key = load_key(operating)
    value = operating.get(key.split(".")[1])
    raise CaseError(key, value, f"a load of at least {MINIMUM_LINE_LOAD * 1e-3:g} N/mm of face width (here "
                    f"{line_load * 1e-3:.3g} N/mm)", "the teeth would deflect by less than a nanometre, below any "
                    "flank's roughness: the transmission error has no meaning and the solvers lose the orbit")


def check_bearing_clearance(drivetrain, mesh: str) -> None:
    """Refuse a bearing's radial clearance under the linear mesh: the clearance is a dead zone, which only the
    backlash solver of the nonlinear mesh takes; the linear drivetrain in permanent contact would ignore it.
    ``drivetrain`` the [drivetrain] section or None, ``mesh`` the case's ``dynamics.mesh``."""
    if drivetrain is None or mesh_law(mesh).backlash:
        return
    for bearing in drivetrain.bearings:
        if bearing.radial_clearance_um > 0.0:
            raise CaseError(f"drivetrain.bearings '{bearing.name}'.radial_clearance_um", bearing.radial_clearance_um,
                            "0 (the bearing in permanent contact) with dynamics.mesh = 'linear'",
                            "with a clearance the bearing is a dead zone, which the linear mesh in permanent "
                            "contact cannot represent; set dynamics.mesh = 'nonlinear' to solve the drivetrain's "
                            "backlash orbit with the clearance")


def check_model_limits(pair, material, operating, inertias, drivetrain, mesh: str, gears_input,
                       operating_keys: dict) -> None:
    """Every limit of this module, in order (called by :func:`thermogear.case.check_case` with the case's pieces):
    ``pair`` the cold GearPair, ``material`` its Material, ``operating`` the OperatingPoint, ``inertias`` the
    case's gear inertias [kg m²] or None, ``drivetrain`` the [drivetrain] section or None, ``mesh`` the
    ``dynamics.mesh`` law, ``gears_input`` the [gears] section and ``operating_keys`` the case file's
    ``[operating]`` table (which key gave the load)."""
    normal_load = operating.normal_load(pair.pinion.base_radius)
    check_fillet_fit(pair)
    check_load_range(normal_load, pair.face_width, operating_keys)
    check_rim_speed(pair, material, operating.speed_rpm)  # before λ: the cause first
    check_dynamic_range(pair, material, operating.speed_rpm, inertias)
    check_bearing_clearance(drivetrain, mesh)
    flag_deep_tip_relief(pair, material, normal_load, gears_input)


def check_rim_speed(pair: "GearPair", material: "Material", speed_rpm: float) -> None:
    """Refuse a speed whose tip speed v_a [m/s] gives a rim hoop stress ρ·v_a² above :data:`MAXIMUM_RIM_HOOP_STRESS`
    (a 10 km/s pitch-line speed passed without a word, issue 36). The faster gear rim is the larger one: both gears
    share the pitch-line speed, the tip speeds differ by their tip-to-pitch radius ratios."""
    omega = speed_rpm * math.pi / 30.0
    tip_speed = max(omega * pair.pinion.tip_radius,
                    omega * pair.pinion.reference_radius / pair.wheel.reference_radius * pair.wheel.tip_radius)
    stress = material.density * tip_speed**2
    if stress <= MAXIMUM_RIM_HOOP_STRESS:
        return
    most = speed_rpm * math.sqrt(MAXIMUM_RIM_HOOP_STRESS / stress)
    raise CaseError("operating.speed_rpm", speed_rpm, f"<= {most:.6g} rpm for this pair (a tip speed of at most "
                    f"{tip_speed * most / speed_rpm:.0f} m/s)",
                    f"the tip speed {tip_speed:.4g} m/s (pitch-line speed {omega * pair.pinion.reference_radius:.4g} "
                    f"m/s) loads the rim with a centrifugal hoop stress ρ·v² = {stress * 1e-6:.0f} MPa, above "
                    f"{MAXIMUM_RIM_HOOP_STRESS * 1e-6:.0f} MPa, the core yield strength of case-hardened gear steels: "
                    "the gear would burst before it meshed")


def flag_deep_tip_relief(pair: "GearPair", material: "Material", normal_load: float, gears_section) -> None:
    """Warn (:class:`~thermogear.errors.ModelAssumptionWarning`) about a tip relief deeper than
    :data:`TIP_RELIEF_DEFLECTIONS_FLAGGED` static deflections of one tooth pair under the case's load (a 1000 μm
    relief on a module 4.5 tooth passed without a flag, issue 36)."""
    import warnings

    from thermogear.errors import ModelAssumptionWarning
    from thermogear.stiffness.iso6336 import iso6336_stiffness

    deflection = None
    for name in ("pinion", "wheel"):
        relief_um = getattr(gears_section, name).tip_relief_um
        if relief_um <= 0.0:
            continue
        if deflection is None:
            deflection = normal_load / (iso6336_stiffness(pair, material)["c_prime"] * pair.face_width)
        if relief_um * 1e-6 > TIP_RELIEF_DEFLECTIONS_FLAGGED * deflection:
            warnings.warn(f"gears.{name}.tip_relief_um = {relief_um:g}: {relief_um * 1e-6 / deflection:.0f} times "
                          f"the static deflection of one tooth pair under the case's load ({deflection * 1e6:.2f} "
                          f"μm, F_bt/(b·c′) with ISO 6336-1's c′); a relief is designed about equal to it, so this "
                          "one keeps the relieved flank out of contact at this load and acts as a profile error",
                          ModelAssumptionWarning, stacklevel=2)

