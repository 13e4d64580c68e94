"""Warm-up: temperature histories, the first-order model, and the operating states they produce."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.experiment.warmup import (TemperatureHistory, first_order_history, first_order_warmup,
                                          read_temperature_history, state_case, table3_history, time_mean, warmup)


def test_first_order_warmup_hand_values():
    time = np.array([0.0, 300.0, 1e9])
    values = first_order_warmup(time, 20.0, 60.0, 300.0)
    np.testing.assert_allclose(values, [20.0, 60.0 - 40.0 / math.e, 60.0])
    with pytest.raises(CaseError, match="time_constant_s"):
        first_order_warmup(time, 20.0, 60.0, 0.0)


def test_first_order_history_states():
    history = first_order_history(20.0, 60.0, 600.0, 1200.0, 5)
    np.testing.assert_allclose(history.time_s, [0, 300, 600, 900, 1200])
    assert np.all(np.diff(history.temperature_c) > 0)
    assert "τ = 600.0 s" in history.source
    with pytest.raises(CaseError, match="states"):
        first_order_history(20.0, 60.0, 600.0, 1200.0, 0)


@pytest.mark.parametrize("time, temperature, message", [
    ([0, 2, 1], [20, 21, 22], "sorted"),
    ([0, 1, 1], [20, 21, 22], "sorted"),
    ([0, 1], [20, float("nan")], "NaN"),
    ([0, 1], [20], "equal-length"),
    ([0, 1], [20, 900], "300"),
])
def test_bad_histories_are_refused(time, temperature, message):
    with pytest.raises(CaseError, match=message):
        TemperatureHistory(np.array(time, dtype=float), np.array(temperature, dtype=float), "test")


def test_read_history_csv_in_minutes(tmp_path):
    path = tmp_path / "history.csv"
    path.write_text("time_min,temperature_c\n3,32.3\n5,35.6\n10,42.7\n")
    history = read_temperature_history(path)
    np.testing.assert_allclose(history.time_s, [180, 300, 600])
    np.testing.assert_allclose(history.temperature_c, [32.3, 35.6, 42.7])
    bad = tmp_path / "bad.csv"
    bad.write_text("when,temperature_c\n3,32.3\n")
    with pytest.raises(CaseError, match="time_s|time_min"):
        read_temperature_history(bad)
    bad.write_text("time_s,temperature_c\n3,hot\n")
    with pytest.raises(CaseError, match="a row has no number") as raised:
        read_temperature_history(bad)
    assert "hot" not in str(raised.value)  # the file's content is not echoed
    with pytest.raises(CaseError, match="no such file"):
        read_temperature_history(tmp_path / "missing.csv")


def test_table3_history_is_the_paper_run():
    history = read_temperature_history("luo2019:900")
    np.testing.assert_allclose(history.temperature_c, [32.3, 35.6, 42.7])
    np.testing.assert_allclose(history.time_s, [180, 300, 600])
    with pytest.raises(CaseError, match="no run at that speed"):
        table3_history(500.0)


def test_time_mean_of_piecewise_constant_values():
    assert time_mean(np.array([1.0, 3.0]), np.array([0.0, 1.0, 4.0])) == pytest.approx((1 * 1 + 3 * 3) / 4)


@dataclass
class FakeSimulation:
    """Stands for thermogear.simulation.Simulation: records what the warm-up asks for."""

    case: object
    model: str

    @property
    def mesh_stiffness_mean(self):
        return 2e8 * (1 - 0.01 * (self.case.temperature.bulk_c - 20.0))

    @property
    def natural_frequency_hz(self):
        return math.sqrt(self.mesh_stiffness_mean / self.case.equivalent_mass) / (2 * math.pi)

    @property
    def mesh_frequency_hz(self):
        return self.case.operating_point.speed_rpm / 60 * self.case.gear_pair.pinion.teeth

    @property
    def mesh_damping(self):
        return np.array([1000.0, 2000.0]) * (1 + self.case.lubricant.operating_temperature_c / 100)

    @property
    def grid(self):
        return type("Grid", (), {"nodes": np.array([0.0, 1.0, 2.0])})()

    def run(self, method):
        assert method == "periodic"
        metrics = {"kv": 1.1, "dte_rms": 1e-6, "dte_peak_to_peak": 3e-6, "max_system_load_ratio": 1.5, "valid": True}
        return type("Response", (), {"metrics": metrics})()


def test_warmup_wiring_with_a_fake_simulation():
    case = load_case("fzg_type_c")
    history = TemperatureHistory(np.array([0.0, 60.0]), np.array([30.0, 50.0]), "test")
    result = warmup(case, history, "thermal", speed_rpm=900.0, simulation=FakeSimulation)
    first, second = result.states
    assert first.mesh_stiffness_mean == pytest.approx(2e8 * 0.9)
    assert second.mesh_stiffness_mean == pytest.approx(2e8 * 0.7)
    assert first.mesh_damping_mean == pytest.approx(1500.0 * 1.3)  # oil at the state temperature
    assert first.mesh_frequency_hz == pytest.approx(900 / 60 * 16)  # the speed given, not the case's
    assert first.response["kv"] == 1.1
    assert result.speed_rpm == 900.0
    payload = result.as_dict()
    assert payload["states"][1]["mesh_stiffness_mean_n_per_mm_um"] == pytest.approx(1.4e8 / 14e-3 / 1e9)
    figure = result.plot()
    assert len(figure.axes) == 2 and len(figure.axes[1].lines[0].get_xdata()) == 2


def test_state_case_sets_uniform_bulk_and_oil_temperature():
    case = state_case(load_case("fzg_type_c"), 42.7, 900.0)
    assert case.temperature.model == "uniform"
    assert case.temperature.bulk_c == 42.7
    assert case.lubricant.operating_temperature_c == 42.7
    assert case.operating_point.speed_rpm == 900.0


def test_real_warmup_thermal_stiffness_falls_and_elastic_stays():
    case = load_case("fzg_type_c")
    history = TemperatureHistory(np.array([0.0, 300.0, 600.0]), np.array([20.0, 35.0, 50.0]), "test")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        thermal = warmup(case, history, "thermal", 900.0, dynamics=False)
        elastic = warmup(case, history, "elastic", 900.0, dynamics=False)
    assert np.all(np.diff(thermal.mesh_stiffness_mean) < 0)
    assert np.all(np.diff(thermal.natural_frequency_hz) < 0)
    np.testing.assert_allclose(elastic.mesh_stiffness_mean, elastic.mesh_stiffness_mean[0], rtol=1e-12)
    # at the stress-free reference temperature (20 °C) there is no thermal expansion: k_T = k_e
    assert thermal.mesh_stiffness_mean[0] == pytest.approx(elastic.mesh_stiffness_mean[0], rel=1e-9)
    me = case.equivalent_mass
    np.testing.assert_allclose(thermal.natural_frequency_hz,
                               np.sqrt(thermal.mesh_stiffness_mean / me) / (2 * np.pi), rtol=1e-12)


# ------------------------------------------------------------------ transfer path and rig-signal synthesis
def test_sdof_transfer_path_limits():
    from thermogear.experiment.comparison import SdofTransferPath

    path = SdofTransferPath(natural_frequency_hz=100.0, damping_ratio=0.05, mass_kg=2.0)
    assert abs(path.acceleration_per_force(1e6)) == pytest.approx(1 / 2.0, rel=1e-6)  # mass line: a = F/m
    assert abs(path.acceleration_per_force(100.0)) == pytest.approx(1 / (2 * 0.05 * 2.0), rel=1e-12)  # resonance
    stiffness = 2.0 * (2 * np.pi * 100.0) ** 2
    low = 0.1
    assert abs(path.acceleration_per_force(low)) == pytest.approx((2 * np.pi * low) ** 2 / stiffness, rel=1e-4)
    with pytest.raises(CaseError, match="damping_ratio"):
        SdofTransferPath(100.0, 0.0, 1.0)
    with pytest.raises(CaseError, match="mass_kg"):
        SdofTransferPath(100.0, 0.1, -1.0)


def test_force_harmonics_of_a_known_periodic_force():
    from thermogear.experiment.comparison import periodic_force_harmonics

    period = 0.01
    time = np.linspace(0.0, period, 1001)  # includes both ends, as a response over one period
    force = 100.0 + 30.0 * np.cos(2 * np.pi * time / period + 0.4) + 5.0 * np.sin(2 * np.pi * 3 * time / period)
    harmonics = periodic_force_harmonics(time, force, period, 4)
    assert harmonics[0].real == pytest.approx(100.0, rel=1e-9)
    assert abs(harmonics[1]) == pytest.approx(30.0, rel=1e-4) and np.angle(harmonics[1]) == pytest.approx(0.4, abs=1e-3)
    assert abs(harmonics[3]) == pytest.approx(5.0, rel=1e-3)
    assert abs(harmonics[2]) < 1e-6


def test_simulated_signal_of_one_harmonic_through_the_mass_line():
    from thermogear.experiment.comparison import SdofTransferPath, simulate_rig_signal
    from thermogear.experiment.spectrum import spectrum

    path = SdofTransferPath(natural_frequency_hz=1.0, damping_ratio=0.1, mass_kg=4.0)  # far below 200 Hz
    signal = simulate_rig_signal(np.array([0.0, 8.0 + 0j]), 200.0, path, 2.0, 2048.0)
    peak = spectrum(signal, "fft").peaks()[0]
    assert peak.frequency_hz == pytest.approx(200.0, abs=0.05)
    assert peak.amplitude == pytest.approx(8.0 * abs(path.acceleration_per_force(200.0)), rel=0.01)  # ≈ F/m = 2


# ------------------------------------------------------------------ command line (wiring only)
def test_warmup_command_json_and_errors():
    import json
    import subprocess
    import sys

    def run(*arguments):
        return subprocess.run([sys.executable, "-m", "thermogear", "warmup", *arguments], capture_output=True,
                              text=True, timeout=120)

    completed = run("fzg_type_c", "--temperature-history", "luo2019:900", "--no-dynamics", "--json")
    assert completed.returncode == 0, completed.stderr
    payload = json.loads(completed.stdout)
    assert payload["speed_rpm"] == 900.0
    assert [state["temperature_c"] for state in payload["states"]] == [32.3, 35.6, 42.7]
    frequencies = [state["natural_frequency_hz"] for state in payload["states"]]
    assert frequencies == sorted(frequencies, reverse=True)
    completed = run("fzg_type_c")
    assert completed.returncode == 2 and "exactly one of" in " ".join(completed.stderr.split())


def test_a_warm_up_state_of_the_papers_case_keeps_its_calibrated_x_te():
    # luo2019 calibrates X_te at its own temperatures; a warm-up state at the assembly temperature (no thermal
    # interference) keeps that X_te instead of failing to calibrate, and replaces the whole temperature section
    from thermogear.case import load_case
    from thermogear.experiment.warmup import state_case
    from thermogear.case.pieces import call_with_pieces
    from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model

    case = load_case("luo2019")
    cold = state_case(case, 20.0)
    assert cold.temperature.model == "uniform" and cold.temperature.flank_c is None
    calibrated = call_with_pieces(paper_thermal_model, case).resolve_x_te()[0]
    assert cold.thermal.x_te_source == "given" and cold.thermal.x_te == calibrated


def test_both_warm_ups_hold_a_calibrated_x_te_one_way():
    # the measured and the predicted warm-up write their states each their own way (through the case file's keys,
    # through the sections) but hold the case's calibrated X_te by one rule: held_x_te
    from thermogear.case import load_case
    from thermogear.case.pieces import call_with_pieces
    from thermogear.experiment.warmup import held_x_te, state_case
    from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model

    paper = load_case("luo2019")
    held = call_with_pieces(held_x_te, paper)
    assert held == {"x_te": call_with_pieces(paper_thermal_model, paper).resolve_x_te()[0], "x_te_source": "given",
                    "calibration_drop_percent": None}
    warm = state_case(paper, 60.0)
    assert {key: getattr(warm.thermal, key) for key in held} == held
    assert call_with_pieces(held_x_te, load_case("fzg_type_c")) == {}  # the thermo-elastic model reads no X_te
