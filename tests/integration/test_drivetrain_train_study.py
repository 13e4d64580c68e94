"""A gear train's drivetrain study (issue 34): the built-in two-stage set through `thermogear sweep` stores every
point (before, each bearing's spectrum of a train's mesh harmonics j·L_m did not fit the one-mesh layout, and every
point was stored "not computed"), with each stage's Kv, DTE and mesh force, equal to the in-process speed sweep."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

pytestmark = [pytest.mark.slow, pytest.mark.filterwarnings("ignore")]


def test_a_train_study_stores_every_stage_as_the_speed_sweep_does(tmp_path):
    import thermogear
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.sweep.drivetrain_speeds import SweepOrigin, drivetrain_speed_sweep

    case = load_case("fzg_type_c_two_stage")
    speeds = [1000.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        study = thermogear.sweep(case, vary={"speed_rpm": speeds}, out=tmp_path / "train.zarr", model="elastic",
                                 scheduler="serial")
        built = case_drivetrain(case, ("elastic",))
        origin = SweepOrigin(case.name, str(case.source), case.document, case.operating_point.load_held)
        alone = drivetrain_speed_sweep(built, origin, np.array(speeds), ("elastic",)).dataset
    assert list(study["status"].values.ravel()) == ["valid"]
    assert list(study["harmonic"].values) == list(alone["harmonic"].values)  # every stage's lines j·L_m
    assert list(study["mesh"].values) == list(alone["mesh"].values)
    # the same per-speed solve on the same modal basis: rounding only
    for name in ("kv", "dte_rms_um", "stage_kv", "stage_dte_rms_um", "stage_max_mesh_force_n",
                 "bearing_harmonic_amplitude_n"):
        np.testing.assert_allclose(study[name].values, alone[name].values, rtol=1e-9, err_msg=name)
