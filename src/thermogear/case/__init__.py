"""Cases: load a case file or a built-in parameter set, validate it, and build the components.

A case file is TOML with units in its key names (``module_mm``, ``speed_rpm``). Every value is checked at load
time; a bad one raises :class:`~thermogear.errors.CaseError` naming the key, the value, the allowed range and
the reason.
"""

from __future__ import annotations

import functools
import inspect
import tomllib
import weakref
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Any, Callable

import pydantic

from thermogear.temperature.kinds import temperature_source
from thermogear import warning_scope
from thermogear.case.errors import case_error_from_validation
from thermogear.case.gears import gear_pair_of, helical_pair_of
from thermogear.case.helical import check_face_gradient, check_helical_case, transverse_gears_section
from thermogear.case.keys import warn_keys_without_effect
from thermogear.case.limits import check_model_limits
from thermogear.case.pieces import call_with_pieces
from thermogear.composition import CASE_CHECKS, TEMPERATURE_MODELS, builtin, resolve
from thermogear.errors import CaseError, closest_key
from thermogear.fzg import fzg_load_stage_torque
from thermogear.geometry import GearPair
from thermogear.helical.geometry import HelicalPair
from thermogear.materials import Material
from thermogear.operating import OperatingPoint
from thermogear.schema.base import StrictTypeError
from thermogear.schema import (CaseFile, DampingSection, DrivetrainSection, DynamicsSection, FemSection, GearboxSection,
                               GearsSection, HousingSection, LubricantSection, MaterialSection, TemperatureSection,
                               ThermalSection)
from thermogear.schema.drivetrain import check_drivetrain_fits_gears
from thermogear.schema.drivetrain_topology import check_drivetrain_train
from thermogear.temperature.field import (check_temperatures, default_bulk_temperature, temperature_field_from_section)
from thermogear.choices.thermal_models import thermal_model_rules, x_te_source
from thermogear.text_files import is_existing_file, path_exists, read_user_text
from thermogear.thermoelastic.inputs import check_thermoelastic_inputs
from thermogear.geometry.involute import disc_polar_inertia


@dataclass(frozen=True)
class GearStage:
    """A further gear pair of a drivetrain ([[drivetrain.stages]]): its name, cold pair, [gears]-like input and
    composite roughness Ra [m]."""

    name: str
    gear_pair: GearPair
    gears_input: GearsSection
    roughness_ra: float


@dataclass(frozen=True)
class Case:
    """A validated case: the gear pair and everything that acts on it.

    The gear pair, material and operating point are built components; the lubricant, temperature, thermal,
    damping and dynamics sections are validated, immutable inputs that the later stages turn into components.
    """

    name: str
    title: str
    citation: str
    assumptions: tuple[str, ...]
    gear_pair: GearPair
    material: Material
    operating_point: OperatingPoint
    roughness_ra: float  # composite Ra [m]
    inertias: tuple[float, float] | None  # [kg m²] or None for discs
    lubricant: LubricantSection
    temperature: TemperatureSection
    thermal: ThermalSection
    damping: DampingSection
    dynamics: DynamicsSection
    fem: FemSection
    source: str  # parameter-set name or file path
    document: dict[str, Any] = field(compare=False, repr=False)  # the case file as loaded (for result files)
    # inputs of the thermo-elastic mesh model (thermogear.thermoelastic): the validated sections
    housing: HousingSection = HousingSection()
    gears_input: GearsSection | None = None
    material_input: MaterialSection = MaterialSection()
    # what thermogear assumed for keys the case left out, in words (every command prints them as "note: …")
    notes: tuple[str, ...] = ()
    gearbox: GearboxSection | None = None  # the gearbox around the pair (thermogear.gearbox), optional
    drivetrain: DrivetrainSection | None = None  # shafts, bearings, couplings (thermogear.drivetrain), optional
    stages: tuple[GearStage, ...] = ()  # the drivetrain's further gear pairs ([[drivetrain.stages]]), in order
    # a helical pair (helix_angle_deg > 0): its helix; gear_pair is then its transverse section, and gears_input the
    # section as the transverse model reads it (backlash along the transverse line of action). None: a spur pair
    helical_pair: HelicalPair | None = None

    @property
    def directory(self) -> Path | None:
        """Folder of the case file (for relative paths in it), None for a built-in set."""
        path = Path(self.source)
        return path.parent if path.suffix == ".toml" and path_exists(path) else None

    @property
    def equivalent_mass(self) -> float:
        """me of Eq. 5 [kg], total over the face width."""
        return self.gear_pair.equivalent_mass(self.material.density, self.inertias)

    @property
    def normal_load(self) -> float:
        """External normal load w = F_bt = T1 / r_b1 [N], total over the face width."""
        return self.operating_point.normal_load(self.gear_pair.pinion.base_radius)

    def with_changes(self, *, predict_temperatures: bool = True, **changes: Any) -> "Case":
        """A new case with dotted case-file keys replaced, re-validated (``{"operating.speed_rpm": 3000}``);
        ``predict_temperatures``: as :func:`case_from_document`."""
        document = _deep_copy(self.document)
        for dotted, value in changes.items():
            node = document
            *parents, last = dotted.split(".")
            if parents and parents[0] not in document:  # a section the file leaves to its default
                document[parents[0]] = _section_default(parents[0])
            for part in parents:
                node = node.setdefault(part, {})
            node[last] = value
        return case_from_document(document, source=self.source, predict_temperatures=predict_temperatures)


