"""Run a thermogear command in this process, as the console script does (``thermogear.cli.main``): the exit
status, stdout and stderr. An exception that escapes ``main`` — a traceback on the command line — is raised to
the test. Much faster than a subprocess per command, for the tests that run many commands on many cases."""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
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


@contextlib.contextmanager
def _as_a_new_process(cwd, env):
    """What a fresh ``python -m thermogear`` process would start with: its working folder and environment, Python's
    own warning filters (not pytest's; PYTHONWARNINGS=ignore honoured) and an empty "printed once" warning tally."""
    from thermogear.cli import console
    from thermogear.warning_causes import WarningTally

    folder = os.getcwd()
    saved_environment = dict(os.environ)
    saved_tally = console._PRINTED
    try:
        if env is not None:
            os.environ.clear()
            os.environ.update(env)
        if cwd is not None:
            os.chdir(cwd)
        console._PRINTED = WarningTally()
        with warnings.catch_warnings():
            warnings.resetwarnings()  # Python's default filters, as a new interpreter has them
            for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
                warnings.simplefilter("ignore", category)
            warnings.filterwarnings("default", category=DeprecationWarning, module="__main__")
            if os.environ.get("PYTHONWARNINGS") == "ignore":
                warnings.simplefilter("ignore")
            yield
    finally:
        console._PRINTED = saved_tally
        os.chdir(folder)
        os.environ.clear()
        os.environ.update(saved_environment)


def run(*args: str, cwd=None, env=None) -> subprocess.CompletedProcess:
    """``thermogear ARGS`` run in this process as a ``subprocess.run([sys.executable, "-m", "thermogear", *ARGS],
    capture_output=True, text=True, cwd=cwd, env=env)`` would run it in a new one (same result object), without
    the 2-3 s of CPU a new interpreter takes to start and import thermogear. For the tests of what a command
    writes and exits with; tests of processes themselves (kills, two at once, the console script) keep a
    subprocess."""
    with _as_a_new_process(cwd, env):
        code, stdout, stderr = invoke(*args)
    return subprocess.CompletedProcess(["thermogear", *args], code, stdout, stderr)
