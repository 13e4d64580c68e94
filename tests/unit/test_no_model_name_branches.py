"""No behaviour of thermogear is keyed on a model's name outside the modules that resolve names (issue 26).

A model name (a simulation model, ``"elastic"`` or ``"thermal"``; a pair model; a ``[thermal] model``) is resolved
once: :mod:`thermogear.mesh.pair_models` turns it into a pair model, :mod:`thermogear.choices.thermal_models` into the
input rules of a thermal model, :mod:`thermogear.mesh.model_names` holds the two simulation models' names. Anywhere
else, code asks the model what it declares (``pair_model.thermal``, ``rules.reads_x_te``, ``rules.temperature_limits``)
instead of testing its name. The AST scan below finds, outside those modules:

* a comparison (``==``, ``!=``, ``in``, ``not in``, ``is``) with a string literal that is a model name, alone or in a
  tuple, list or set display (``model == "thermal"``, ``name in ("luo2020", "thermoelastic")``);
* a second table or list of the thermal models by name: a dict display keyed by, or a tuple, list or set display
  holding, a thermal model's name (``{"thermoelastic": ..., "luo2020": ...}``).

The names are read from the registries, so a model added there is scanned too.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import thermogear
from thermogear.mesh.model_names import MODELS
from thermogear.mesh.pair_models import PAIR_MODELS
from thermogear.choices.thermal_models import THERMAL_MODEL_RULES

SOURCE = Path(thermogear.__file__).parent

#: Where model names are resolved (the registries): the only modules allowed to compare them.
REGISTRY_MODULES = ("mesh/pair_models.py", "mesh/model_names.py", "choices/thermal_models.py")

#: Every model name: the simulation models, the pair models and the thermal models of case files.
MODEL_NAMES = frozenset(MODELS) | frozenset(PAIR_MODELS) | frozenset(THERMAL_MODEL_RULES)
#: The names of the models a case file chooses in ``[thermal] model`` and of pair models beyond the two simulation
#: models: no second table of them may exist.
THERMAL_MODEL_NAMES = (frozenset(THERMAL_MODEL_RULES) | frozenset(PAIR_MODELS)) - frozenset(MODELS)

#: Comparisons left on purpose, each with its reason: (module, number of hits). None now: the drivetrain's case model
#: selects its runs by the ELASTIC / THERMAL constants of thermogear.mesh.model_names.
KNOWN: dict[str, int] = {}


def _literals(node: ast.AST) -> list[str]:
    """The string constants of a node: itself, or the elements of a tuple, list or set display."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [node.value]
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return [value for element in node.elts for value in _literals(element)]
    return []


