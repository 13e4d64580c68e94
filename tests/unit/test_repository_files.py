"""Files a new contributor meets first: the docs index names every example, .gitignore keeps a virtual
environment out of the repository (issue 24)."""

from __future__ import annotations

import re
from fnmatch import fnmatch
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_docs_index_names_every_example_script():
    row = next(line for line in (ROOT / "docs" / "index.md").read_text(encoding="utf-8").splitlines()
               if line.startswith("| [examples.md]"))
    listed = {int(number) for number in re.findall(r"[:,] (\d+) ", row)}
    scripts = {int(path.name[:2]) for path in (ROOT / "examples").glob("[0-9][0-9]_*.py")}
    assert scripts and listed == scripts


def test_gitignore_keeps_virtual_environments_out():
    patterns = [line.strip() for line in (ROOT / ".gitignore").read_text(encoding="utf-8").splitlines()
                if line.strip() and not line.startswith("#")]
    for folder in (".venv", "venv"):
        assert any(fnmatch(f"{folder}/", pattern) or fnmatch(folder, pattern.rstrip("/")) for pattern in patterns)
