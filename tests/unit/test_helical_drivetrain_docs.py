"""docs/drivetrain.md, "A helical pair on two shafts": the Python snippet runs as shown and its numbers hold (the
thrust on the wheel shaft's bearings is W tan β_b); the case-file keys it shows load and build the helical mesh."""

from __future__ import annotations

import math
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
SECTION = "## A helical pair on two shafts"


def _block(kind: str) -> str:
    page = (ROOT / "docs" / "drivetrain.md").read_text(encoding="utf-8")
    section = page.split(SECTION, 1)[1].split("\n## ", 1)[0]
    return section.split(f"```{kind}\n", 1)[1].split("```", 1)[0]


def test_the_python_snippet_runs_and_its_thrust_balances():
    namespace: dict = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(_block("python"), "docs/drivetrain.md", "exec"), namespace)  # noqa: S102 - our own docs
    helical, state = namespace["helical"], namespace["state"]
    assert abs(namespace["thrust"]) == pytest.approx(state.normal_load * math.tan(helical.base_helix_angle), rel=1e-9)
    assert np.all(np.abs(namespace["response"].multipliers) < 1.0)
    assert namespace["modes"].frequencies_hz.size == 8


def _two_shaft_case(document: dict):
    from thermogear.case import case_from_document

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_from_document(document, "two_shaft_drivetrain.toml (helical)")


def _helical_document(contact: str | None = None) -> dict:
    """tests/data/two_shaft_drivetrain.toml with the keys the docs show ([gears] helix and hand, the contact
    option, a bearing's tilting stiffness)."""
    document = tomllib.loads((ROOT / "tests" / "data" / "two_shaft_drivetrain.toml").read_text(encoding="utf-8"))
    keys = tomllib.loads(_block("toml"))
    document["gears"].update({key: keys["gears"][key] for key in ("helix_angle_deg", "hand")})
    document["drivetrain"]["helical_contact"] = keys["drivetrain"]["helical_contact"] if contact is None else contact
    tilting = keys["drivetrain"]["bearings"][0]
    for bearing in document["drivetrain"]["bearings"]:
        if bearing["name"] == tilting["name"]:
            bearing["tilting_stiffness_n_m_per_rad"] = tilting["tilting_stiffness_n_m_per_rad"]
    return document


def test_the_case_file_keys_build_the_helical_mesh_and_its_modes():
    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.drivetrain.modes import drivetrain_modes
    from thermogear.drivetrain.static_state import static_state

    case = _two_shaft_case(_helical_document())
    drivetrain = case_drivetrain(case, models=("elastic",)).drivetrains["elastic"]
    mesh = drivetrain.meshes[0]
    assert mesh.base_helix_angle == case.helical_pair.base_helix_angle and mesh.base_helix_angle > 0.0
    assert mesh.hand == 1 and mesh.contact.name == "spread" and mesh.face_width == pytest.approx(20e-3)
    tilting = {bearing.name: bearing.tilting_stiffness for bearing in drivetrain.bearings}
    assert tilting["pinion bearing A"] == 2.0e5 and tilting["wheel bearing A"] == 0.0
    assembled = drivetrain.assemble()
    load = case.operating_point.torque / case.gear_pair.pinion.base_radius
    state = static_state(assembled, load)
    thrust = sum(state.bearing_forces[b.name][2] for b in drivetrain.bearings if b.location.shaft == "wheel shaft")
    assert abs(thrust) == pytest.approx(load * math.tan(mesh.base_helix_angle), rel=1e-9)
    point = _two_shaft_case(_helical_document("point"))
    point_drivetrain = case_drivetrain(point, models=("elastic",)).drivetrains["elastic"]
    spread_hz = drivetrain_modes(assembled, count=12).frequencies_hz
    point_hz = drivetrain_modes(point_drivetrain.assemble(), count=12).frequencies_hz
    assert np.all(spread_hz >= point_hz * (1 - 1e-12))  # the spread adds a positive semi-definite tilting stiffness
