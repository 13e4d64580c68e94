"""One warning format on the command line: `warning: …`, once per cause, never a Python warning with a file path
and a source line (issue 15, part B)."""

from __future__ import annotations

import subprocess
import sys

from thermogear.warning_causes import WarningTally, distinct_warnings, warning_cause

FRICTION = ("friction coefficient (DIN 3990-4): unit load {load} N/mm is {gap} N/mm below the formula's usual "
            "lower limit 150 N/mm")


def test_same_cause_with_other_numbers_is_listed_once():
    messages = [FRICTION.format(load=load, gap=150 - load) for load in (21.0, 42.5, 64.0, 1e2)]
    listed = distinct_warnings(messages)
    assert listed == [messages[0] + " (and 3 more like it with other values)"]


def test_other_causes_stay_apart_and_repeats_count_nothing():
    viscosity = "viscosity of oil 'sch632': temperature 30.0 °C is 10.0 K below the fitted range 40–100 °C"
    pinion = "pinion: θ_f = 0.1883 rad outside the fitted range [0.01, 0.12]"
    wheel = "wheel: θ_f = 0.1255 rad outside the fitted range [0.01, 0.12]"
    tally = WarningTally()
    for message in (viscosity, pinion, viscosity, wheel, pinion):
        tally.add(message)
    assert tally.messages() == [viscosity, pinion, wheel]


def test_cause_replaces_every_number_form():
    assert warning_cause("load −1.5e+03 N at 7 points, 0.25 each") == "load # N at # points, # each"


def test_python_warnings_print_once_per_cause_without_path():
    script = ("import warnings\n"
              "from thermogear.cli.console import install_warning_printer\n"
              "install_warning_printer()\n"
              "for load in (10.0, 20.0, 30.0):\n"
              "    warnings.warn(f'unit load {load} N/mm is low', UserWarning)\n"
              "warnings.warn('another cause', RuntimeWarning)\n")
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stderr.splitlines() == ["warning: unit load 10.0 N/mm is low", "warning: another cause"]


def test_stiffness_warnings_use_the_one_format():
    result = subprocess.run([sys.executable, "-m", "thermogear", "stiffness", "fzg_type_c"], capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stderr
    lines = result.stderr.strip().splitlines()
    assert lines, "fzg_type_c extrapolates the Sainsot fit (θ_f = 0.188 rad): at least one warning"
    for line in lines:
        assert line.startswith("warning: ") and "(extrapolation)" not in line
        assert ".py:" not in line and "Warning:" not in line  # no path, no Python class name
    assert len(lines) == len(set(lines))
