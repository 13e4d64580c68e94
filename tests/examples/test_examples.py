"""Every script of the examples gallery (examples/) runs, passes its own checks (each asserts its numbers) and
writes the figure that docs/examples.md shows."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SCRIPTS = sorted(EXAMPLES.glob("[0-9][0-9]_*.py"))


def test_the_gallery_has_the_examples_the_docs_promise():
    names = {path.stem for path in SCRIPTS}
    assert len(names) >= 4, names
    docs = (EXAMPLES.parent / "docs" / "examples.md").read_text(encoding="utf-8")
    for path in SCRIPTS:
        assert f"examples/{path.name}" in docs, f"docs/examples.md does not show {path.name}"


@pytest.mark.parametrize("script", SCRIPTS, ids=[path.stem for path in SCRIPTS])
def test_example_runs_and_checks_its_numbers(script, tmp_path, script_module):
    import matplotlib.pyplot as plt

    module = script_module(script, f"thermogear_example_{script.stem}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the examples show results; the model's warnings are tested elsewhere
        result = module.main(tmp_path / "out")
    figure = Path(result["figure"])
    assert figure.is_file() and figure.stat().st_size > 10_000, figure
    assert figure.parent == tmp_path / "out"  # writes only into the folder it is given
    # the figure the docs show is the one this script draws (same name)
    assert (EXAMPLES.parent / "docs" / "images" / "examples" / figure.name).is_file(), figure.name
    plt.close("all")
