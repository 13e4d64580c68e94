"""`thermogear damping` and `thermogear fem` show the paper's numbers for a parameter set of the paper, decided by
the case's content (its citation's DOI), not its name: the built-in luo2019 under another name keeps them, a user's
pair never shows them. The numbers shown are the paper table's."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import inprocess_cli

import thermogear
from thermogear.luo2020.report.table import row

USER_PAIR = Path(__file__).resolve().parents[1] / "data" / "user_pair.toml"


@pytest.fixture(scope="module")
def renamed(tmp_path_factory) -> Path:
    text = (Path(thermogear.__file__).parent / "parameter_sets" / "luo2019.toml").read_text(encoding="utf-8")
    path = tmp_path_factory.mktemp("copy") / "our_test_rig.toml"
    path.write_text(text.replace('name = "luo2019"', 'name = "our_test_rig"', 1), encoding="utf-8")
    return path


def _damping_json(case: str) -> dict:
    result = inprocess_cli.run("damping", case, "--json")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_damping_shows_the_paper_means_for_a_renamed_copy_only(renamed):
    copy, own = _damping_json(str(renamed)), _damping_json(str(USER_PAIR))
    assert copy["case"] == "our_test_rig"
    assert copy["paper_n_s_per_m"]["thermal"]["double"] == row("fig8.cr_double").paper
    assert copy["paper_n_s_per_m"]["elastic"]["single"] == row("fig7.ce_single").paper
    assert "paper_n_s_per_m" not in own


def test_fem_summary_shows_the_paper_range_for_a_renamed_copy_only(renamed):
    from thermogear.cli.fem import fem_summary

    copy, _ = fem_summary(str(renamed), refine=False)
    own, _ = fem_summary(str(USER_PAIR), refine=False)
    assert copy["paper"]["flank_temperature_c"] == [row("fig3.flank_temperature_min").paper,
                                                    row("fig3.flank_temperature_max").paper]
    assert copy["paper"]["stiffness_drop_percent"]["C"] == row("fig4.drop_at_C").paper
    assert "paper" not in own
