"""Write an output folder so that it is either complete or absent.

Everything is written into a hidden temporary folder next to the target (same file system) and renamed into
place at the end. SIGINT and SIGTERM during the run remove the temporary folder and leave the previous output
(or none); the final swap runs with both signals blocked. An existing target is only replaced with ``force``.

    with OutputFolder(Path("thermogear-luo2019"), force=False) as folder:
        (folder.path / "report.html").write_text(...)
    # here the complete folder is in place
"""

from __future__ import annotations

import os
import shutil
import signal
import tempfile
from pathlib import Path
from types import FrameType

from thermogear.errors import CaseError

__all__ = ["OutputFolder", "Terminated"]

_SIGNALS = (signal.SIGINT, signal.SIGTERM)


class Terminated(KeyboardInterrupt):
    """Raised in the main thread when SIGINT or SIGTERM arrives during a write, so that clean-up runs."""


class OutputFolder:
    """A folder written under a temporary name and moved to ``target`` on success (see module docstring)."""

    def __init__(self, target: Path | str, force: bool = False, option: str = "--out") -> None:
        self.target = Path(target).absolute()
        self.force = force
        self.option = option
        self.path: Path | None = None
        self.interrupted = False
        self._previous_handlers: dict = {}

    def check(self) -> None:
        """Refuse an existing target without ``force`` (before any work is done)."""
        if self.target.exists() and not self.force:
            raise CaseError(self.option, str(self.target), "a folder that does not exist yet, or --force",
                            "the output folder exists and is not overwritten silently; pass --force to replace it")
        if self.target.exists() and not self.target.is_dir():
            raise CaseError(self.option, str(self.target), "a folder", "a file of that name exists")

    def __enter__(self) -> "OutputFolder":
        self.check()
        self.target.parent.mkdir(parents=True, exist_ok=True)
        self.path = Path(tempfile.mkdtemp(prefix=f".{self.target.name}.partial-", dir=self.target.parent))
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(self.path, 0o777 & ~umask)  # mkdtemp makes it private; the report folder is an ordinary folder
        for signum in _SIGNALS:
            try:
                self._previous_handlers[signum] = signal.signal(signum, self._on_signal)
            except ValueError:  # not the main thread: the signal keeps its handler
                pass
        return self

    def _on_signal(self, signum: int, frame: FrameType | None) -> None:
        # The flag makes the interruption stick even if some library code swallows the exception.
        self.interrupted = True
        raise Terminated(f"interrupted by signal {signum}")

    def __exit__(self, kind, error, traceback) -> bool:
        try:
            if kind is None:
                if self.interrupted:
                    raise Terminated("interrupted; the output folder was not replaced")
                self._commit()
        finally:
            if self.path is not None and self.path.exists():
                shutil.rmtree(self.path, ignore_errors=True)
            for signum, handler in self._previous_handlers.items():
                signal.signal(signum, handler)
            self._previous_handlers.clear()
        return False

    def _commit(self) -> None:
        """Swap the finished folder into place with SIGINT/SIGTERM blocked."""
        blocked = hasattr(signal, "pthread_sigmask")
        if blocked:
            previous = signal.pthread_sigmask(signal.SIG_BLOCK, _SIGNALS)
        try:
            old = None
            if self.target.exists():
                if not self.force:  # appeared while we were running
                    raise CaseError(self.option, str(self.target), "a folder that does not exist yet, or --force",
                                    "the output folder appeared during the run; nothing was replaced")
                old = Path(tempfile.mkdtemp(prefix=f".{self.target.name}.old-", dir=self.target.parent))
                os.rmdir(old)
                os.replace(self.target, old)
            os.replace(self.path, self.target)
            if old is not None:
                shutil.rmtree(old, ignore_errors=True)
        finally:
            if blocked:
                signal.pthread_sigmask(signal.SIG_SETMASK, previous)  # a pending signal is delivered here
