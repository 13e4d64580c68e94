"""Write an output folder so that it is either complete or absent.

Everything is written into a hidden temporary folder next to the target (same file system) and renamed into
place at the end. SIGINT and SIGTERM during the run remove the temporary folder and leave the previous output
(or none); the final swap runs with both signals blocked. An existing target is only replaced with ``force``, and
only when thermogear wrote it (its ownership marker, :mod:`thermogear.ownership`); anything else is refused and
left untouched. The target is resolved first (symbolic links followed, ``..`` removed), so a link given as the
target keeps pointing at the new folder and ``a/sub/../x`` never creates ``a/sub``. The temporary folder carries
the marker too, with the writing process: a run killed outright (SIGKILL) leaves it behind, and the next run into
the same parent folder removes such stale partial folders of its own target, and only those.

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
from thermogear.ownership import (MARKER, marker_process_alive, read_marker, require_owned, resolve_output,
                                  write_marker, written_files)

__all__ = ["OutputFolder", "Terminated"]

_SIGNALS = (signal.SIGINT, signal.SIGTERM)


class Terminated(KeyboardInterrupt):
    """Raised in the main thread when SIGINT or SIGTERM arrives during a write, so that clean-up runs."""


class OutputFolder:
    """A folder written under a temporary name and moved to ``target`` on success (see module docstring)."""

    def __init__(self, target: Path | str, force: bool = False, option: str = "--out") -> None:
        self.target = resolve_output(target)
        self.force = force
        self.option = option
        self.path: Path | None = None
        self.interrupted = False
        self._previous_handlers: dict = {}

    def check(self) -> None:
        """Refuse an existing target without ``force`` (before any work is done)."""
        if self.target.exists() and not self.target.is_dir():
            raise CaseError(self.option, str(self.target), "a folder", "a file of that name exists")
        if self.target.exists():  # a folder thermogear did not write: --force would not help, so say that first
            require_owned(self.target, "report", self.option, "replaced")
        if self.target.exists() and not self.force:
            raise CaseError(self.option, str(self.target), "a folder that does not exist yet, or --force",
                            "the output folder exists and is not overwritten silently; pass --force to replace it")
        existing = self.target.parent
        while not existing.exists() and existing != existing.parent:
            existing = existing.parent
        if not existing.is_dir() or not os.access(existing, os.W_OK | os.X_OK):
            raise CaseError(self.option, str(self.target), "a folder thermogear can create and write",
                            f"cannot write there: {existing} is not a writable folder")
        try:  # os.access says yes to root and knows nothing of read-only mounts: try it, before any work
            os.rmdir(tempfile.mkdtemp(prefix=f".{self.target.name}.probe-", dir=existing))
        except OSError as error:
            raise CaseError(self.option, str(self.target), "a folder thermogear can create and write",
                            f"cannot write there: {error.strerror or error}") from None

    def __enter__(self) -> "OutputFolder":
        self.check()
        # the handlers go in before the partial folder exists: a signal between the two would otherwise end the
        # process with its default action and leave the folder behind
        for signum in _SIGNALS:
            try:
                self._previous_handlers[signum] = signal.signal(signum, self._on_signal)
            except ValueError:  # not the main thread: the signal keeps its handler
                pass
        try:
            self.target.parent.mkdir(parents=True, exist_ok=True)
            self.remove_stale_partials()
            self.path = Path(tempfile.mkdtemp(prefix=f".{self.target.name}.partial-", dir=self.target.parent))
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(self.path, 0o777 & ~umask)  # mkdtemp makes it private; the report folder is an ordinary one
            write_marker(self.path, "report")
        except BaseException as error:  # an OSError, or a signal while the folder is being made
            self.__exit__(type(error), error, None)
            if isinstance(error, OSError):
                raise CaseError(self.option, str(self.target), "a folder thermogear can create and write",
                                f"cannot write there: {error.strerror or error}") from None
            raise
        return self

    def remove_stale_partials(self) -> list[Path]:
        """Remove the ``.NAME.partial-*`` folders of this target left by a killed run: only folders that carry
        thermogear's report marker and whose writing process is gone. Returns the folders removed."""
        removed = []
        for candidate in self.target.parent.glob(f".{self.target.name}.partial-*"):
            if candidate.is_symlink() or not candidate.is_dir():
                continue
            document = read_marker(candidate)
            if document is None or document.get("kind") != "report" or marker_process_alive(document):
                continue
            shutil.rmtree(candidate, ignore_errors=True)
            removed.append(candidate)
        return removed

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
            written = written_files(self.path)
            write_marker(self.path, "report", files=[name for name in written if name != MARKER])
            if self.target.exists():
                if not self.force:  # appeared while we were running
                    raise CaseError(self.option, str(self.target), "a folder that does not exist yet, or --force",
                                    "the output folder appeared during the run; nothing was replaced")
                require_owned(self.target, "report", self.option, "replaced")
                _keep_foreign_files(self.target, self.path, set(written))
                old = Path(tempfile.mkdtemp(prefix=f".{self.target.name}.old-", dir=self.target.parent))
                os.rmdir(old)
                os.replace(self.target, old)
            os.replace(self.path, self.target)
            if old is not None:
                shutil.rmtree(old, ignore_errors=True)
        finally:
            if blocked:
                signal.pthread_sigmask(signal.SIG_SETMASK, previous)  # a pending signal is delivered here


def _keep_foreign_files(previous: Path, new: Path, new_files: set[str]) -> None:
    """Move into ``new`` every file of the ``previous`` report folder that thermogear did not write (a user's
    ``notes.txt`` or ``figures/mine/``), so that replacing a report replaces only thermogear's files. What
    thermogear wrote is read from the previous marker's file list; a folder written before that list existed
    counts the files the new report writes as thermogear's."""
    document = read_marker(previous) or {}
    own = set(document.get("files") or ()) | new_files | {MARKER}
    for name in written_files(previous):
        if name in own:
            continue
        source, destination = previous / name, new / name
        if name.endswith("/"):
            destination.mkdir(parents=True, exist_ok=True)
            continue
        if destination.exists() or destination.is_symlink():
            continue  # a name the new report writes: thermogear's
        destination.parent.mkdir(parents=True, exist_ok=True)
        os.replace(source, destination)
