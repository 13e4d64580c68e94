"""Thermo-elastic outputs: the ``thermal`` object of ``thermogear stiffness --thermal --json``, its figure."""

from __future__ import annotations

import json
import subprocess
import sys
import warnings

import pytest

from thermogear.case import case_from_document, load_case
from thermogear.case.pieces import call_with_pieces
from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model
from thermogear.mesh.model import MeshModel
from thermogear.thermoelastic.mesh import ThermoelasticMesh
from thermogear.summaries.thermoelastic import ThermalModels, thermal_block

from test_thermoelastic_operating import document

GEOMETRY_KEYS = {"centre_distance_mm", "pressure_angle_deg", "contact_ratio", "backlash_normal_um"}


def _block(case):
    # resolved as the stiffness command resolves the case
    models = ThermalModels(paper=call_with_pieces(paper_thermal_model, case), elastic=MeshModel(case, "elastic"),
                           thermal=MeshModel(case, "thermal"), component_of=lambda: ThermoelasticMesh.from_case(case),
                           name=case.name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return thermal_block(models)


def test_thermoelastic_block_has_the_documented_keys():
    block = _block(case_from_document(document()))
    assert block["model"] == "thermoelastic" and "luo2020" not in block and "x_te" not in block
    assert set(block["operating"]) == GEOMETRY_KEYS == set(block["cold"])
    assert set(block["youngs_modulus_gpa"]) == {"pinion", "wheel"}
    assert set(block["mesh_stiffness_n_per_mm_um"]) == {"min", "mean", "max"}
    assert {"peak_to_peak"} <= set(block["deviation_um"])
    assert set(block["loaded_transmission_error_um"]) == {"mean", "peak_to_peak"}
    assert block["jamming_bulk_temperature_c"] > 80.0
    # values follow the component (no re-derivation): backlash and E in display units
    component = ThermoelasticMesh.from_case(case_from_document(document()))
    assert block["operating"]["backlash_normal_um"] == pytest.approx(component.backlash_normal * 1e6, rel=1e-12)
    assert block["youngs_modulus_gpa"]["pinion"] == pytest.approx(206.0 * (1 - 3.33e-4 * 60), rel=1e-12)
    assert block["plausibility"] == [] and len(block["assumptions"]) >= 3
    json.dumps(block)  # plain JSON


def test_paper_model_keeps_its_keys_and_gets_the_prediction_beside_it():
    block = _block(load_case("luo2019"))
    assert block["model"] == "luo2020"
    assert block["stiffness_drop_percent"]["C"] == pytest.approx(14.52, abs=1e-6)  # the paper's calibration
    assert block["thermoelastic"]["model"] == "luo2020"
    assert set(block["thermoelastic"]["operating"]) == GEOMETRY_KEYS


def test_figure_has_three_panels():
    pytest.importorskip("matplotlib")
    from thermogear.summaries.thermoelastic_plots import plot_thermoelastic

    import matplotlib.pyplot as plt

    doc = document()
    for name in ("pinion", "wheel"):
        doc["gears"][name].update(tip_relief_um=20.0, tip_relief_length_mm=6.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        figure = plot_thermoelastic(ThermoelasticMesh.from_case(case_from_document(doc)))
    try:
        assert len(figure.axes) == 3 and all(axis.lines for axis in figure.axes)
    finally:
        plt.close(figure)


def test_command_line_thermal_json(tmp_path):
    import tomli_w

    path = tmp_path / "unseen.toml"
    path.write_bytes(tomli_w.dumps(document()).encode())
    result = subprocess.run([sys.executable, "-m", "thermogear", "stiffness", str(path), "--thermal", "--json"],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    thermal = json.loads(result.stdout)["thermal"]
    assert thermal["model"] == "thermoelastic" and set(thermal["operating"]) == GEOMETRY_KEYS
