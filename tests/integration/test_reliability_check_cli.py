"""`thermogear check` on the bad case files (issue 15): every one exit 2, one message, no traceback; the valid
reference passes. The files and the key each must name are in tests/data/bad_cases/ (first line)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

import inprocess_cli

BAD_CASES = Path(__file__).parents[1] / "data" / "bad_cases"


def _expected_key(path: Path) -> str:
    return path.read_bytes().split(b"\n", 1)[0].decode("ascii").removeprefix("# expect: ").strip()


def _check(path: Path) -> subprocess.CompletedProcess:
    # in this process: an exception escaping the command (a traceback on the command line) fails the test
    return inprocess_cli.run("check", str(path))


@pytest.mark.parametrize("path", sorted(BAD_CASES.glob("*.toml")), ids=lambda p: p.stem)
def test_check_refuses_each_bad_case_with_one_message(path):
    result = _check(path)
    if _expected_key(path) == "valid":
        assert result.returncode == 0, result.stderr
        return
    assert result.returncode == 2, result.stdout + result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""  # nothing computed, no table printed
    # one message (its wrapping on a narrow stream is the console's business: issue 15 part B)
    assert result.stderr.count("error:") == 1 and result.stderr.lstrip().startswith("error:"), result.stderr
    assert _expected_key(path) in result.stderr.replace("\n", ""), result.stderr
