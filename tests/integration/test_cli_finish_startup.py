"""Start-up of the command line: commands load lazily, `--help` still lists every command (issue 15, part B).

Speed itself is measured in benchmarks/bench_startup.py (ratios against `python -c pass`); these tests check
what makes it fast and cannot flake on a loaded machine: which modules a command imports.
"""

from __future__ import annotations

import importlib
import inspect
import subprocess
import sys

import pytest

from thermogear.cli.app import COMMANDS, app, first_sentence

HEAVY = ("scipy", "matplotlib", "numba", "dask", "distributed", "zarr", "xarray", "skfem")


# Runs the console script's main() and lists sys.modules at exit (importlib.import_module, which the lazy group
# uses, does not show in `python -X importtime`).
DRIVER = """
import atexit, sys
output = sys.argv.pop(1)
atexit.register(lambda: open(output, "w").write(" ".join(sorted(sys.modules))))
sys.argv[0] = "thermogear"
from thermogear.cli import main
main()
"""


def imported_modules(tmp_path, *arguments: str) -> set[str]:
    """Modules a fresh `thermogear ARGUMENTS` process has imported when it exits."""
    listing = tmp_path / "modules.txt"
    result = subprocess.run([sys.executable, "-c", DRIVER, str(listing), *arguments], capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stderr[-2000:]
    return set(listing.read_text().split())


def test_help_lists_every_command_without_importing_one(tmp_path):
    modules = imported_modules(tmp_path, "--help")
    command_modules = {entry.module for entry in COMMANDS.values()}
    assert not modules & command_modules
    assert not {m for m in modules if m.split(".")[0] in HEAVY}
    assert "numpy" not in modules and "thermogear.case" not in modules


def test_cases_imports_only_its_own_module(tmp_path):
    modules = imported_modules(tmp_path, "cases")
    assert {m for m in modules if m.startswith("thermogear.cli.") and m not in (
        "thermogear.cli.app", "thermogear.cli.console")} == {"thermogear.cli.cases"}
    assert not {m for m in modules if m.split(".")[0] in HEAVY}


def test_help_text_lists_every_command_with_its_one_line_help():
    result = subprocess.run([sys.executable, "-m", "thermogear", "--help"], capture_output=True, text=True)
    text = " ".join(result.stdout.split())
    for name, entry in COMMANDS.items():
        assert f"{name} {entry.help}" in text


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_listed_help_is_the_first_sentence_of_the_command_docstring(name: str):
    importlib.import_module(COMMANDS[name].module)
    callbacks = {(info.name or info.callback.__name__.replace("_", "-")): info.callback
                 for info in app.registered_commands}
    assert name in callbacks, f"{COMMANDS[name].module} registers no command '{name}'"
    assert COMMANDS[name].help == first_sentence(inspect.getdoc(callbacks[name]))


def test_a_mistyped_command_is_answered_with_the_closest_one():
    result = subprocess.run([sys.executable, "-m", "thermogear", "stifness", "luo2019"], capture_output=True,
                            text=True)
    assert result.returncode == 2
    assert "error: No such command 'stifness'. Did you mean 'stiffness'?" in result.stderr.splitlines()


def test_usage_errors_use_the_one_error_format():
    result = subprocess.run([sys.executable, "-m", "thermogear", "sweep", "luo2019", "--workers", "0", "--out", "x"],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1].startswith("error: Invalid value for '--workers'")
    assert "Traceback" not in result.stderr and "Error:" not in result.stderr


def test_first_sentence():
    assert first_sentence("Run a study. Then more.\n\nDetails.") == "Run a study."
    assert first_sentence("Two lines\nof one sentence (e.g. this).") == "Two lines of one sentence (e.g. this)."


def test_cases_lists_what_load_case_builds():
    from thermogear.case import load_case, parameter_set_names
    from thermogear.cli.cases import parameter_set_headers

    headers = parameter_set_headers()
    assert [row["name"] for row in headers] == parameter_set_names()
    for row in headers:
        case = load_case(row["name"])
        # a case whose temperatures are predicted at load (temperature.model = "gearbox") adds the prediction
        written = len(row["assumptions"])
        assert (row["title"], row["citation"], tuple(row["assumptions"])) == (case.title, case.citation,
                                                                             tuple(case.assumptions[:written]))
        assert all(line.startswith("temperatures predicted by the gearbox thermal model")
                   for line in case.assumptions[written:])


def test_a_sweep_without_a_plot_imports_neither_xarray_nor_the_reference_integrator(tmp_path):
    # its summary reads the store with zarr (xarray and pandas: about 0.5 s); solve_ivp is for tests and benchmarks
    modules = imported_modules(tmp_path, "sweep", "luo2019", "--vary", "speed_rpm=1000:3000:2", "--out",
                               str(tmp_path / "study.zarr"), "--json")
    assert "zarr" in modules and "thermogear.sweep.engine" in modules  # the study ran and wrote its store
    assert not {m for m in modules if m.split(".")[0] in ("xarray", "pandas")}
    assert "scipy.integrate" not in modules
