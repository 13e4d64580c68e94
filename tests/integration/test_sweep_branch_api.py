"""The Python snippet of docs/sweeps.md ("Nonlinear mesh … / Python") runs as written and gives what it says."""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

DOCS = Path(__file__).resolve().parents[2] / "docs" / "sweeps.md"


def _snippet() -> str:
    text = DOCS.read_text(encoding="utf-8")
    section = text[text.index("### Python"):]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def test_the_documented_branch_study_snippet_runs(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the case's own extrapolation warnings
        exec(compile(_snippet(), str(DOCS), "exec"), namespace)  # noqa: S102 - the documentation's own code
    data, bands = namespace["data"], namespace["bands"]
    assert data["kv"].dims == ("direction", "model", "torque_nm", "speed_rpm")
    # FZG type C at 200 N·m: the down sweep rides the high branch below the linear primary resonance
    # (21 900 rpm): the branches differ over a band there, and the down sweep falls off it
    assert bands["differ"] and bands["bands_rpm"][0][1] < 21900.0
    assert any(jump["amplitude"] == "falls" for jump in bands["down_sweep_jumps"])
    assert "branches differ over" in capsys.readouterr().out
    assert (tmp_path / "branches.png").stat().st_size > 10_000
    import xarray as xr

    stored = xr.open_zarr(tmp_path / "branches.zarr")
    assert float(stored["kv"].max()) == float(data["kv"].max())