def _section_default(name: str) -> dict[str, Any]:
    """The keys a top-level section absent from a case file takes by default (``[lubricant]`` names its default
    oil), so that a change to one key of such a section keeps the others' defaults: ``thermogear fem`` set the
    oil temperature of a case without ``[lubricant]`` and lost the default oil's name (issue 36)."""
    field = CaseFile.model_fields.get(name)
    default = None if field is None else field.default
    if isinstance(default, pydantic.BaseModel):
        return default.model_dump(exclude_unset=True)
    return {}


def cached_per_case(function):
    """A resolver of a case, memoised on that Case instance: ``function``'s parameters name the pieces of the case it
    reads (:mod:`thermogear.case.pieces`: ``lubricant``, ``gear_pair``, a derived piece such as ``oil``; ``case``
    the whole case), and the memoised resolver is called with the case (``resolver(case)``), which it reads in one
    place: here.

    Derived components of a case (its temperature field, lubricant, X_te) are pure functions of the case and are
    asked for by several stages of one operating point; like the stiffness tables they are computed once per case.
    A Case holds lists and so is not hashable: results are keyed by identity and dropped with the case.
    The warnings the first computation raised are recorded with the result and raised again on every later call,
    so a cached component never swallows a warning the second time it is asked for.
    """
    results: dict[int, tuple[weakref.ref, object, tuple]] = {}

    @functools.wraps(function)
    def cached(case):
        key = id(case)
        entry = results.get(key)
        if entry is None or entry[0]() is not case:
            with warning_scope.recorded() as caught:
                value = call_with_pieces(function, case)
            entry = (weakref.ref(case, lambda _, key=key: results.pop(key, None)), value, warning_scope.kept(caught))
            results[key] = entry
        warning_scope.raise_again(entry[2])
        return entry[1]

    cached.cache_clear = results.clear
    cached.cases = lambda: frozenset(results)  # the identities of the cases it holds a result for (tests)
    # called with the case: its signature is (case); the resolver of the pieces stays ``cached.__wrapped__``
    cached.__signature__ = inspect.Signature([inspect.Parameter("case", inspect.Parameter.POSITIONAL_OR_KEYWORD)])
    return cached


def parameter_set_names() -> list[str]:
    """Names of the built-in parameter sets."""
    folder = resources.files("thermogear.parameter_sets")
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


def parameter_set_path(name: str):
    """Path (importlib resource) of a built-in parameter set."""
    return resources.files("thermogear.parameter_sets") / f"{name}.toml"


