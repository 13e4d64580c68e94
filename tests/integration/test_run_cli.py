"""`thermogear run CASE`: JSON per model (issue 5), the full report of any case (issue 6), and the words the CLI
must say about contact loss and instability."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

import inprocess_cli

from thermogear.report.evaluate import model_messages

KEYS = ("kv", "max_pair_load_n_per_mm", "max_system_load_ratio", "equilibrium_um", "amplitude_um",
        "natural_frequency_hz", "frequency_ratio", "floquet_multipliers_abs")


DATA = Path(__file__).resolve().parents[1] / "data"
USER_PAIR = DATA / "user_pair.toml"  # a user's own pair under the default (thermo-elastic) thermal model


def _run(*args: str, cwd=None) -> subprocess.CompletedProcess:
    return inprocess_cli.run("run", *args, cwd=cwd)


def test_json_has_every_key_per_model():
    result = _run("luo2019", "--json")
    assert result.returncode == 0, result.stderr
    payload = json.loads(result.stdout)
    assert set(payload["models"]) == {"elastic", "thermal"}
    for model, data in payload["models"].items():
        for key in KEYS:
            assert key in data, (model, key)
        assert set(data["equilibrium_um"]) == {"single", "double"}
        assert set(data["amplitude_um"]) == {"single", "double"}
        assert all(math.isfinite(v) for v in data["equilibrium_um"].values())
        assert data["stable"] and data["valid"]
        # no contact loss, no instability; the thermal model of the paper is checked against what E(T) can do, and
        # its calibrated k_T (−13 % mean stiffness) is flagged as beyond it (issue 13, sanity that protects the user)
        expected = 1 if model == "thermal" else 0
        assert len(data["messages"]) == expected and all("check" in m for m in data["messages"]), data["messages"]
    # heat softens the mesh: larger static transmission error in both regions, lower natural frequency
    elastic, thermal = payload["models"]["elastic"], payload["models"]["thermal"]
    assert thermal["equilibrium_um"]["single"] > elastic["equilibrium_um"]["single"]
    assert thermal["natural_frequency_hz"] < elastic["natural_frequency_hz"]


def test_one_model_transient():
    result = _run("luo2019", "--model", "thermal", "--method", "transient", "--json")
    assert result.returncode == 0, result.stderr
    payload = json.loads(result.stdout)
    assert list(payload["models"]) == ["thermal"] and payload["method"] == "transient"
    assert payload["models"]["thermal"]["method"].startswith("transient")


def test_table_output_and_bad_option():
    result = _run("fzg_type_c", "--model", "elastic")
    assert result.returncode == 0, result.stderr
    assert "Kv" in result.stdout and "equilibrium, single" in result.stdout
    bad = _run("fzg_type_c", "--model", "thermic")
    assert bad.returncode == 2 and "elastic | thermal | both" in bad.stderr


def test_report_of_any_case_is_complete(tmp_path):
    out = tmp_path / "fzg"
    result = _run("fzg_type_c", "--out", str(out), "--quiet")
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["table"] == []  # no paper column for a user's case
    assert summary["case"]["name"] == "fzg_type_c"
    assert summary["not_computed_stages"] == {}, summary["not_computed_stages"]
    assert summary["figures"]["missing"] == {} or set(summary["figures"]["missing"]) <= {"fig15"}
    quantities = [row["quantity"] for row in summary["results"]]
    assert "dynamic load factor Kv (Eq. 29)" in quantities
    for row in summary["results"]:
        assert row["elastic"] is not None or row["thermal"] is not None, row["quantity"]
    page = (out / "report.html").read_text()
    # nine figures in the figures section (Fig. 15 needs the FE run of the paper's case), three of them (Figs. 4,
    # 9 and 12) shown again as key figures in the headline block at the top
    assert page.count("src='data:image/png;base64,") == 9 + 3
    assert "paper vs thermogear" not in page and "FZG type C" in page
    assert (out / "results.nc").stat().st_size > 0


def _fake_response(detected: bool, stable: bool):
    metrics = {"contact_loss": {"detected": detected, "start_times": [2.0e-4], "durations": [1.5e-4],
                                "min_force": -1200.0, "min_force_ratio": -0.12},
               "stable": stable, "floquet_multipliers_abs": [1.07, 0.2]}
    return SimpleNamespace(metrics=metrics, problem=SimpleNamespace(period=1.0e-3))


def test_contact_loss_and_instability_are_said_in_words():
    assert model_messages(_fake_response(False, True), "elastic") == []
    loss, = model_messages(_fake_response(True, True), "thermal")
    assert "CONTACT LOSS" in loss and "0.200 ms" in loss and "0.150 ms" in loss and "-12 %" in loss
    unstable, = model_messages(_fake_response(False, False), "elastic")
    assert "UNSTABLE" in unstable and "1.07" in unstable


def test_user_guide_case_file_runs(tmp_path):
    """The minimal case file of docs/user-guide.md loads and runs as written."""
    import re
    from pathlib import Path

    guide = (Path(__file__).resolve().parents[2] / "docs" / "user-guide.md").read_text(encoding="utf-8")
    case_file = tmp_path / "my_pair.toml"
    case_file.write_text(re.search(r"```toml\n(.*?)```", guide, re.S).group(1), encoding="utf-8")
    result = _run(str(case_file), "--json")
    assert result.returncode == 0, result.stderr
    assert set(json.loads(result.stdout)["models"]) == {"elastic", "thermal"}


def test_nonlinear_transient_runs_as_table_and_json():
    # fzg_type_c uses the nonlinear mesh (the default): `--method transient` used to end in KeyError 'response'
    table = _run("fzg_type_c", "--method", "transient")
    assert table.returncode == 0, table.stderr
    assert "Traceback" not in table.stderr and "equilibrium, single" in table.stdout and "from rest" in table.stdout
    result = _run("fzg_type_c", "--method", "transient", "--json", "--model", "elastic")
    assert result.returncode == 0, result.stderr
    elastic = json.loads(result.stdout)["models"]["elastic"]
    assert elastic["method"] == "nonlinear transient from rest" and elastic["branch"] == "from rest"
    assert set(elastic["equilibrium_um"]) == {"single", "double"} and elastic["kv"] > 1.0


def test_transient_method_in_the_case_writes_the_report(tmp_path):
    # `method = "transient"` in the case and --out used to fail with KeyError 'equilibrium_per_region' and write
    # no folder
    text = USER_PAIR.read_text(encoding="utf-8") + '\n[dynamics]\nmethod = "transient"\n'
    case_file = tmp_path / "transient.toml"
    case_file.write_text(text, encoding="utf-8")
    out = tmp_path / "report"
    result = _run(str(case_file), "--out", str(out), "--quiet")
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert (out / "report.html").exists() and summary["not_computed_stages"] == {}
    kv = next(row for row in summary["results"] if row["quantity"] == "dynamic load factor Kv (Eq. 29)")
    assert kv["elastic"] > 1.0 and kv["thermal"] > 1.0


def test_check_and_run_agree_on_a_user_pair_under_the_default_model(tmp_path):
    # check accepted the case, then run reported "figures not drawn: fig3c, fig4 (stage 'thermal stiffness' failed:
    # thermal.x_te = None …)": the paper's k_T stages ran for a model that does not use X_te
    check = subprocess.run([sys.executable, "-m", "thermogear", "check", str(USER_PAIR)], capture_output=True,
                           text=True, timeout=300)
    assert check.returncode == 0, check.stderr
    out = tmp_path / "user"
    result = _run(str(USER_PAIR), "--out", str(out), "--quiet")
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["not_computed_stages"] == {}, summary["not_computed_stages"]
    assert set(summary["figures"]["missing"]) <= {"fig15"}, summary["figures"]["missing"]  # fig15: FE of the paper
    quantities = {row["quantity"]: row for row in summary["results"]}
    assert "X_te (thermo-elastic correction factor)" not in quantities  # the paper's model is not in use
    backlash = quantities["normal backlash"]
    assert backlash["thermal"] < backlash["elastic"]  # gears hotter than the housing: the backlash closes


def test_run_gives_what_the_thermoelastic_model_is_for():
    # the numbers are the summary's (summaries.thermoelastic), not recomputed by the command
    from thermogear.case import load_case
    from thermogear.summaries.thermoelastic import thermoelastic_summary
    from thermogear.temperature.source import temperature_field_from_case
    from thermogear.thermoelastic.mesh import ThermoelasticMesh

    result = _run(str(USER_PAIR), "--json")
    assert result.returncode == 0, result.stderr
    block = json.loads(result.stdout)["thermoelastic"]
    case = load_case(str(USER_PAIR))
    expected = json.loads(json.dumps(thermoelastic_summary(ThermoelasticMesh.from_case(case), case.thermal.model,
                                                           temperature_field_from_case(case))))
    for path in (("operating", "centre_distance_mm"), ("operating", "pressure_angle_deg"), ("operating", "contact_ratio"),
                 ("cold", "backlash_normal_um"), ("operating", "backlash_normal_um"), ("jamming_bulk_temperature_c",),
                 ("jamming_margin_k",), ("youngs_modulus_gpa", "pinion"), ("loaded_transmission_error_um", "mean"),
                 ("loaded_transmission_error_um", "peak_to_peak"), ("elastic", "loaded_transmission_error_um", "mean")):
        value, reference = block, expected
        for key in path:
            value, reference = value[key], reference[key]
        assert value == pytest.approx(reference, rel=1e-12), path
    # the hotter gears (85 °C) in a housing at the oil temperature (70 °C): margin = jamming − bulk temperature
    assert block["jamming_margin_k"] == pytest.approx(block["jamming_bulk_temperature_c"] - 85.0, rel=1e-9)
    table = _run(str(USER_PAIR))
    assert table.returncode == 0, table.stderr
    for label in ("operating centre distance", "operating pressure angle", "normal backlash", "jamming bulk temperature",
                  "jamming margin", "Young's modulus E(T), pinion", "loaded static transmission error, mean",
                  "loaded static transmission error, peak-to-peak"):
        assert label in table.stdout, label
