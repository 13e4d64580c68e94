"""The documentation builds with MkDocs in strict mode (broken links, missing pages and anchors fail), every page
is in the navigation, and the docs stand alone: no file of the repository cites the team's private reference
sheet, and the install line is the one that works (from the repository)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SHEET = "physics" + ".md"  # spelled in two parts so that this file does not mention it


def _tracked_text_files() -> list[Path]:
    result = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                            capture_output=True, text=True)
    if result.returncode != 0:  # not a git checkout (an sdist): scan the usual folders
        return [p for folder in ("src", "docs", "tests", "examples", "benchmarks") for p in (ROOT / folder).rglob("*")
                if p.is_file()]
    return [ROOT / name for name in result.stdout.splitlines() if (ROOT / name).is_file()]


def _citing_files() -> set[str]:
    found = set()
    for path in _tracked_text_files():
        try:
            text = path.read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue
        if SHEET in text:
            found.add(path.relative_to(ROOT).as_posix())
    return found


def test_mkdocs_build_is_strict_clean(tmp_path):
    pytest.importorskip("mkdocs", reason="mkdocs is in the test extra: pip install -e '.[test]'")
    result = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file",
                             str(ROOT / "mkdocs.yml"), "--site-dir", str(tmp_path / "site")],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-4000:]
    assert (tmp_path / "site" / "validation" / "index.html").is_file()
    assert (tmp_path / "site" / "examples" / "index.html").is_file()


def test_every_page_is_in_the_navigation():
    yaml = pytest.importorskip("yaml")
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))

    def pages(node):
        if isinstance(node, str):
            yield node
        elif isinstance(node, dict):
            for value in node.values():
                yield from pages(value)
        elif isinstance(node, list):
            for value in node:
                yield from pages(value)

    listed = set(pages(config["nav"]))
    present = {path.name for path in (ROOT / "docs").glob("*.md")}
    assert present == listed, f"pages not in the nav: {present - listed}; nav entries without a page: {listed - present}"


def test_no_file_cites_the_reference_sheet():
    offenders = _citing_files()
    assert not offenders, f"cite the paper, the standard or a docs/ page instead: {sorted(offenders)}"


def test_install_line_is_from_the_repository():
    guide = (ROOT / "docs" / "user-guide.md").read_text(encoding="utf-8")
    assert "pip install ." in guide
    assert "pip install thermogear" not in guide  # not published on PyPI
    assert "a few seconds" not in guide


def test_user_guide_case_file_loads(tmp_path):
    """The minimal case file of the user guide is a valid case (loaded and checked as `thermogear check` does)."""
    import re

    from thermogear import load_case

    guide = (ROOT / "docs" / "user-guide.md").read_text(encoding="utf-8")
    match = re.search(r"A minimal file:\n\n```toml\n(.*?)```", guide, re.S)
    assert match, "the user guide lost its minimal case file"
    path = tmp_path / "my_pair.toml"
    path.write_text(match.group(1), encoding="utf-8")
    case = load_case(path)
    assert case.name == "my_pair" and case.gear_pair.pinion.teeth == 20
