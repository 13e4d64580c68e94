"""Run a thermogear command in this process, as the console script does (``thermogear.cli.main``): the exit
status, stdout and stderr. An exception that escapes ``main`` — a traceback on the command line — is raised to
the test. Much faster than a subprocess per command, for the tests that run many commands on many cases."""

from __future__ import annotations

import contextlib
import io
import sys
import warnings


def invoke(*args: str) -> tuple[int, str, str]:
    """(exit status, stdout, stderr) of ``thermogear ARGS``."""
    from thermogear.cli import main

    stdout, stderr = io.StringIO(), io.StringIO()
    saved = sys.argv, warnings.showwarning, warnings.formatwarning
    sys.argv = ["thermogear", *args]
    code = 0
    try:
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr), warnings.catch_warnings():
            main()
    except SystemExit as exit_:
        code = exit_.code if isinstance(exit_.code, int) else (0 if exit_.code is None else 1)
    finally:
        sys.argv, warnings.showwarning, warnings.formatwarning = saved
    return code, stdout.getvalue(), stderr.getvalue()