def load_case(name_or_path: str | Path, predict_temperatures: bool = True) -> Case:
    """Load a built-in parameter set by name (``"luo2019"``) or a TOML case file by path.

    Every check the model would make is made here (:func:`case_from_document`), so a case that loads is one that
    runs; a file that is not UTF-8 text or not TOML is one CaseError, never a traceback. ``predict_temperatures``:
    as :func:`case_from_document`."""
    text_source = str(name_or_path)
    path = Path(name_or_path)
    if path.suffix == ".toml" or path_exists(path):
        if not is_existing_file(path):
            raise CaseError("case", text_source, "an existing .toml file or a built-in name "
                            f"({', '.join(parameter_set_names())})", "no such file")
        text = read_user_text(path, "case", text_source, "TOML")
    elif text_source in parameter_set_names():
        text = parameter_set_path(text_source).read_text(encoding="utf-8")
    else:
        suggestion = closest_key(text_source, parameter_set_names())
        hint = f" (did you mean '{suggestion}'?)" if suggestion else ""
        raise CaseError("case", text_source, f"one of {', '.join(parameter_set_names())} or a .toml path",
                        f"no such parameter set{hint}")
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise CaseError("case", text_source, "valid TOML", f"the file cannot be parsed: {error}") from None
    except RecursionError:
        raise CaseError("case", text_source, "TOML nested a few levels deep",
                        "the file nests tables or arrays too deeply to be a case file") from None
    return case_from_document(document, source=str(path if path_exists(path) else text_source),
                              predict_temperatures=predict_temperatures)


# --------------------------------------------------------------------------------------------- load-time checks
CaseCheck = Callable[..., None]  # its parameters name pieces of the case (thermogear.case.pieces)
_CASE_CHECKS: list[CaseCheck] = []


def register_case_check(check: CaseCheck) -> CaseCheck:
    """Add a check that every loaded case must pass (it raises CaseError). The check receives the pieces of the
    case its parameters name (:mod:`thermogear.case.pieces`: ``check(gear_pair, operating_point)``; ``check(case)``
    the whole case). Returns the check, so it can be used as a decorator. The built-in checks (temperatures, X_te, then those named in :mod:`thermogear.composition`) run
    first; registered ones after, in order."""
    if not callable(check):
        raise TypeError("a case check must be callable: check(case) -> None")
    if check not in _CASE_CHECKS:
        _CASE_CHECKS.append(check)
    return check


def check_case(case: "Case") -> None:
    """Run every load-time check on a built case: what the model would refuse later is refused now.

    Section-local checks run in the schema (values, lubricant name and viscosity points, the flank table's
    values); here run the checks that need the gear pair or several sections: the temperature field over the path
    of contact (:func:`~thermogear.temperature.field.check_temperatures`: table sorted and matched, fit degree,
    temperatures within what the case's thermal model evaluates) and the X_te the paper's thermal model needs.
    Warnings of these checks are left to the stage that uses the value (it issues them once, there)."""
    with warning_scope.ignored():
        _check_temperature_field(case.temperature, case.directory, case.gear_pair, case.thermal.model)
    _check_thermal_inputs(case.thermal)
    check_model_limits(case.gear_pair, case.material, case.operating_point, case.inertias, case.drivetrain,
                       case.dynamics.mesh, case.gears_input, case.document.get("operating", {}))
    builtin_checks = [check for check in map(resolve, CASE_CHECKS) if check is not None]
    for check in builtin_checks + [check for check in _CASE_CHECKS if check not in builtin_checks]:
        call_with_pieces(check, case)  # each receives the pieces of the case it names (thermogear.case.pieces)


def _check_temperature_field(section: TemperatureSection, directory: Path | None, pair: GearPair,
                             thermal_model: str) -> None:
    """A given temperature field (``[temperature]``, files relative to ``directory``) over the path of contact of
    ``pair``, within what the ``[thermal] model`` evaluates."""
    if not temperature_source(section.model).given:  # computed by its provider, checked there
        return
    field = temperature_field_from_section(section, directory)
    points = pair.path_points
    check_temperatures(field, float(pair.gamma(points["A"])), float(pair.gamma(points["E"])),
                       limits=thermal_model_rules(thermal_model).temperature_limits)


