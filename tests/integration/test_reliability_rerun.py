"""What was left on issues 24 and 25, each a defect found by rerunning the issues' commands as written:

* the sweep outputs (summary, ``--json``, the store's attributes, the CSV export) name the load held — constant
  torque or constant power — as ``run`` does (only the plot title said it);
* ``check --json`` lists the warnings ``check`` prints (keys without effect) and the model-choice flag ``run``
  gives every result (the paper's secant k_T in the nonlinear mesh): check = run;
* ``write_branch_store`` itself refuses a store holding a user's file (only the command line checked);
* a ``--plot`` target no one can write is refused before any computing, also as root (a path whose parent is a
  regular file, and a path inside /proc/self, where not even root can create a file: procfs has no regular files
  to create, whatever the permissions);
* random spur pairs through stiffness and both meshes (benchmarks/random_pairs.py, a derandomised draw).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from thermogear.errors import CaseError
from thermogear.sweep.load_held import study_load_held
from thermogear.sweep.study import Study

from inprocess_cli import invoke

LINEAR = ("--model", "elastic", "--scheduler", "serial", "--no-progress")
USER_PAIR = """[case]
name = "user_pair"
[gears]
module_mm = 3.0
face_width_mm = 20.0
[gears.pinion]
teeth = 21
[gears.wheel]
teeth = 27
[operating]
speed_rpm = 3000.0
torque_nm = 150.0
[temperature]
bulk_c = 85.0
"""


# ------------------------------------------------------------------------------------------------ load held
@pytest.mark.parametrize("vary, held, because", [
    (["speed_rpm=1000,2000"], "constant torque", "holds its torque at 2000 rpm"),  # luo2019 gives 80 kW
    (["speed_rpm=1000,2000", "power_kw=10,20"], "constant power", "power_kw is varied"),
    (["speed_rpm=1000,2000", "torque_nm=100,200"], "constant torque", "torque_nm is varied"),
    (["oil_temperature_c=40,60"], "constant power", "its one speed"),  # no speed axis: the case's own load
])
def test_the_load_a_study_holds_follows_what_its_points_are_computed_with(luo2019, vary, held, because):
    study = Study.define(luo2019, vary, model="elastic")
    label, note = study_load_held(study)
    assert (label, because in note) == (held, True), note
    if study.dims == ("speed_rpm",):  # the label is what the points do: one torque at both speeds
        torques = [study.case_at((speed,)).operating_point.torque_at(speed) for speed in (1000.0, 2000.0)]
        assert torques[0] == pytest.approx(torques[1], rel=1e-12)


def test_a_linear_sweep_names_the_load_in_its_summary_json_store_and_csv(tmp_path):
    store = tmp_path / "study.zarr"
    code, out, err = invoke("sweep", "luo2019", "--vary", "speed_rpm=1000,2000", "--vary", "power_kw=10,20",
                            "--out", str(store), "--json", "--method", "simulation", *LINEAR)
    assert code == 0, err
    summary = json.loads(out)
    assert summary["load_held"] == "constant power" and "power_kw" in summary["load_held_note"]
    import zarr

    attributes = dict(zarr.open_group(str(store), mode="r").attrs)
    assert attributes["load"] == "constant power" and attributes["load_note"] == summary["load_held_note"]
    code, csv, err = invoke("export", str(store))
    assert code == 0, err
    assert "# load held: constant power (power_kw is varied" in csv
    code, out, err = invoke("sweep", "luo2019", "--vary", "speed_rpm=1000,2000", "--out", str(tmp_path / "t.zarr"),
                            "--method", "simulation", *LINEAR)
    assert code == 0, err
    assert "load held: constant torque (the case gives a power" in out


def test_a_branch_sweep_names_the_load_in_its_summary_json_store_and_csv(tmp_path):
    store = tmp_path / "branches.zarr"
    code, out, err = invoke("sweep", "fzg_type_c", "--vary", "speed_rpm=1000,2000", "--out", str(store), "--json",
                            "--model", "elastic", "--no-progress")
    assert code == 0, err
    summary = json.loads(out)
    assert summary["load_held"] == "constant torque" and "the case's torque" in summary["load_held_note"]
    import zarr

    assert dict(zarr.open_group(str(store), mode="r").attrs)["load"] == "constant torque"
    code, csv, err = invoke("export", str(store))
    assert code == 0 and "# load held: constant torque" in csv and "# case: fzg_type_c" in csv, err
    code, out, err = invoke("sweep", "fzg_type_c", "--vary", "speed_rpm=1000,2000", "--vary", "power_kw=5,10",
                            "--out", str(tmp_path / "p.zarr"), "--model", "elastic", "--no-progress")
    assert code == 0 and "load held: constant power" in out, err


def test_run_csv_names_the_load(tmp_path):
    code, _, err = invoke("run", "luo2019", "--model", "elastic", "--csv", str(tmp_path / "luo.csv"), "-q")
    assert code == 0, err
    assert "# load held: constant power" in (tmp_path / "luo.csv").read_text(encoding="utf-8")


# ------------------------------------------------------------------------------------------------ check --json
def test_check_json_lists_the_warnings_check_prints(tmp_path):
    path = tmp_path / "given.toml"
    path.write_text(USER_PAIR + '[thermal]\nx_te_source = "given"\n', encoding="utf-8")
    code, out, err = invoke("check", str(path), "--json")
    assert code == 0, err
    warnings = json.loads(out)["warnings"]
    assert len(warnings) == 1 and warnings[0].startswith("thermal.x_te_source: no effect"), warnings
    code, out, _ = invoke("check", str(tmp_path / "given.toml"))
    assert code == 0 and "case is valid" in out


def test_check_says_what_run_flags_on_the_papers_stiffness_in_the_nonlinear_mesh(tmp_path):
    path = tmp_path / "paper_nonlinear.toml"
    path.write_text(USER_PAIR + '[thermal]\nmodel = "luo2020"\nx_te = 1.0\n[dynamics]\nmesh = "nonlinear"\n',
                    encoding="utf-8")
    code, out, err = invoke("check", str(path), "--json")
    assert code == 0, err
    flags = json.loads(out)["model_checks"]
    assert len(flags) == 1 and "secant stiffness" in flags[0]
    code, out, _ = invoke("check", str(path))
    assert code == 0 and "check — the paper's k_T" in out
    code, out, _ = invoke("check", "luo2019", "--json")  # the paper's model in the linear mesh: nothing to flag
    assert json.loads(out)["model_checks"] == []


# ------------------------------------------------------------------------------------------------ own outputs
def _branch_dataset():
    import xarray as xr

    return xr.Dataset({"kv": (("speed_rpm",), np.array([1.0, 1.1]))}, coords={"speed_rpm": [1000.0, 2000.0]})


def test_write_branch_store_itself_refuses_a_store_holding_a_users_file(tmp_path):
    import xarray as xr

    from thermogear.sweep.branches import write_branch_store

    target = write_branch_store(_branch_dataset(), tmp_path / "b.zarr")
    (target / "notes.txt").write_text("my notes", encoding="utf-8")
    with pytest.raises(CaseError, match="notes.txt"):
        write_branch_store(_branch_dataset(), target, overwrite=True)
    assert (target / "notes.txt").read_text(encoding="utf-8") == "my notes"
    assert xr.open_dataset(target, engine="zarr")["kv"].values.tolist() == [1.0, 1.1]  # the store is untouched
    (target / "notes.txt").unlink()
    write_branch_store(_branch_dataset(), target, overwrite=True)  # its own store alone: replaced


def _unwritable_targets(tmp_path: Path) -> list[str]:
    (tmp_path / "a_file").write_text("x", encoding="utf-8")
    targets = [str(tmp_path / "a_file" / "figure.png")]
    if Path("/proc/self").is_dir():
        targets.append("/proc/self/figure.png")
    return targets


@pytest.mark.parametrize("case", ["luo2019", "fzg_type_c"])  # the linear and the nonlinear (branch) path
def test_an_unwritable_plot_target_is_refused_before_computing(tmp_path, case):
    for target in _unwritable_targets(tmp_path):
        store = tmp_path / "study.zarr"
        code, out, err = invoke("sweep", case, "--vary", "speed_rpm=1000,2000", "--out", str(store), "--plot", target,
                                *LINEAR)
        assert code == 2 and out == "", err
        errors = [line for line in err.splitlines() if line.startswith("error:")]
        assert len(errors) == 1 and "--plot" in errors[0], err
        assert not store.exists()  # nothing computed, nothing written


def test_an_unwritable_plot_target_of_stiffness_is_refused(tmp_path):
    for target in _unwritable_targets(tmp_path):
        code, out, err = invoke("stiffness", "luo2019", "--plot", target)
        assert code == 2 and out == "" and err.startswith("error: --plot"), err


# ------------------------------------------------------------------------------------------------ random pairs
RANDOM_PAIRS = Path(__file__).resolve().parents[2] / "benchmarks" / "random_pairs.py"


def test_random_pairs_through_stiffness_and_both_meshes(script_module):
    # the suite's small version of `benchmarks/random_pairs.py --count 10000` (seed 0, 30 pairs, about 2 s): no
    # traceback, no NaN in a result called valid, every non-periodic point labelled, check = run
    module = script_module(RANDOM_PAIRS)
    rng = np.random.default_rng(0)
    outcomes = [module.check_pair(module.draw_document(rng, index)) for index in range(30)]
    defects = [(index, result["defects"], result.get("message")) for index, result in enumerate(outcomes)
               if result["defects"]]
    assert defects == []
    kinds = {result["outcome"] for result in outcomes}
    assert kinds == {"computed", "refused"}  # the draw reaches both: the checks above have points to check
    assert sum(sum(result["labels"].values()) for result in outcomes) >= 40  # models solved


def test_the_random_pair_checks_find_every_non_finite_number(script_module):
    module = script_module(RANDOM_PAIRS)
    assert module._non_finite({"a": [1.0, float("nan")], "b": {"c": np.array([np.inf])}}) == [".a[1]", ".b.c"]
    assert module._non_finite({"a": 1.0, "b": np.arange(3.0)}) == []


# ------------------------------------------------------------------------------------------------ a failed model
UNSTABLE = """[case]
name = "light_load_fast"
[gears]
module_mm = 2.4295
face_width_mm = 37.362
pinion = {teeth = 57, profile_shift = -0.262}
wheel = {teeth = 22, profile_shift = 0.713}
[operating]
speed_rpm = SPEED
power_kw = 0.355
[lubricant]
name = "iso_vg_220_mineral"
operating_temperature_c = 109.0
[housing]
temperature_c = 84.9
[dynamics]
mesh = "linear"
"""


def test_run_reports_the_model_it_computed_beside_the_one_that_is_unstable(tmp_path):
    # a random pair of the 10^4-pair check: at 15 500 rpm (f_mesh ≈ 2.17 f_n, a light load and so little friction
    # damping) the elastic mesh is parametrically unstable and the thermal one, a little softer, is not. `run` gave
    # one error and dropped the thermal result; `run --out` reported it, and the elastic model as not computed
    path = tmp_path / "half.toml"
    path.write_text(UNSTABLE.replace("SPEED", "15500.0"), encoding="utf-8")
    code, out, err = invoke("run", str(path), "--json")
    assert code == 0, err
    payload = json.loads(out)
    assert list(payload["models"]) == ["thermal"] and payload["models"]["thermal"]["status"] == "valid"
    assert payload["not_computed"]["elastic"].startswith("ModelLimitError: parametric instability")
    code, out, err = invoke("run", str(path))
    assert code == 0 and "elastic model not computed: ModelLimitError: parametric instability" in err, err
    path.write_text(UNSTABLE.replace("SPEED", "14760.542"), encoding="utf-8")  # both unstable: nothing to show
    code, out, err = invoke("run", str(path))
    assert code == 2 and out == "" and [line[:29] for line in err.splitlines() if line.startswith("error:")] == [
        "error: parametric instability"], err


# ------------------------------------------------------------------------------------------------ slow transients
SLOW = """[case]
name = "slow_transient"
[gears]
module_mm = 2.6991
face_width_mm = 40.047
backlash_normal_um = 87.64
pinion = {teeth = 16, profile_shift = 0.329}
wheel = {teeth = 47, profile_shift = 0.275}
[operating]
speed_rpm = 147.825
power_kw = 2.049
[temperature]
bulk_c = 89.3
[dynamics]
mesh = "linear"
"""


def test_a_transient_too_long_to_store_is_refused_by_check_and_run_alike(tmp_path):
    # a random pair at 148 rpm: a mesh period holds about 200 natural oscillations, so the RK4 motion from rest
    # needs about 8e5 steps per period and 60 periods exceed what a transient stores. `check` accepted
    # method = "transient" and `run` then failed inside the solver ("solver input periods = 60")
    path = tmp_path / "slow.toml"
    path.write_text(SLOW + 'method = "transient"\n', encoding="utf-8")
    code, _, check_err = invoke("check", str(path))
    assert code == 2 and "error: dynamics.transient_periods = 60: allowed <= " in check_err, check_err
    code, out, run_err = invoke("run", str(path), "--json")
    assert (code, out) == (2, "") and run_err.splitlines()[-1] == check_err.splitlines()[-1]
    path.write_text(SLOW, encoding="utf-8")  # the case's periodic method: accepted, and --method transient refused
    assert invoke("check", str(path))[0] == 0
    code, _, err = invoke("run", str(path), "--method", "transient")
    assert code == 2 and "dynamics.transient_periods" in err, err
    path.write_text(SLOW + 'method = "transient"\n', encoding="utf-8")  # a study solves periodic states only
    code, _, err = invoke("sweep", str(path), "--vary", "torque_nm=10,20", "--out", str(tmp_path / "s.zarr"),
                          "--method", "simulation", *LINEAR)
    assert code == 0, err


def test_the_transient_length_check_draws_the_line_where_the_solver_does(tmp_path):
    from thermogear.case import load_case
    from thermogear.dynamics.transients.transient import transient_from_rest
    from thermogear.errors import ProblemError
    from thermogear.preflight import check_transient_length
    from thermogear.simulation import Simulation

    path = tmp_path / "slow.toml"
    path.write_text(SLOW, encoding="utf-8")
    problem = Simulation(load_case(str(path)), "elastic").problem
    with pytest.raises(CaseError) as refused:
        check_transient_length(problem, 60, 147.825)
    most = int(refused.value.allowed.split()[1])  # "<= N at … rpm, …"
    check_transient_length(problem, most, 147.825)  # accepted
    with pytest.raises(CaseError):
        check_transient_length(problem, most + 1, 147.825)
    with pytest.raises(ProblemError, match="periods × intervals × steps"):  # the solver refuses the same length
        transient_from_rest(problem, most + 1)
