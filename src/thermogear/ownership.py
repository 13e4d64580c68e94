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
from pathlib import Path

from thermogear.errors import CaseError

__all__ = ["MARKER", "is_owned", "marker_process_alive", "read_marker", "require_owned", "resolve_output",
           "write_marker"]

#: Name of the marker file inside every output folder thermogear writes.
MARKER = ".thermogear-owner.json"


def resolve_output(path: Path | str) -> Path:
    """Absolute path of an output with symbolic links and ``..`` resolved (nothing is created)."""
    return Path(os.path.realpath(os.path.abspath(os.fspath(path))))


def write_marker(folder: Path | str, kind: str) -> Path:
    """Write the ownership marker of ``kind`` (``"report"``, ``"sweep-store"``) into ``folder``."""
    from thermogear import __version__

    marker = Path(folder) / MARKER
    marker.write_text(json.dumps({"writer": "thermogear", "kind": kind, "version": __version__,
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