def _check_thermal_inputs(section: ThermalSection) -> None:
    """The X_te inputs of a ``[thermal]`` section whose model reads X_te: given or calibrated, not both."""
    if not thermal_model_rules(section.model).reads_x_te:  # e.g. the paper's k_T (Eqs. 13–23) uses X_te
        return
    source = x_te_source(section.x_te_source)
    if source.given and section.x_te is None:
        raise CaseError("thermal.x_te", None, ">= 0 (or x_te_source = 'calibrated')",
                        "thermal.model = 'luo2020', the paper's thermal stiffness (Luo & Li 2020 Eqs. 13–23), needs "
                        "the thermal-load correction factor X_te; give thermal.x_te or calibrate it")
    if source.calibrated and section.x_te is not None:
        raise CaseError("thermal.x_te", section.x_te, "absent with x_te_source = 'calibrated'",
                        "X_te is either given or calibrated; remove one of them")
    if source.calibrated and section.calibration_drop_percent is None:
        raise CaseError("thermal.calibration_drop_percent", None, "(0, 100)",
                        "x_te_source = 'calibrated' needs the target stiffness drop")


def _stage(section, model: CaseFile) -> GearStage:
    """A further stage of a drivetrain: its pair, checked as the first stage's is (profile shifts, tip reliefs,
    backlash, no jamming hot), under the case's material, temperatures and thermal model. A stage's own
    temperatures along its path are not given: the case's temperature must be uniform."""
    key = f"drivetrain.stages '{section.name}'.gears"
    if not temperature_source(model.temperature.model).uniform:
        raise CaseError("temperature.model", model.temperature.model, "'uniform' with [[drivetrain.stages]]",
                        "a tabulated or computed flank temperature is given along the first stage's path of contact "
                        "only; the further stages take the uniform bulk temperature")
    if any(getattr(section.gears, name).inertia_kg_m2 is not None for name in ("pinion", "wheel")):
        raise CaseError(f"{key}.pinion.inertia_kg_m2", "given", "absent (the gear bodies are annuli)",
                        "a stage's gear bodies are the annuli of their pitch circles on the shafts")
    pair = gear_pair_of(section.gears)
    check_thermoelastic_inputs(pair, model.model_copy(update={"gears": section.gears}))
    return GearStage(name=section.name, gear_pair=pair, gears_input=section.gears,
                     roughness_ra=section.gears.roughness_ra_um * 1e-6)


