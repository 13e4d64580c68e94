"""The command line prints text as written and keeps it whole off a terminal (issue 15, part B).

Every test runs the real console script in a fresh process with its output captured (a pipe, as `| cat`), with
COLUMNS=40 where the width matters: a narrow terminal setting must not cut or wrap what goes to a pipe.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from thermogear.case import parameter_set_path
from thermogear.cli.app import COMMANDS


def thermogear(*arguments: str, columns: int | None = None) -> subprocess.CompletedProcess:
    environment = dict(os.environ)
    if columns is not None:
        environment["COLUMNS"] = str(columns)
    return subprocess.run([sys.executable, "-m", "thermogear", *arguments], capture_output=True, text=True,
                          env=environment)


def test_sweep_help_shows_the_range_syntax_and_the_section_name():
    result = thermogear("sweep", "--help")
    assert result.returncode == 0, result.stderr
    text = " ".join(result.stdout.split())  # help wraps lines; markup would have removed these characters
    assert "'a:b:n'" in text
    assert "[sweep] table" in text
    assert "\N{NEGATIVE SQUARED LATIN CAPITAL LETTER B}" not in result.stdout  # the emoji 'a:b:n' used to become


def test_check_piped_shows_the_units_of_its_rows_whole():
    result = thermogear("check", "luo2019", columns=40)
    assert result.returncode == 0, result.stderr
    for unit in ("[mm]", "[°]", "[N]", "[Hz]"):
        assert unit in result.stdout
    # the title is longer than the table: on its own line, not wrapped to the table's width
    assert "luo2019: Luo & Li (2020) spur gear pair, Table 1: z 27/35, m 3 mm, 80 kW at 2000 rpm" in result.stdout
    assert "…" not in result.stdout
    assert "\x1b[" not in result.stdout  # no terminal codes in a pipe


def test_case_text_with_markup_and_emoji_codes_prints_as_written(tmp_path: Path):
    source = parameter_set_path("luo2019").read_text(encoding="utf-8")
    title = "[bold]rig A[/bold] :smile: [red] a:b:n /etc/passwd"
    case_file = tmp_path / "marked.toml"
    case_file.write_text(re.sub(r'^title = ".*"$', f'title = "{title}"', source, count=1, flags=re.M),
                         encoding="utf-8")
    result = thermogear("check", str(case_file))
    assert result.returncode == 0, result.stderr
    assert title in result.stdout


def test_oils_title_keeps_the_section_name():
    result = thermogear("oils", columns=40)
    assert result.returncode == 0, result.stderr
    assert "[lubricant] name" in result.stdout
    assert "…" not in result.stdout


def test_error_message_is_one_line_off_a_terminal():
    result = thermogear("check", "no_such_case_with_a_long_name_to_wrap_it_at_forty_columns", columns=40)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ")
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_help_is_uniform(command: str):
    result = thermogear(command, "--help")
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert "<bool>" not in text  # a flag takes no value: no type shown
    usage = text.splitlines()[0]
    assert usage.startswith(f"Usage: thermogear {command} [OPTIONS]")
    # arguments upper case in every command (CASE, FILE, PAPER), never {case} in one and {CASE} in another
    assert re.findall(r"\{([A-Za-z_]+)\}", usage) == [name.upper() for name in re.findall(r"\{([A-Za-z_]+)\}",
                                                                                           usage)]
    assert not re.search(r"-[\w-]*…", text)  # no option name cut short


def test_warmup_help_names_every_option_in_full():
    result = thermogear("warmup", "--help")
    for option in ("--temperature-history", "--time-constant-s", "--dynamics / --no-dynamics", "--rig-comparison"):
        assert option in result.stdout
