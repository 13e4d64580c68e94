"""Study definition (parsing, aliases, checks, chunks) and the batch fast path against one Simulation per point."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel
from thermogear.simulation import Simulation
from thermogear.sweep.batch import MODEL_VARIABLES, POINT_VARIABLES, evaluate_block, evaluate_point, \
    evaluate_speeds, group_tables
from thermogear.sweep.study import Study, _chunk_shape, parse_values, resolve_key


@pytest.fixture(scope="module")
def luo():
    return load_case("luo2019")


# ------------------------------------------------------------------------------------------- parsing
def test_range_includes_both_ends():
    values = parse_values("500:12000:240")
    assert values.size == 240 and values[0] == 500.0 and values[-1] == 12000.0
    assert np.allclose(np.diff(values), (12000.0 - 500.0) / 239)


@pytest.mark.parametrize("text, expected", [("30,60,90", [30.0, 60.0, 90.0]), ("2000", [2000.0]),
                                            ([1, 2.5], [1.0, 2.5]), (7, [7.0])])
def test_lists_and_single_values(text, expected):
    assert parse_values(text).tolist() == expected


@pytest.mark.parametrize("text", ["1:2", "1:2:1", "1:1:5", "a:2:3", "1:2:2.5", "1,x", "", "1,1", "nan", [],
                                  "1:2:3:4"])
def test_bad_value_specifications_are_refused(text):
    with pytest.raises(CaseError) as error:
        parse_values(text, name="vary.speed_rpm")
    assert error.value.key == "vary.speed_rpm"


def test_aliases_map_to_case_keys():
    assert resolve_key("speed_rpm") == "operating.speed_rpm"
    assert resolve_key("oil_temperature_c") == "lubricant.operating_temperature_c"
    assert resolve_key("pinion_profile_shift") == "gears.pinion.profile_shift"
    assert resolve_key("gears.module_mm") == "gears.module_mm"


def test_unknown_parameter_suggests_the_closest(luo):
    with pytest.raises(CaseError, match="speed_rpm"):
        Study.define(luo, ["sped_rpm=1000:2000:3"])
    with pytest.raises(CaseError, match="operating.speed_rpm"):
        Study.define(luo, ["operating.speed_rmp=1000"])


def test_out_of_range_value_is_refused_at_definition(luo):
    with pytest.raises(CaseError) as error:
        Study.define(luo, ["speed_rpm=1000,-5"])
    assert error.value.key == "vary.speed_rpm" and error.value.value == -5.0


def test_one_key_twice_and_bad_model_are_refused(luo):
    with pytest.raises(CaseError):
        Study.define(luo, ["speed_rpm=1000,2000", "operating.speed_rpm=3000"])
    with pytest.raises(CaseError):
        Study.define(luo, ["speed_rpm=1000,2000"], model="plastic")
    with pytest.raises(CaseError):
        Study.define(luo, ["speed_rpm"])


def test_integer_keys_take_integers(luo):
    # at luo2019's fixed centre distance (93 mm, zero backlash for 27/35) another tooth count opens 1.1 mm of
    # backlash and is refused as a gear pair; the integer parsing is what this test is about
    study = Study.define(luo, ["gears.pinion.teeth=27", "gears.wheel.teeth=35"])
    assert study.parameters[0].values == (27,) and isinstance(study.parameters[1].values[0], int)
    with pytest.raises(CaseError):
        Study.define(luo, ["gears.pinion.teeth=26.5"])


def test_torque_replaces_power_and_x_te_is_given(luo):
    study = Study.define(luo, ["torque_nm=100,200", "x_te=0.5"])
    changes = study.changes((200.0, 0.5))
    assert changes["operating.torque_nm"] == 200.0 and changes["operating.power_kw"] is None
    assert changes["thermal.x_te_source"] == "given"
    case = study.case_at((200.0, 0.5))
    assert case.operating_point.torque == 200.0


def test_speed_sweep_of_a_power_case_runs_at_the_case_torque(luo):
    study = Study.define(luo, ["speed_rpm=1000,4000"])
    torque = luo.operating_point.torque
    assert study.case_at((4000.0,)).operating_point.torque == pytest.approx(torque, rel=1e-15)


def test_flank_offset_shifts_the_tabulated_flank(luo):
    study = Study.define(luo, ["flank_temperature_offset_c=0,10"])
    shifted = study.case_at((10.0,)).temperature.flank_c
    assert np.allclose(np.array(shifted) - np.array(luo.temperature.flank_c), 10.0)


# ------------------------------------------------------------------------------------------- chunks
@pytest.mark.parametrize("sizes, target, expected", [((240,), 256, (240,)), ((3, 240), 256, (1, 240)),
                                                     ((240, 3), 16, (5, 3)), ((10, 10), 1, (1, 1)),
                                                     ((4, 5, 6), 1000, (4, 5, 6))])
def test_chunk_shape(sizes, target, expected):
    assert _chunk_shape(sizes, target) == expected


def test_blocks_cover_the_grid_once(luo):
    study = Study.define(luo, ["speed_rpm=1000:3000:7", "oil_temperature_c=30,60,90"], chunk_points=4)
    count = np.zeros(study.shape, dtype=int)
    for block in study.blocks():
        count[block.slices] += 1
        assert len(study.block_values(block)) == block.size
    assert np.all(count == 1)
    assert [b.number for b in study.blocks()] == list(range(len(study.blocks())))


# ------------------------------------------------------------------------------------------- fast path
def _relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


@pytest.mark.parametrize("model", ["elastic", "thermal"])
def test_batch_equals_one_simulation_per_point(luo, model):
    """The fast path (roll tables once, time-scaled batch, compiled metrics) against Simulation(...).run().

    Both evaluate the same exact orbit at the same samples; only rounding differs, so 1e-9 relative is a wide
    margin (measured: ~1e-14)."""
    case = luo.with_changes(**{"operating.power_kw": None, "operating.torque_nm": 300.0})
    speeds = np.array([800.0, 2000.0, 6500.0, 11000.0])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fast = evaluate_speeds(group_tables(MeshModel(case, model)), speeds)
        for index, speed in enumerate(speeds):
            slow = evaluate_point(Simulation(case.with_changes(**{"operating.speed_rpm": float(speed)}), model))
            for name in (*MODEL_VARIABLES, *POINT_VARIABLES):
                assert _relative(fast[name][index], slow[name]) < 1e-9, (name, speed)


def test_block_batch_equals_block_simulation(luo):
    """Whole blocks, grouped over torque and oil temperature: the two evaluation methods agree to 1e-9."""
    study = Study.define(luo, ["torque_nm=250,400", "speed_rpm=1500,5000,9000"], chunk_points=6)
    block = study.blocks()[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fast, _ = evaluate_block(study, block, "batch")
        slow, _ = evaluate_block(study, block, "simulation")
    for name in fast:
        assert fast[name].shape == slow[name].shape
        both = np.isfinite(slow[name])
        assert np.array_equal(np.isfinite(fast[name]), both), name
        assert np.all(np.abs(fast[name][both] - slow[name][both]) <= 1e-9 * np.abs(slow[name][both])), name
    # heavier load: larger static deflection, larger max pair load
    assert np.all(fast["max_pair_load"][:, 1, :] > fast["max_pair_load"][:, 0, :])


# ------------------------------------------------------------------------------------------- resonance
def test_luo2019_resonance_where_the_natural_frequency_predicts_it(luo, tmp_path):
    """Speed sweep of luo2019 through the main mesh resonance (f_m = f_n, n1 = 60 f_n / z1).

    The mesh is lightly damped, so the response is parametrically unstable in a band around the resonance; the
    band's centre must lie within 3 % of the prediction from the time-mean stiffness (the stiffness fluctuation
    of k(τ), ~10 % peak to peak, shifts and widens the tongue at second order), and the thermal band must sit
    lower by the ratio of the natural frequencies, sqrt(mean k_T / mean k_e), within 1 % (the same argument,
    applied to both models)."""
    import matplotlib

    from thermogear.sweep import Study, run_study
    from thermogear.sweep.plots import find_resonance, plot_speed_response

    study = Study.define(luo, ["speed_rpm=10000:15500:221"], chunk_points=256)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        data = run_study(study, tmp_path / "r.zarr", scheduler="serial", progress=False).dataset
    elastic = find_resonance(data, "elastic")
    thermal = find_resonance(data, "thermal")
    for found in (elastic, thermal):
        assert abs(found["relative_offset"]) < 0.03, found
    stiffness_ratio = float(data["mean_mesh_stiffness"].sel(model="thermal").mean()
                            / data["mean_mesh_stiffness"].sel(model="elastic").mean())
    assert stiffness_ratio < 0.95  # the thermal model is softer
    assert thermal["speed_rpm"] / elastic["speed_rpm"] == pytest.approx(stiffness_ratio**0.5, rel=0.01)
    figure = plot_speed_response(data)
    assert len(figure.axes) == 4
    matplotlib.pyplot.close(figure)


def test_default_chunks_grow_with_the_study():
    # small studies keep 4096-point chunks; a 10⁶-point study gets about 50 tasks of 20 000 points (two local
    # workers reached 1.68× of serial with them against 1.55× with 4096), never more than 65 536 points a chunk
    from thermogear.sweep.study import default_chunk_points

    assert default_chunk_points(100) == 4096 and default_chunk_points(100_000) == 4096
    assert default_chunk_points(1_000_000) == 20_000
    assert default_chunk_points(100_000_000) == 65_536
