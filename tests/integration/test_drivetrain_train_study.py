"""A gear train's drivetrain study (issue 34): the built-in two-stage set through `thermogear sweep` stores every
point (before, each bearing's spectrum of a train's mesh harmonics j·L_m did not fit the one-mesh layout, and every
point was stored "not computed"), with each stage's Kv, DTE and mesh force, equal to the in-process speed sweep."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

pytestmark = [pytest.mark.slow, pytest.mark.filterwarnings("ignore")]


def test_a_train_study_stores_every_stage_as_the_response_at_its_speed(tmp_path):
    import thermogear
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import bearing_force_summary, case_drivetrain, stage_summary

    case = load_case("fzg_type_c_two_stage")
    speeds = [1000.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        study = thermogear.sweep(case, vary={"speed_rpm": speeds}, out=tmp_path / "train.zarr", model="elastic",
                                 scheduler="serial")
        built = case_drivetrain(case, ("elastic",))
        alone = built.response("elastic", speeds[0], case.drivetrain.sweep_points_per_period)
    assert list(study["status"].values.ravel()) == ["valid"]
    harmonics = case.drivetrain.bearing_harmonics
    forces = bearing_force_summary(alone, harmonics)
    stages = list(stage_summary(alone).values())
    assert list(study["mesh"].values) == list(stage_summary(alone)) and len(stages) == 2
    # every stage's mesh harmonics j·L_m over the common period: the lines of the bearing spectrum
    lines = sorted({j * repeat for repeat in built.train_repeats for j in range(1, harmonics + 1)})
    assert list(study["harmonic"].values) == lines and len(lines) > harmonics
    # one speed: the same solve on the same modal basis, rounding only
    point = study.sel(model="elastic").isel(speed_rpm=0)
    assert float(point["kv"]) == pytest.approx(alone.kv, rel=1e-9)
    np.testing.assert_allclose(point["stage_kv"].values, [stage["kv"] for stage in stages], rtol=1e-9)
    np.testing.assert_allclose(point["stage_max_mesh_force_n"].values, [stage["max_mesh_force_n"] for stage in stages],
                               rtol=1e-9)
    np.testing.assert_allclose(point["bearing_harmonic_amplitude_n"].values,
                               [forces[name]["harmonic_amplitude_n"] for name in forces], rtol=1e-9)