def model_name_branches(source: str, model_names=MODEL_NAMES, thermal_names=THERMAL_MODEL_NAMES) -> list[str]:
    """``line: code`` of every comparison with a model name and every table of thermal model names in ``source``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            if any(value in model_names for side in sides for value in _literals(side)):
                found.append(f"{node.lineno}: {ast.unparse(node)}")
        elif isinstance(node, ast.Dict):
            if any(value in thermal_names for key in node.keys if key is not None for value in _literals(key)):
                found.append(f"{node.lineno}: dict keyed by thermal model names")
        elif isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            if sum(value in thermal_names for value in _literals(node)) >= 2:
                found.append(f"{node.lineno}: {ast.unparse(node)}")
    return found


def _package_hits() -> dict[str, list[str]]:
    hits = {}
    for path in sorted(SOURCE.rglob("*.py")):
        relative = path.relative_to(SOURCE).as_posix()
        if relative in REGISTRY_MODULES:
            continue
        found = model_name_branches(path.read_text(encoding="utf-8"))
        if found:
            hits[relative] = found
    return hits


def test_the_names_come_from_the_registries():
    assert {"elastic", "thermal"} <= MODEL_NAMES and {"luo2020", "thermoelastic"} <= THERMAL_MODEL_NAMES


def test_no_module_outside_the_registries_branches_on_a_model_name():
    hits = _package_hits()
    unexpected = {path: found for path, found in hits.items() if len(found) != KNOWN.get(path, 0)}
    assert not unexpected, unexpected
    # every allowance is still needed (a mended module leaves the list)
    assert {path: len(found) for path, found in hits.items()} == KNOWN


def test_the_scan_finds_what_the_code_did_before(tmp_path):
    # the forms the package held before the seam (issue 26), one per line, written to a file and read back
    source = tmp_path / "before.py"
    source.write_text(
        'TEMPERATURE_LIMITS = {"thermoelastic": 1, "luo2020": 2}\n'
        'if getattr(section, "model", "luo2020") != "luo2020":\n    pass\n'
        'if thermal.model != "luo2020":\n    pass\n'
        'for name in ("luo2020", "thermoelastic"):\n    pass\n'
        'mesh = MeshModel(case, "elastic" if name == "elastic" else "thermal")\n'
        'flag = self.model == "thermal"\n'
        'shown = "thermal" in models\n'
        'columns = ["elastic", "luo2020", "thermoelastic"]\n', encoding="utf-8")
    lines = sorted(int(hit.split(":")[0]) for hit in model_name_branches(source.read_text(encoding="utf-8")))
    assert lines == [1, 2, 4, 6, 8, 9, 10, 11]


def test_the_scan_passes_what_the_seam_writes():
    # asking the model, and a name as a plain value (a default, a dict key of results, a label), is no branch
    source = ('if not thermal_model_rules(section.model).reads_x_te:\n    pass\n'
              'flags = thermal_result_flags(mesh) if mesh.thermal else []\n'
              'result = {"elastic": 1.0, "thermal": 2.0}\n'
              'simulation = Simulation(case, "thermal")\n'
              'if THERMAL in models:\n    pass\n')
    assert model_name_branches(source) == []


#: Where the solution methods (``[dynamics] method``) and the sources of X_te (``[thermal] x_te_source``) are resolved
#: from their names (issue 33: no method chosen by comparing a string outside one registry).
METHOD_REGISTRIES = ("dynamics/problems/solution_methods.py", "choices/thermal_models.py")
#: Comparisons with those names left on purpose: a response's kind (``metrics["response"]``: "periodic",
#: "subharmonic", "non-periodic", "not settled") shares the word "periodic" with the method and is not a method.
METHOD_KNOWN = {"report/evaluate.py": 1}


def test_solution_methods_and_x_te_sources_are_compared_only_in_their_registries():
    from thermogear.dynamics.problems.solution_methods import SOLUTION_METHODS
    from thermogear.choices.thermal_models import X_TE_SOURCES

    names = frozenset(SOLUTION_METHODS) | frozenset(X_TE_SOURCES)
    hits = {}
    for path in sorted(SOURCE.rglob("*.py")):
        relative = path.relative_to(SOURCE).as_posix()
        found = [] if relative in METHOD_REGISTRIES else model_name_branches(path.read_text(encoding="utf-8"),
                                                                              names, frozenset())
        if len(found) > METHOD_KNOWN.get(relative, 0):
            hits[relative] = found
    assert not hits, hits
    # the scan can fail: a comparison of a method's name is found
    assert model_name_branches('if method == "transient": pass\n', names, frozenset())


def test_the_schema_accepts_exactly_the_registered_methods_and_x_te_sources():
    import typing

    from thermogear.dynamics.problems.solution_methods import SOLUTION_METHODS
    from thermogear.schema.dynamics import DynamicsSection
    from thermogear.schema.thermal import ThermalSection
    from thermogear.choices.thermal_models import X_TE_SOURCES

    assert typing.get_args(DynamicsSection.model_fields["method"].annotation) == tuple(SOLUTION_METHODS)
    assert typing.get_args(ThermalSection.model_fields["x_te_source"].annotation) == tuple(X_TE_SOURCES)


def _choice_registries() -> dict:
    """(registry module, the names it resolves) of every other choice of a model, method or law by name
    (issue 33): each name is compared in its registry only, every other module asks the resolved object."""
    from thermogear.cli.warmup import WARMUP_MODELS
    from thermogear.friction.damping import DAMPING_RULES, DAMPING_STIFFNESSES
    from thermogear.choices.drivetrain import END_KINDS, ROTATIONS
    from thermogear.dynamics.problems.damping_modes import DAMPING_MODES
    from thermogear.gearbox.injection import JET_POSITIONS
    from thermogear.experiment.spectrum import SPECTRUM_METHODS
    from thermogear.fem.elasticity import PLANE_ASSUMPTIONS
    from thermogear.fem.tooth_heat import BORE_CONDITIONS
    from thermogear.friction.models import FRICTION_MODELS
    from thermogear.gearbox.bearing_entries import BEARING_TYPES
    from thermogear.lubricant.methods import LUBRICATION_METHODS
    from thermogear.luo2020.thermal.case_inputs import LOAD_BASES
    from thermogear.luo2020.thermal.expansion import EXPANSION_FORMS
    from thermogear.sweep.evaluation_methods import EVALUATION_METHODS
    from thermogear.sweep.load_held import HOLDS
    from thermogear.sweep.schedulers import LOCAL_DEFAULT_NAMES, SCHEDULERS
    from thermogear.dynamics.problems.continuation_directions import DIRECTIONS, STUDY_DIRECTIONS

    return {
        "lubrication method ([gearbox.oil] lubrication)": ("lubricant/methods.py", LUBRICATION_METHODS),
        "warm-up model (warmup --model)": ("cli/warmup.py", WARMUP_MODELS),
        "evaluation method of a study (sweep --method)": ("sweep/evaluation_methods.py", EVALUATION_METHODS),
        "mesh-damping rule ([damping] rule)": ("friction/damping.py", DAMPING_RULES),
        "form of Eq. 9 ([thermal] expansion_model)": ("luo2020/thermal/expansion.py", EXPANSION_FORMS),
        "friction law (friction_model)": ("friction/models.py", FRICTION_MODELS),
        "load basis of the paper's k_T ([thermal] load_basis)": ("luo2020/thermal/case_inputs.py", LOAD_BASES),
        "spectrum estimate (vibration --method)": ("experiment/spectrum.py", SPECTRUM_METHODS),
        "plane assumption of the FE model ([fem] plane)": ("fem/elasticity.py", PLANE_ASSUMPTIONS),
        "bore condition of the FE heat model ([fem] bore)": ("fem/tooth_heat.py", BORE_CONDITIONS),
        "bearing type of a loss entry (type)": ("gearbox/bearing_entries.py", BEARING_TYPES),
        "mesh damping in flight ([dynamics] damping_in_flight)": ("dynamics/problems/damping_modes.py", DAMPING_MODES),
        "load a speed sweep holds (sweep --hold)": ("sweep/load_held.py", HOLDS),
        "kind of a train's end ([drivetrain.driving] kind)": ("choices/drivetrain.py", END_KINDS),
        "pinion's turning sense ([drivetrain] pinion_rotation)": ("choices/drivetrain.py", ROTATIONS),
        "scheduler of a study (--scheduler)": ("sweep/schedulers.py",
                                               (*SCHEDULERS, *(name for name in LOCAL_DEFAULT_NAMES if name))),
        "direction of a branch (--direction)": ("dynamics/problems/continuation_directions.py",
                                                (*DIRECTIONS, *STUDY_DIRECTIONS)),
        "pair stiffness of the damping ([damping] stiffness)": ("friction/damping.py", DAMPING_STIFFNESSES),
        "aim of an oil jet ([gearbox.oil] jet_position)": ("gearbox/injection.py", JET_POSITIONS),
    }


CHOICES = ("lubrication method ([gearbox.oil] lubrication)", "warm-up model (warmup --model)",
           "evaluation method of a study (sweep --method)", "mesh-damping rule ([damping] rule)",
           "form of Eq. 9 ([thermal] expansion_model)", "friction law (friction_model)",
           "load basis of the paper's k_T ([thermal] load_basis)", "spectrum estimate (vibration --method)",
           "plane assumption of the FE model ([fem] plane)", "bore condition of the FE heat model ([fem] bore)",
           "bearing type of a loss entry (type)", "mesh damping in flight ([dynamics] damping_in_flight)",
           "load a speed sweep holds (sweep --hold)", "kind of a train's end ([drivetrain.driving] kind)",
           "pinion's turning sense ([drivetrain] pinion_rotation)", "scheduler of a study (--scheduler)",
           "direction of a branch (--direction)", "pair stiffness of the damping ([damping] stiffness)",
           "aim of an oil jet ([gearbox.oil] jet_position)")


@pytest.mark.parametrize("choice", CHOICES)
def test_every_choice_is_compared_only_in_its_registry(choice):
    # at 98809ca: lubrication == "injection" (gearbox x2, schema), == "dip" (gearbox input checks), model ==
    # "gearbox" (cli/warmup x2), method == "batch" (cli/sweep x2, sweep/api, sweep/batch, sweep/engine), rule ==
    # "paper" (damping, damping plots), circumferential == "consistent" (luo2020/expansion), basis == "external"
    # (luo2020 x2), method == "fft" (spectrum), plane == "stress" (fem x4), bore == "convective", type ==
    # "deep_groove_ball" (gearbox bearing entries)
    registry, names = _choice_registries()[choice]
    hits = {}
    for path in sorted(SOURCE.rglob("*.py")):
        relative = path.relative_to(SOURCE).as_posix()
        if relative != registry and (found := model_name_branches(path.read_text(encoding="utf-8"),
                                                                  frozenset(names), frozenset())):
            hits[relative] = found
    assert {path: len(found) for path, found in hits.items()} == CHOICES_KNOWN.get(choice, {}), hits


#: Comparisons left on purpose, with their reason. None now: the schema checks the keys of a friction law by what
#: the law declares in :mod:`thermogear.choices.friction` (below the schema), not by its name.
CHOICES_KNOWN: dict[str, dict[str, int]] = {}


def test_the_choice_scan_finds_the_forms_the_package_held():
    source = ('injection = section.oil.lubrication == "injection"\n'
              'if model == "gearbox":\n    pass\n'
              'flag = subject.backlash and method == "batch"\n'
              'show = summary.rule == "paper"\n'
              'if model != "constant":\n    pass\n'  # the schema's before issue 33's friction declaration
              'jet = lubrication_method(section.oil.lubrication).oil_jet\n')
    names = frozenset().union(*(frozenset(names) for _, names in _choice_registries().values()))
    assert sorted(int(hit.split(":")[0]) for hit in model_name_branches(source, names, frozenset())) == [1, 2, 4, 5, 6]


def test_the_schema_accepts_exactly_the_registered_choices():
    import typing

    from thermogear.friction.damping import DAMPING_RULES
    from thermogear.lubricant.methods import LUBRICATION_METHODS
    from thermogear.luo2020.thermal.expansion import EXPANSION_FORMS
    from thermogear.schema.dynamics import DampingSection
    from thermogear.schema.gearbox import GearboxOilSection
    from thermogear.schema.thermal import ThermalSection

    assert typing.get_args(GearboxOilSection.model_fields["lubrication"].annotation) == tuple(LUBRICATION_METHODS)
    assert set(typing.get_args(DampingSection.model_fields["rule"].annotation)) == set(DAMPING_RULES)
    assert set(typing.get_args(ThermalSection.model_fields["expansion_model"].annotation)) == set(EXPANSION_FORMS)
    from thermogear.fem.elasticity import PLANE_ASSUMPTIONS
    from thermogear.fem.tooth_heat import BORE_CONDITIONS
    from thermogear.luo2020.thermal.case_inputs import LOAD_BASES
    from thermogear.schema.fem import FemSection

    assert set(typing.get_args(ThermalSection.model_fields["load_basis"].annotation)) == set(LOAD_BASES)
    assert set(typing.get_args(FemSection.model_fields["plane"].annotation)) == set(PLANE_ASSUMPTIONS)
    assert set(typing.get_args(FemSection.model_fields["bore"].annotation)) == set(BORE_CONDITIONS)
    from thermogear.dynamics.problems.damping_modes import DAMPING_MODES
    from thermogear.schema.dynamics import DynamicsSection

    assert typing.get_args(DynamicsSection.model_fields["damping_in_flight"].annotation) == tuple(DAMPING_MODES)
    from thermogear.choices.drivetrain import END_KINDS, ROTATIONS
    from thermogear.schema.drivetrain import DrivetrainSection, EndSection

    assert typing.get_args(EndSection.model_fields["kind"].annotation) == tuple(END_KINDS)
    from thermogear.friction.damping import DAMPING_STIFFNESSES
    from thermogear.gearbox.injection import JET_POSITIONS

    assert typing.get_args(DampingSection.model_fields["stiffness"].annotation) == tuple(DAMPING_STIFFNESSES)
    assert typing.get_args(GearboxOilSection.model_fields["jet_position"].annotation) == tuple(JET_POSITIONS)
    assert typing.get_args(DrivetrainSection.model_fields["pinion_rotation"].annotation) == tuple(ROTATIONS)


def test_a_bearing_entry_of_each_type_is_that_type():
    # the registry's factories read an entry's sliding constants as the type needs them (two for a roller, the
    # first for a ball bearing)
    from types import SimpleNamespace

    from thermogear.gearbox.bearing_entries import rolling_bearing
    from thermogear.gearbox.bearing_loss import RollingBearing

    constants = dict(bore_mm=30.0, outside_mm=90.0, width_mm=23.0, rolling_constant=1.09e-6, geometry_constant=5.1)
    entry = dict(designation=None, sliding_constants=[0.16, 0.0015], drag_variable=None, **constants)
    ball = rolling_bearing(SimpleNamespace(type="deep_groove_ball", **entry))
    roller = rolling_bearing(SimpleNamespace(type="cylindrical_roller", **entry))
    assert ball == RollingBearing.deep_groove_ball(sliding_constant=0.16, drag_variable=0.0, **constants)
    assert roller == RollingBearing.cylindrical_roller(sliding_constants=(0.16, 0.0015), drag_variable=0.0,
                                                       **constants)
    assert not ball.roller and roller.roller


def test_a_name_outside_a_registry_is_refused_naming_the_key_and_the_registered_names():
    from thermogear.errors import CaseError
    from thermogear.lubricant.methods import lubrication_method

    assert lubrication_method("injection").oil_jet and lubrication_method("dip").wheel_dipped
    with pytest.raises(CaseError) as caught:
        lubrication_method("mist")
    assert caught.value.key == "gearbox.oil.lubrication" and "dip | injection" in str(caught.value)


def test_the_command_line_offers_exactly_the_registered_schedulers_and_directions():
    # the --scheduler and --direction help texts are written from the registries, so they list every name and no
    # other (a name in the help that the registry does not resolve would be a promise the command breaks)
    import inspect
    import re

    from thermogear.cli.gearbox import gearbox
    from thermogear.cli.sweep import sweep
    from thermogear.dynamics.problems.continuation_directions import STUDY_DIRECTIONS
    from thermogear.sweep.schedulers import SCHEDULERS

    def help_of(command, name: str) -> str:
        return inspect.signature(command).parameters[name].default.help

    for command in (sweep, gearbox):
        listed = re.match(r"([a-z]+(?: \| [a-z]+)*), or ", help_of(command, "scheduler")).group(1)
        assert listed.split(" | ") == list(SCHEDULERS), command
    listed = re.search(r"speed ([a-z]+(?: \| [a-z]+)*) \(default", help_of(sweep, "direction")).group(1)
    assert listed.split(" | ") == list(STUDY_DIRECTIONS)


def test_the_friction_declaration_names_every_law_and_says_what_each_law_does():
    # the schema reads FRICTION_INPUTS (below it), the laws FRICTION_MODELS (above it): the same names, in order, and
    # each declared fact is what the law does with the key
    import typing

    from thermogear.friction.models import FRICTION_MODELS, PitchContact
    from thermogear.choices.friction import FRICTION_INPUTS
    from thermogear.schema.dynamics import DampingSection
    from thermogear.schema.gearbox import GearboxSection

    assert tuple(FRICTION_INPUTS) == tuple(FRICTION_MODELS)
    for section in (GearboxSection, DampingSection):
        assert set(typing.get_args(section.model_fields["friction_model"].annotation)) == set(FRICTION_INPUTS)
    contact = dict(unit_load=300e3, roughness=0.5e-6, viscosity=0.02, sum_velocity=10.0, relative_radius=0.01)
    for name, law in FRICTION_MODELS.items():
        assert law.inputs is FRICTION_INPUTS[name]
        plain, doubled = (law.coefficient(PitchContact(**contact, lubricant_factor=factor), 0.05, warn=False)
                          for factor in (1.0, 2.0))
        assert (doubled != plain) == law.inputs.takes_lubricant_factor, name  # X_L acts exactly where declared
        given = law.coefficient(PitchContact(**contact, lubricant_factor=1.0), 0.07, warn=False)
        assert (given == 0.07) == law.inputs.takes_coefficient, name  # the given μ is the result exactly there
        if law.inputs.takes_coefficient:
            with pytest.raises(Exception):
                law.coefficient(PitchContact(**contact, lubricant_factor=1.0), None, warn=False)


@pytest.mark.parametrize("section", ["gearbox", "damping"])
def test_the_friction_keys_are_checked_by_what_the_law_declares(section):
    from thermogear.errors import CaseError
    from thermogear.schema.friction_inputs import check_friction_inputs

    check_friction_inputs(section, "constant", 0.05, None)
    check_friction_inputs(section, "schlenk", None, 0.8)
    for model, coefficient, factor, key in (("constant", None, None, "friction_coefficient"),
                                            ("paper", 0.05, None, "friction_coefficient"),
                                            ("constant", 0.05, 0.8, "lubricant_factor")):
        with pytest.raises(CaseError) as caught:
            check_friction_inputs(section, model, coefficient, factor)
        assert caught.value.key == f"{section}.{key}"