def case_from_document(document: dict[str, Any], source: str = "<memory>", predict_temperatures: bool = True) -> Case:
    """Validate a case document (the parsed TOML) and build the components.

    A ``[temperature] model`` that predicts the case's temperatures when it is loaded (the gearbox network's) writes
    them into the case unless ``predict_temperatures`` is False: the commands that report that model itself
    (``gearbox``, ``warmup --model gearbox``) take the case before its prediction where the prediction refuses it."""
    try:
        model = CaseFile.model_validate(document)
    except pydantic.ValidationError as error:
        raise case_error_from_validation(error) from None
    gears = model.gears
    check_helical_case(model)
    helical = helical_pair_of(gears)
    pair = helical.transverse
    check_face_gradient(model, helical)
    if helical.helix_angle > 0.0:
        gears = transverse_gears_section(gears, helical)
        model = model.model_copy(update={"gears": gears})
    check_thermoelastic_inputs(pair, model)
    stages = ()
    if model.drivetrain is not None:  # the gears' seats on their shafts (the drivetrain is built by its resolver)
        stages = tuple(_stage(stage, model) for stage in model.drivetrain.stages)
        seats = tuple((f"stages '{stage.name}' {name}", point, gear.bore_radius * 1e3, gear.root_radius * 1e3)
                      for stage, section in zip(stages, model.drivetrain.stages)
                      for name, point, gear in (("pinion", section.pinion, stage.gear_pair.pinion),
                                                ("wheel", section.wheel, stage.gear_pair.wheel)))
        check_drivetrain_fits_gears(model.drivetrain, (pair.pinion.bore_radius * 1e3, pair.wheel.bore_radius * 1e3),
                                    (pair.pinion.root_radius * 1e3, pair.wheel.root_radius * 1e3), seats)
        density = model.material.density_kg_m3
        inertias = [(f"{stage} {name}", disc_polar_inertia(density, radius, item.bore_radius, item.face_width))
                    for stage, stage_pair in (("first stage", pair), *((stage.name, stage.gear_pair) for stage in stages))
                    for name, item, radius in zip(("pinion", "wheel"), (stage_pair.pinion, stage_pair.wheel),
                                                  stage_pair.operating_pitch_radii)]
        check_drivetrain_train(model.drivetrain, (gears.pinion.teeth, gears.wheel.teeth), inertias)
    material = model.material
    op = model.operating
    if op.power_kw is not None:
        operating = OperatingPoint.from_power(op.speed_rpm, op.power_kw * 1e3)
    else:
        torque = op.torque_nm if op.torque_nm is not None else fzg_load_stage_torque(op.fzg_load_stage)
        operating = OperatingPoint(op.speed_rpm, torque)
    temperature, notes = default_bulk_temperature(model.temperature, model.lubricant)
    inertias = None
    if (gears.pinion.inertia_kg_m2 is None) != (gears.wheel.inertia_kg_m2 is None):
        raise CaseError("gears.wheel.inertia_kg_m2", gears.wheel.inertia_kg_m2, "given for both gears or neither",
                        "the equivalent mass needs both inertias")
    if gears.pinion.inertia_kg_m2 is not None:
        inertias = (gears.pinion.inertia_kg_m2, gears.wheel.inertia_kg_m2)
    case = Case(
        name=model.case.name, title=model.case.title, citation=model.case.citation,
        assumptions=tuple(model.case.assumptions), gear_pair=pair,
        material=Material(youngs_modulus=material.youngs_modulus_gpa * 1e9, poisson_ratio=material.poisson_ratio,
                          density=material.density_kg_m3, specific_heat=material.specific_heat_j_per_kg_k,
                          thermal_conductivity=material.thermal_conductivity_w_per_m_k,
                          thermal_expansion=material.thermal_expansion_per_k),
        operating_point=operating, roughness_ra=gears.roughness_ra_um * 1e-6, inertias=inertias,
        lubricant=model.lubricant, temperature=temperature, thermal=model.thermal, damping=model.damping,
        dynamics=model.dynamics, fem=model.fem, source=source, document=document, housing=model.housing,
        gears_input=gears, material_input=material, notes=notes, gearbox=model.gearbox, drivetrain=model.drivetrain,
        stages=stages, helical_pair=helical if helical.helix_angle > 0.0 else None)
    if predict_temperatures and temperature_source(case.temperature.model).predicted_at_load:  # its model (below)
        name = case.temperature.model
        resolver = _TEMPERATURE_MODELS.get(name) or builtin(TEMPERATURE_MODELS, name)
        if resolver is None:
            raise CaseError("temperature.model", name, "a registered model (its module is not installed)",
                            "this temperature model is predicted by a model that is not loaded")
        case = replace(case, **call_with_pieces(resolver, case))  # the parts of the case it predicts
    check_case(case)
    warn_keys_without_effect(case.thermal, case.dynamics)
    return case


# --------------------------------------------------------------------------------------------- predicted temperatures
#: ``resolver(pieces) -> {Case field: new value}``: its parameters name pieces (thermogear.case.pieces)
CaseResolver = Callable[..., dict[str, Any]]
_TEMPERATURE_MODELS: dict[str, CaseResolver] = {}


def register_temperature_model(name: str, resolver: CaseResolver) -> None:
    """Plug in a temperature model that predicts the case's temperatures at load time, selectable as
    ``[temperature].model = name``: ``resolver(pieces)`` receives the pieces of the case its parameters name
    (:mod:`thermogear.case.pieces`) and returns the parts of the case it predicts, ``{field: value}`` (the
    ``lubricant`` and ``housing`` sections at the predicted oil and housing temperatures, say), which the loader
    writes into the case (the built-in ones, such as the gearbox thermal model's ``"gearbox"``, are named in
    :mod:`thermogear.composition`; one registered here takes precedence). Its gear temperatures come from the
    temperature provider of the same name."""
    if not callable(resolver):
        raise TypeError("a temperature model must be callable: resolver(pieces) -> {field: value}")
    _TEMPERATURE_MODELS[name] = resolver


# --------------------------------------------------------------------------------------------- errors
def _deep_copy(document: Any) -> Any:
    if isinstance(document, dict):
        return {key: _deep_copy(value) for key, value in document.items()}
    if isinstance(document, list):
        return [_deep_copy(value) for value in document]
    return document
