"""The suite's own fuzz (issue 25): every key of every section of the case file set to hostile values, and the
command options that parse text, must give a clean CaseError (or a valid result) — never another exception.
Hypothesis with a bounded number of examples and ``derandomize=True``: deterministic in CI and well under a
minute in all (the case fuzz builds cases only; the command fuzz runs the commands in this process)."""

from __future__ import annotations

import copy
import json
import math
import tomllib
import typing
import warnings
from pathlib import Path

import numpy as np
import pydantic
import pytest
import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermogear.case import case_from_document, parameter_set_path
from thermogear.errors import CaseError, ThermogearError
from thermogear.schema import CaseFile

from inprocess_cli import invoke

FUZZ = settings(max_examples=300, derandomize=True, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
FEW = settings(FUZZ, max_examples=40)


def _model_of(annotation):
    candidates = [annotation, *typing.get_args(annotation)]
    for candidate in list(candidates):
        candidates.extend(typing.get_args(candidate))
    return next((c for c in candidates if isinstance(c, type) and issubclass(c, pydantic.BaseModel)), None)


def _leaf_keys(model=CaseFile, prefix: str = "") -> list[str]:
    keys = []
    for name, field in model.model_fields.items():
        nested = _model_of(field.annotation)
        # a list of tables ([[gearbox.bearings]]) has no dotted path to its keys: the fuzz sets the list whole
        in_list = "list[" in str(field.annotation)
        if nested is not None and name != "vary" and not in_list:
            keys += _leaf_keys(nested, f"{prefix}{name}.")
        else:
            keys.append(prefix + name)
    return keys


#: Every key of every section (gears.pinion.teeth, temperature.flank_c, sweep.vary, ...).
KEYS = sorted(_leaf_keys()) + ["sweep.vary.speed_rpm", "sweep.vary.module_mm", "sweep.vary.sped_rpm"]

SPECIAL_FLOATS = [0.0, -0.0, -1.0, 1e-300, 1e-30, 1e-9, 1e-12, 1e9, 1e30, 1e300, math.nan, math.inf, -math.inf,
                  -273.0, -273.15, 5000.0, 13000.0]
VALUES = st.one_of(
    st.booleans(),
    st.integers(min_value=-10**6, max_value=10**6),
    st.sampled_from(SPECIAL_FLOATS),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(["", "2000", "yes", "nan", "0:1000:10", "-100:100:5", "a:b:c", "1,1", "\x1b[2J", "é" * 3]),
    st.text(max_size=6),
    st.lists(st.sampled_from(SPECIAL_FLOATS + [True, "x", 1]), max_size=4),
    st.lists(st.lists(st.sampled_from([1.0, 40.0, 100.0, -300.0, 2.0, math.nan]), max_size=3), max_size=3),
    st.just({}), st.just({"x": 1}),
)


def _documents() -> dict[str, dict]:
    luo = tomllib.loads(parameter_set_path("luo2019").read_text(encoding="utf-8"))
    plain = {"case": {"name": "plain"},
             "gears": {"module_mm": 3.0, "face_width_mm": 20.0, "pinion": {"teeth": 20}, "wheel": {"teeth": 40}},
             "operating": {"speed_rpm": 1000.0, "torque_nm": 100.0}, "temperature": {"bulk_c": 60.0},
             "dynamics": {"mesh": "nonlinear"}}
    return {"luo2019": luo, "plain": plain}


DOCUMENTS = _documents()


def _set(document: dict, dotted: str, value) -> dict:
    document = copy.deepcopy(document)
    node = document
    *parents, last = dotted.split(".")
    for part in parents:
        child = node.get(part)
        if not isinstance(child, dict):
            child = node[part] = {}
        node = child
    if value is _REMOVE:
        node.pop(last, None)
    else:
        node[last] = value
    return document


_REMOVE = object()


def _takes_a_number(dotted: str) -> bool:
    from thermogear.schema.base import _leaf_kinds

    model, parts = CaseFile, dotted.split(".")
    for part in parts[:-1]:
        if part not in model.model_fields:
            return False
        model = _model_of(model.model_fields[part].annotation)
        if model is None:
            return False
    field = model.model_fields.get(parts[-1])
    return field is not None and bool(_leaf_kinds(field.annotation) & {"number", "integer"}) and not (
        _leaf_kinds(field.annotation) & {"str", "list", "dict"})


@FUZZ
@given(base=st.sampled_from(sorted(DOCUMENTS)), key=st.sampled_from(KEYS),
       value=st.one_of(VALUES, st.just(_REMOVE)))
def test_any_value_of_any_key_is_a_case_or_a_clean_error_naming_it(base, key, value):
    document = _set(DOCUMENTS[base], key, value)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            case = case_from_document(document, source="<fuzz>")
        except CaseError as error:
            assert error.key and str(error)  # key, value, range and reason in one message
            if isinstance(value, (bool, str)) and _takes_a_number(key):  # strict types: the key itself is named
                assert error.key == key, (key, value, str(error))
            return
    # accepted: a number key kept a number, never a boolean or a string coerced into one
    assert not (isinstance(value, (bool, str)) and _takes_a_number(key)), (key, value)
    assert math.isfinite(case.operating_point.torque) and case.operating_point.torque > 0.0


@FEW
@given(key=st.sampled_from(KEYS), value=VALUES)
def test_check_on_a_fuzzed_case_file_exits_0_or_2_with_one_message(key, value, tmp_path_factory):
    path = tmp_path_factory.mktemp("fuzz") / "case.toml"
    try:
        text = tomli_w.dumps(_set(DOCUMENTS["plain"], key, value))
    except (TypeError, ValueError):  # a value TOML cannot hold never reaches a case file
        return
    path.write_text(text, encoding="utf-8")
    code, out, err = invoke("check", str(path))
    assert code in (0, 2), err
    if code == 2:
        assert out == "" and sum(line.startswith("error:") for line in err.splitlines()) == 1, err


@settings(FUZZ, max_examples=15)
@given(key=st.sampled_from(KEYS), value=VALUES)
def test_check_and_the_other_commands_agree_on_a_fuzzed_case(key, value, tmp_path_factory):
    # check = run: a case check refuses, stiffness and damping refuse with the same message; one it accepts they
    # compute (exit 0), never a traceback
    path = tmp_path_factory.mktemp("agree") / "case.toml"
    try:
        path.write_text(tomli_w.dumps(_set(DOCUMENTS["plain"], key, value)), encoding="utf-8")
    except (TypeError, ValueError):
        return
    code, _, err = invoke("check", str(path))
    message = [line for line in err.splitlines() if line.startswith("error:")]
    if code == 2 and message[0].startswith("error: vary."):
        return  # the [sweep] study is defined by check and sweep only (the other commands never read it)
    for command in (["stiffness", str(path), "--json"], ["damping", str(path), "--json", "--points", "64"]):
        other, _, other_err = invoke(*command)
        assert other == code, (command, err, other_err)
        if code == 2:
            assert [line for line in other_err.splitlines() if line.startswith("error:")] == message


@FEW
@given(data=st.binary(max_size=200))
def test_check_on_arbitrary_bytes_is_one_error(data, tmp_path_factory):
    path = tmp_path_factory.mktemp("bytes") / "case.toml"
    path.write_bytes(data)
    code, out, err = invoke("check", str(path))
    assert code == 2 and out == "" and err.startswith("error:"), err


TEXT = st.one_of(st.text(max_size=12), st.sampled_from(["0:inf", "inf:0", "1e308", "-1", "0", "nan", "1:2:3",
                                                         "300:400", "luo2019:", "luo2019:abc", "luo2019:-5",
                                                         "luo2019:1e400", "1,1", "a=b", "speed_rpm=", "=1"]))


@FEW
@given(name=st.sampled_from(["speed_rpm", "sped_rpm", "module_mm", "teeth", "oil_temperature_c",
                             "gears.pinion.teeth", "operating.torque_nm", "case.name"]), values=TEXT)
def test_sweep_vary_text_is_a_study_or_a_clean_error(name, values, luo2019):
    from thermogear.sweep.study import Study

    try:
        Study.define(luo2019, [f"{name}={values}"], model="elastic")
    except CaseError as error:
        assert error.key


@pytest.fixture(scope="module")
def signal_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("signal") / "signal.csv"
    time = np.arange(512) / 4096.0
    path.write_text("time_s,accel\n" + "\n".join(f"{t!r},{np.sin(2 * np.pi * 300 * t)!r}" for t in time),
                    encoding="utf-8")
    return path


@FEW
@given(option=st.sampled_from(["--band", "--scale", "--rate", "--windows", "--segment", "--mesh-frequency",
                               "--column", "--method"]), value=TEXT)
def test_vibration_options_give_a_result_or_one_error(option, value, signal_file):
    code, _, err = invoke("vibration", str(signal_file), option, value, "--json")
    assert code in (0, 2), err
    assert "Traceback" not in err


@FEW
@given(option=st.sampled_from(["--model", "--method"]), value=TEXT)
def test_run_options_are_checked_before_any_work(option, value):
    if value in ("elastic", "thermal", "both", "periodic", "transient"):
        return  # a valid choice runs the dynamics: covered by the run tests
    code, out, err = invoke("run", "luo2019", option, value, "--json")
    assert code == 2 and out == "", err


@FEW
@given(history=TEXT)
def test_warmup_temperature_history_text_is_one_error(history):
    code, out, err = invoke("warmup", "luo2019", "--temperature-history", history, "--json")
    assert code == 2 and out == "" and sum(line.startswith("error:") for line in err.splitlines()) == 1, err


def test_the_fuzz_reaches_every_section():
    sections = {key.split(".")[0] for key in KEYS}
    assert sections == set(CaseFile.model_fields)
    assert issubclass(CaseError, ThermogearError)


# ------------------------------------------------------------------------- the commands the fuzz above leaves out
def _case_file(tmp_path_factory, key, value, name: str):
    path = tmp_path_factory.mktemp(name) / "case.toml"
    try:
        path.write_text(tomli_w.dumps(_set(DOCUMENTS["plain"], key, value)), encoding="utf-8")
    except (TypeError, ValueError):  # a value TOML cannot hold never reaches a case file
        return None
    return path


def _errors(err: str) -> list[str]:
    return [line for line in err.splitlines() if line.startswith("error:")]


def _checked(tmp_path_factory, key, value, name: str):
    """``(path, check's exit status, its stderr)`` of the fuzzed case file, or None where there is nothing to
    compare: TOML cannot hold the value, or check refuses the [sweep] study (read by check and sweep only)."""
    path = _case_file(tmp_path_factory, key, value, name)
    if path is None:
        return None
    code, _, err = invoke("check", str(path))
    if code == 2 and _errors(err)[0].startswith("error: vary."):
        return None
    return path, code, err


@settings(FUZZ, max_examples=12)
@given(key=st.sampled_from(KEYS), value=VALUES)
def test_run_agrees_with_check_on_a_fuzzed_case_and_its_json_is_labelled(key, value, tmp_path_factory):
    # check = run on the command the issues name most; a computed model is labelled (valid, non-periodic or not
    # valid) and a valid one has a finite Kv
    if (checked := _checked(tmp_path_factory, key, value, "run")) is None:
        return
    path, code, err = checked
    other, out, other_err = invoke("run", str(path), "--json")
    assert other == code, (err, other_err)
    if code == 2:
        assert _errors(other_err) == _errors(err)
        return
    for model in json.loads(out)["models"].values():
        assert model["status"] in ("valid", "non-periodic", "not valid")
        assert model["status"] != "valid" or (model["kv"] is not None and math.isfinite(model["kv"]))


@settings(FUZZ, max_examples=15)
@given(key=st.sampled_from(KEYS), value=VALUES)
def test_sweep_fem_and_warmup_refuse_what_check_refuses(key, value, tmp_path_factory):
    # the commands that compute longest are run only where check refuses: they must refuse the same way, at once
    if (checked := _checked(tmp_path_factory, key, value, "refuse")) is None or checked[1] != 2:
        return
    path, _, err = checked
    for command in (["sweep", str(path), "--vary", "speed_rpm=1000,2000", "--out", str(path.parent / "s.zarr")],
                    ["fem", str(path), "--json"],
                    ["warmup", str(path), "--model", "first-order", "--no-dynamics", "--json"]):
        other, out, other_err = invoke(*command)
        assert (other, out, _errors(other_err)) == (2, "", _errors(err)), command
    assert not (path.parent / "s.zarr").exists()


NUMBERS = st.sampled_from(["nan", "inf", "-inf", "-1", "0", "1e-300", "1e308", "-273.15", "5000", "abc", "", "1,2"])


@FEW
@given(option=st.sampled_from(["--start-c", "--final-c", "--time-constant-s", "--duration-s", "--states",
                               "--speed-rpm", "--gear-model"]), value=NUMBERS)
def test_warmup_options_give_a_result_or_one_error(option, value):
    code, out, err = invoke("warmup", "luo2019", "--model", "first-order", "--no-dynamics", option, value, "--json")
    assert code in (0, 2), err
    if code == 2:
        assert out == "" and len(_errors(err)) == 1, err
    else:
        json.loads(out)


@settings(FUZZ, max_examples=20)
@given(option=st.sampled_from(["--speeds", "--torques"]), value=TEXT)
def test_gearbox_options_give_a_result_or_one_error(option, value):
    case = str(Path(__file__).resolve().parents[1] / "data" / "gearbox" / "fzg_gearbox.toml")
    code, out, err = invoke("gearbox", case, option, value, "--json")
    assert code in (0, 2), err
    if code == 2:
        assert out == "" and len(_errors(err)) == 1, err


@FEW
@given(option=st.sampled_from(["--rule", "--points"]), value=st.one_of(TEXT, NUMBERS))
def test_damping_options_give_a_result_or_one_error(option, value):
    code, out, err = invoke("damping", "luo2019", option, value, "--json")
    assert code in (0, 2), err
    if code == 2:
        assert out == "" and len(_errors(err)) == 1, err


@pytest.fixture(scope="module")
def branch_store(tmp_path_factory):
    import xarray as xr

    from thermogear.sweep.branches import write_branch_store

    dataset = xr.Dataset({"kv": (("direction", "speed_rpm"), np.ones((2, 3)))},
                         coords={"direction": ["up", "down"], "speed_rpm": [1000.0, 2000.0, 3000.0]},
                         attrs={"case": "plain", "load": "constant torque"})
    return write_branch_store(dataset, tmp_path_factory.mktemp("store") / "study.zarr")


@FEW
@given(option=st.sampled_from(["--dimension", "--group", "--out", "SOURCE"]), value=TEXT)
def test_export_options_give_a_table_or_one_error(option, value, branch_store, tmp_path_factory):
    if option == "--out":
        value = str(tmp_path_factory.mktemp("csv") / (value.replace("/", "_").replace("\x00", "") or "x"))
    arguments = [value] if option == "SOURCE" else [str(branch_store), option, value]
    code, out, err = invoke("export", *arguments)
    assert code in (0, 2), err
    if code == 2:
        assert out == "" and len(_errors(err)) == 1, err


@FEW
@given(paper=TEXT)
def test_reproduce_refuses_an_unknown_paper_at_once(paper, tmp_path_factory):
    if paper == "luo2019":
        return
    out_folder = tmp_path_factory.mktemp("reproduce") / "report"
    code, out, err = invoke("reproduce", paper, "--out", str(out_folder))
    assert code == 2 and len(_errors(err)) == 1, err
    assert not out_folder.exists()
