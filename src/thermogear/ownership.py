"""Ownership markers: thermogear only ever replaces, resumes or deletes what it wrote itself.

Every output folder thermogear creates (a report folder of ``run``/``reproduce``, a sweep's zarr store, and the
hidden ``.NAME.partial-*`` folder a report is written into) gets a small JSON file :data:`MARKER` naming what it
is, the process that wrote it and the host. Before ``--force``, ``--overwrite`` or ``--resume`` touches an
existing path, :func:`require_owned` checks that marker; a path without it is refused with a
:class:`~thermogear.errors.CaseError` naming the path, and is left untouched.

Paths are resolved with :func:`resolve_output` first: symbolic links are followed to the directory they name (so
the link itself stays valid and is never left dangling) and ``..`` is resolved before anything is created (so
``--out a/sub/../x`` never creates ``a/sub``).
"""

from __future__ import annotations

import json
import os
import socket
from importlib import metadata
from pathlib import Path

from thermogear.errors import CaseError

__all__ = ["FIGURE_SUFFIXES", "MARKER", "check_figure_file", "check_output_folder", "is_owned",
           "marker_process_alive", "read_marker", "require_owned", "resolve_output", "write_marker"]

#: File types a figure option (--plot) writes.
FIGURE_SUFFIXES = (".png", ".svg", ".pdf")

#: Name of the marker file inside every output folder thermogear writes.
MARKER = ".thermogear-owner.json"


def resolve_output(path: Path | str) -> Path:
    """Absolute path of an output with symbolic links and ``..`` resolved (nothing is created)."""
    return Path(os.path.realpath(os.path.abspath(os.fspath(path))))


def write_marker(folder: Path | str, kind: str) -> Path:
    """Write the ownership marker of ``kind`` (``"report"``, ``"sweep-store"``) into ``folder``."""
    try:
        version = metadata.version("thermogear")
    except metadata.PackageNotFoundError:  # a source tree that is not installed
        version = "0+unknown"
    marker = Path(folder) / MARKER
    marker.write_text(json.dumps({"writer": "thermogear", "kind": kind, "version": version,
                                  "pid": os.getpid(), "host": socket.gethostname()}), encoding="utf-8")
    return marker


def read_marker(folder: Path | str) -> dict | None:
    """The marker of ``folder`` as a dict, or None when there is none (or it is not thermogear's)."""
    marker = Path(folder) / MARKER
    try:
        if marker.is_symlink() or not marker.is_file():
            return None
        document = json.loads(marker.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(document, dict) or document.get("writer") != "thermogear":
        return None
    return document


def is_owned(folder: Path | str, kind: str) -> bool:
    """True when ``folder`` is a real directory (not a link) carrying thermogear's marker of ``kind``."""
    path = Path(folder)
    if path.is_symlink() or not path.is_dir():
        return False
    document = read_marker(path)
    return document is not None and document.get("kind") == kind


def require_owned(folder: Path | str, kind: str, option: str, action: str) -> None:
    """Refuse (CaseError, nothing touched) to ``action`` a path that thermogear did not write as ``kind``."""
    path = Path(folder)
    if is_owned(path, kind):
        return
    what = "a file" if path.is_file() else "a folder" if path.is_dir() else "a path"
    raise CaseError(option, str(path), f"a {kind} folder written by thermogear (it holds {MARKER})",
                    f"{what} that thermogear did not write is never {action}; nothing was changed")


def marker_process_alive(document: dict) -> bool:
    """Whether the process that wrote a marker may still be running (another host's process counts as alive)."""
    if document.get("host") != socket.gethostname():
        return True
    pid = document.get("pid")
    if not isinstance(pid, int) or pid <= 0:
        return True
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # it exists but belongs to someone else
        return True
    return True


def check_figure_file(path: Path | str, option: str = "--plot", suffixes: tuple[str, ...] = FIGURE_SUFFIXES) -> Path:
    """Check a figure file target before any work: a known suffix, not an existing folder, in an existing writable
    folder. Returns the resolved path; raises CaseError naming the option (a file of that name is replaced)."""
    target = resolve_output(path)
    if target.suffix.lower() not in suffixes:
        raise CaseError(option, str(path), "a file name ending in " + ", ".join(suffixes),
                        "the figure format is taken from the suffix")
    if target.is_dir():
        raise CaseError(option, str(path), "a file name (not a folder)", "a folder of that name exists")
    if not target.parent.is_dir():
        raise CaseError(option, str(path), "a file in an existing folder", f"no folder {target.parent}")
    if not os.access(target.parent, os.W_OK | os.X_OK):
        raise CaseError(option, str(path), "a file in a writable folder", f"cannot write in {target.parent}")
    return target


def check_output_folder(path: Path | str, option: str = "--plot") -> Path:
    """Check a folder that figures are written into (created if absent): not an existing file, creatable.
    Returns the resolved path; raises CaseError naming the option."""
    target = resolve_output(path)
    if target.exists() and not target.is_dir():
        raise CaseError(option, str(path), "a folder (figures are written into it)", "a file of that name exists")
    existing = target
    while not existing.exists() and existing != existing.parent:
        existing = existing.parent
    if not existing.is_dir() or not os.access(existing, os.W_OK | os.X_OK):
        raise CaseError(option, str(path), "a folder thermogear can create and write",
                        f"cannot write there: {existing} is not a writable folder")
    return target
