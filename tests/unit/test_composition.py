"""Providers are found where the package is assembled (thermogear.composition), never by an import side effect:
a mesh model of an "fem" or "gearbox" case works in a fresh interpreter that never imported thermogear.simulation."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from thermogear import composition

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("target", [*composition.TEMPERATURE_PROVIDERS.values(), *composition.X_TE_PROVIDERS.values(),
                                    *composition.TEMPERATURE_MODELS.values(), *composition.CASE_CHECKS])
def test_every_builtin_target_is_an_installed_callable(target):
    assert callable(composition.resolve(target))


@pytest.mark.parametrize("target", ["thermogear.no_such_module:function", "thermogear.composition:no_such_name",
                                    "thermogear.composition:TEMPERATURE_MODELS"])
def test_a_missing_or_uncallable_target_resolves_to_none(target):
    assert composition.resolve(target) is None


def test_unknown_name_has_no_builtin():
    assert composition.builtin(composition.TEMPERATURE_PROVIDERS, "uniform") is None


def test_models_that_live_above_the_thermal_chain_need_no_prior_import():
    # Before: the "fem" provider was registered by importing thermogear.fem.provider (thermogear.simulation did),
    # so this script raised "not registered". It runs in a fresh interpreter, where nothing was imported before.
    script = textwrap.dedent("""
        import sys, warnings
        warnings.simplefilter("ignore")
        import thermogear.fem.provider, thermogear.gearbox.provider
        import thermogear.temperature.source as temperature
        assert temperature._PROVIDERS == {}, "importing a provider module registered something"
        from thermogear.case import load_case
        from thermogear.mesh.model import MeshModel
        fem = load_case("luo2019").with_changes(**{"temperature.model": "fem"})
        print(MeshModel(fem, "thermal").temperature.source)
        gearbox = load_case(sys.argv[1])
        print(MeshModel(gearbox, "thermal").temperature.source.split(" ")[0])
        print("thermogear.simulation" in sys.modules)
    """)
    result = subprocess.run([sys.executable, "-c", script, str(ROOT / "tests/data/gearbox/fzg_gearbox.toml")],
                            capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["fem", "gearbox", "False"]


def test_an_absent_provider_module_is_none_but_a_broken_one_raises(tmp_path, monkeypatch):
    # "not installed" is the provider's own module missing; a module that exists but fails to import is a defect
    # that must not be reported as an absent model
    from thermogear.composition import resolve

    assert resolve("thermogear_no_such_package.module:function") is None
    (tmp_path / "thermogear_broken_provider.py").write_text("import thermogear_no_such_dependency\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(ModuleNotFoundError, match="thermogear_no_such_dependency"):
        resolve("thermogear_broken_provider:function")
