"""No behaviour of thermogear is keyed on a case's name.

A case's name is a label: a user's copy of a built-in parameter set under another name must behave as the
original, and a pair of one's own named after a built-in set must not inherit that set's special treatment. What
a case is (e.g. a parameter set of Luo & Li 2020, which gets the paper's numbers beside its own) is read from its
content (``thermogear.evaluation.is_paper_case``: the citation's DOI). The scan below finds comparisons of a name
with a string: ``case.name == …``, ``case_name != …``, ``… == "luo2019"`` for every built-in parameter set's name,
and membership tests of those names (``name in ("luo2019", …)``).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import thermogear
from thermogear.case import load_case

SOURCE = Path(thermogear.__file__).parent

#: The names of the built-in parameter sets (the files' stems), read from the package.
BUILT_IN_NAMES = tuple(sorted(path.stem for path in (SOURCE / "parameter_sets").glob("*.toml")))


def _patterns(names: tuple[str, ...]) -> list[re.Pattern]:
    quoted = "|".join(re.escape(name) for name in names)
    return [re.compile(r"\bcase\.name\s*(==|!=)"), re.compile(r"\bcase_name\s*(==|!=)"),
            re.compile(r"(==|!=)\s*case(_|\.)name\b"),
            re.compile(rf"(==|!=)\s*[\"']({quoted})[\"']"), re.compile(rf"[\"']({quoted})[\"']\s*(==|!=)"),
            re.compile(rf"\bin\s*[\(\[\{{][^\)\]\}}]*[\"']({quoted})[\"']")]


def case_name_comparisons(root: Path = SOURCE, names: tuple[str, ...] = BUILT_IN_NAMES) -> list[str]:
    """``path:line: text`` of every comparison of a case name in the Python files under ``root``."""
    patterns = _patterns(names)
    found = []
    for path in sorted(root.rglob("*.py")):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
            if any(pattern.search(line) for pattern in patterns):
                found.append(f"{path.relative_to(root)}:{number}: {line.strip()}")
    return found


def test_the_built_in_names_are_known():
    assert "luo2019" in BUILT_IN_NAMES and "fzg_type_c" in BUILT_IN_NAMES


def test_no_source_compares_a_case_name():
    assert case_name_comparisons() == []


@pytest.mark.parametrize("planted", ['    if case.name == "luo2019":', "    return summary.case_name != 'x'",
                                     "    paper = 'luo2019' == loaded.name", "    if name == 'fzg_type_c':",
                                     '    if name in ("fzg_type_c", "other"):'])
def test_the_scan_finds_a_planted_comparison(tmp_path, planted):
    """The scan is not vacuous: each planted form is reported, with its file and line."""
    (tmp_path / "planted.py").write_text(f"def f(case, summary, loaded, name):\n{planted}\n        pass\n")
    (tmp_path / "innocent.py").write_text("SECTION = 'gears'\nok = item.name == section\n")
    assert case_name_comparisons(tmp_path) == [f"planted.py:2: {planted.strip()}"]


def test_a_renamed_copy_of_the_paper_case_is_the_paper_case(tmp_path):
    """The content decides: the paper's parameter set under another name keeps the paper's comparison; the same
    file without the paper's citation, under the paper's own name, does not get it."""
    from thermogear.evaluation import is_paper_case
    from thermogear.luo2020.report.table import paper_reference

    text = (SOURCE / "parameter_sets" / "luo2019.toml").read_text(encoding="utf-8")
    renamed = tmp_path / "my_copy.toml"
    renamed.write_text(text.replace('name = "luo2019"', 'name = "my_copy"', 1), encoding="utf-8")
    citation_line = next(line for line in text.splitlines() if line.startswith("citation = "))
    uncited = tmp_path / "uncited.toml"
    uncited.write_text(text.replace(citation_line, 'citation = "my own drawing 4711"'), encoding="utf-8")
    copy, own = load_case(str(renamed)), load_case(str(uncited))
    assert copy.name == "my_copy" and own.name == "luo2019"
    assert is_paper_case(copy.citation) and paper_reference(copy.citation) is not None
    assert not is_paper_case(own.citation) and paper_reference(own.citation) is None
    assert not is_paper_case(load_case("fzg_type_c").citation)


def test_a_citation_names_a_reference_by_its_doi_only():
    from thermogear.citations import cited_in, reference

    doi = reference("luo2020").doi
    assert cited_in(f"Luo & Li, EFA (2020), doi:{doi.upper()}", "luo2020")  # DOIs compare without case
    assert not cited_in("B. Luo, W. Li, Investigation on the influence of heat ... (2020)", "luo2020")  # no DOI
    assert not cited_in("", "luo2020") and not cited_in(None, "luo2020")
    assert reference("iso6336_1").doi == "" and not cited_in("ISO 6336-1:2019", "iso6336_1")  # no DOI: never
