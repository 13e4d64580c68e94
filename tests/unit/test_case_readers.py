"""How many functions take a whole Case: the count may only fall (issue 26: physics functions and components take
the small frozen inputs a case resolves into, not the Case).

A function takes a whole case when one of its parameters is annotated ``Case`` (or ``"Case"``) or is named
``case`` without a ``str`` annotation (a command's ``case: str`` argument is the name or path the user typed, which
the command resolves; it is not a Case). The scan reads the source (AST), so it counts nested functions and methods
too.
"""

from __future__ import annotations

import ast
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2] / "src" / "thermogear"

#: Upper bound on the functions taking a whole Case: 109 at bff64a9, 107 after the pair-model seam (116 once the
#: drivetrain and gearbox merges landed), 69 once the case is resolved once (issue 26: luo2020's PaperThermalModel,
#: the thermo-elastic builder, the summaries, fem, gearbox, sweep and report helpers take the small inputs), 59 once
#: the drivetrain's results, report data and run outputs take the built CaseDrivetrain (through its builder). Lower
#: it when a change brings the count down; never raise it (a new function takes the resolved inputs it needs: the
#: gear pair, the operating point, a section, not the Case). 61 once a command's ``case: str`` argument was no longer
#: counted; 35 once fem (FemInputs), the paper's k_T (PaperThermalModel methods), the summaries (ThermalModels), the
#: gearbox steady state, the sweep point, export and check took what they read. Those left are the resolvers, the
#: load-time checks, the temperature providers (their protocol passes the case) and the entry points. 31 once the
#: drivetrain's results and its speed sweeps take the built CaseDrivetrain. Raised to 49 by stop 32's nine merged
#: branches, against this rule, and said so in its note: new resolvers (a train's stages, the mesh table file, the
#: coupled heat of gearbox and drivetrain, the drivetrain's bearings for the loss model) and entry points
#: (thermogear.run, thermogear.sweep, the gearbox grid on the executor). Issue 33 asks for at most 15 and stays open
#: until it is brought down; bring it down, never up again. 36 (from 50) once the load-time checks take the sections
#: they check (temperature field, X_te inputs, the model limits), the picture folder the [drivetrain] section, the
#: drivetrain bearings' loads and losses the section, pair and material, the gearbox description its pieces (the case
#: resolved once, by gearbox_model_from_case), the coupled heat's parts the gearbox model and sections, the mesh
#: table's resolver is its own load-time check, the drivetrain's heat provider and the predicted-temperature model
#: are looked up by their one resolver, and preflight is asked through the Orchestrator. 35 once main's study kinds
#: (the warm-up kind and study_kind, merged at 38) pick a case's kind from its StudySubject, resolved once. 28 once
#: the checks and providers of thermogear.composition receive the pieces of the case they name
#: (thermogear.case.pieces.call_with_pieces: the FE and gearbox temperature providers, the FE X_te, the network's
#: drivetrain heat, the gearbox and damping-law checks; +1 for call_with_pieces itself), study_kind takes the
#: StudySubject and the held load of a sweep the case's [operating] keys and operating point. 27 once the callable
#: module thermogear.sweep forwards its arguments to thermogear.sweep.api.study (the entry point) unread. 22 once the
#: memoised resolvers name the pieces they read and thermogear.case.cached_per_case reads the case for them (the oil,
#: the gearbox network, the mesh table, the thermo-elastic mesh: called with the case as before, each declares its
#: inputs) and StudySubject.of takes the three sections it reads. Left: the machinery that reads the case for the
#: others (check_case, cached_per_case, call_with_pieces), the entry points (thermogear.run, evaluate_case, the
#: report, the sweeps and Study.define/from_description, the warm-ups, the gearbox grid) and the resolvers that
#: write a new case or hand the case on lazily (the warm-up states, fem_inputs, the gearbox's predicted
#: temperatures, the stages' cases, the drivetrain, the paper's k_T, the pair model, the temperature field) and
#: PredictedTemperatureError, which carries the unresolved case. The next step to 15: those resolvers onto pieces.
#: 20 once Study.from_description, which nothing called, was removed (the store's --resume compares describe()),
#: and the pair model is chosen from the two names it reads (pair_model_class(model, thermal_model)).
#: 18 once the tooth temperature field and the paper's k_T model name their pieces (the provider a section chooses
#: by name is a piece, thermogear.composition.CHOSEN_PIECES; a piece needed on some paths only is asked for later,
#: ``temperature_field_of``; the paper's per-case memo is the piece paper_thermal_memo).
#: 16 once the gearbox's temperature model returns the parts of the case it predicts (the loader writes them;
#: predicted_temperatures names its pieces) and PredictedTemperatureError carries the steady state and the key it
#: reports, not the unresolved case (the network's commands load with predict_temperatures=False).
#: 15 once a train's further stages are resolved from the pieces they read (stage_train: the [drivetrain] section,
#: the built stages, the first pair and the operating point give each stage's changes, speed, repeats and phase)
#: and the drivetrain's resolver writes the stages' cases. Left: the machinery (check_case, cached_per_case,
#: call_with_pieces), the entry points (thermogear.run, evaluate_case, the report, thermogear.sweep's study,
#: Study.define, the gearbox grid, the two warm-ups) and the resolvers that write new cases (case_drivetrain,
#: fem_inputs, the two warm-ups' state_case: one at a measured temperature through the checked case file, one at
#: the network's node temperatures through its sections, without re-reading the case: about 30-190 ms against
#: the 20 ms of a state's periodic solve; both hold a calibrated X_te by one rule, held_x_te, which names its pieces).
MAXIMUM_CASE_READERS = 15


def _takes_case(argument: ast.arg) -> bool:
    annotation = argument.annotation
    if isinstance(annotation, ast.Constant) and isinstance(annotation.value, str):
        name = annotation.value.strip()
    elif annotation is not None:
        name = ast.unparse(annotation)
    else:
        name = ""
    if name == "str":
        return False
    return argument.arg == "case" or name in ("Case", "thermogear.case.Case")


def case_readers(source: Path = SOURCE) -> list[str]:
    """``module:function`` of every function with a parameter that is a whole Case."""
    found = []
    for path in sorted(source.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                arguments = node.args
                every = [*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs]
                if any(_takes_case(argument) for argument in every):
                    name = getattr(node, "name", "<lambda>")
                    found.append(f"{path.relative_to(source).with_suffix('')}:{name}:{node.lineno}")
    return found


def test_functions_taking_a_whole_case_do_not_grow():
    readers = case_readers()
    assert len(readers) <= MAXIMUM_CASE_READERS, "\n".join(readers)


def test_the_scan_finds_a_case_parameter(tmp_path):
    # the count can fail: each of the three spellings is found, a function without one is not
    (tmp_path / "module.py").write_text("def a(case): ...\ndef b(x: 'Case'): ...\ndef c(x: Case): ...\n"
                                        "def d(x: int, cases=None): ...\ndef e(case: str): ...\n", encoding="utf-8")
    assert [item.split(":")[1] for item in case_readers(tmp_path)] == ["a", "b", "c"]
