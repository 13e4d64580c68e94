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
import re
import socket
from collections.abc import Iterator
from contextlib import contextmanager
from importlib import metadata
from pathlib import Path

from thermogear.errors import CaseError

__all__ = ["FIGURE_SUFFIXES", "MARKER", "check_figure_file", "check_output_folder", "exclusive_writer",
           "foreign_store_entries", "is_owned", "marker_process_alive", "read_marker", "remove_interrupted_writes",
           "require_no_foreign_entries", "require_owned", "resolve_output", "write_marker", "written_files"]

#: File types a figure option (--plot) writes.
FIGURE_SUFFIXES = (".png", ".svg", ".pdf")

#: Name of the marker file inside every output folder thermogear writes.
MARKER = ".thermogear-owner.json"


def resolve_output(path: Path | str) -> Path:
    """Absolute path of an output with symbolic links and ``..`` resolved (nothing is created)."""
    return Path(os.path.realpath(os.path.abspath(os.fspath(path))))


def write_marker(folder: Path | str, kind: str, files: list[str] | None = None) -> Path:
    """Write the ownership marker of ``kind`` (``"report"``, ``"sweep-store"``) into ``folder``; ``files``: the
    relative paths thermogear wrote there (a finished report), so that a later run replaces those and no
    others."""
    try:
        version = metadata.version("thermogear")
    except metadata.PackageNotFoundError:  # a source tree that is not installed
        version = "0+unknown"
    marker = Path(folder) / MARKER
    document = {"writer": "thermogear", "kind": kind, "version": version, "pid": os.getpid(),
                "host": socket.gethostname()}
    if files is not None:
        document["files"] = sorted(files)
    marker.write_text(json.dumps(document), encoding="utf-8")
    return marker


def written_files(folder: Path | str) -> list[str]:
    """Relative paths of every file under ``folder`` (links not followed), in POSIX form."""
    root = Path(folder)
    found = []
    for directory, subfolders, files in os.walk(root):
        for name in files + [sub for sub in subfolders if (Path(directory) / sub).is_symlink()]:
            found.append((Path(directory) / name).relative_to(root).as_posix())
        if not files and not subfolders and Path(directory) != root:  # an empty folder, as "name/"
            found.append(Path(directory).relative_to(root).as_posix() + "/")
    return found


#: Top-level entries of a zarr store that zarr writes (v2 and v3 metadata) besides the arrays' folders.
ZARR_METADATA = (".zgroup", ".zattrs", ".zmetadata", "zarr.json")


_ZARR_NODE_METADATA = (".zarray", ".zgroup", ".zattrs", "zarr.json")


def _is_zarr_node(entry: Path) -> bool:
    return entry.is_dir() and not entry.is_symlink() and any((entry / name).is_file() and not
                                                             (entry / name).is_symlink()
                                                             for name in _ZARR_NODE_METADATA)


#: A file zarr was writing when its process was killed: zarr's local store writes each file as
#: NAME.<32 hex digits>.partial and renames it once complete (zarr.storage.LocalStore's atomic write), so such a file
#: is zarr's own and never holds a finished chunk.
_INTERRUPTED_WRITE = re.compile(r"\.[0-9a-f]{32}\.partial$")


def _is_interrupted_write(entry: Path) -> bool:
    return entry.is_file() and not entry.is_symlink() and _INTERRUPTED_WRITE.search(entry.name) is not None


def remove_interrupted_writes(folder: Path | str) -> list[Path]:
    """Delete the files zarr left half-written in an owned store when its writer was killed (``_INTERRUPTED_WRITE``),
    at any depth; return them. Call only after :func:`require_owned`: the task that was writing them is not marked
    done, so a resumed study writes its chunks again."""
    removed = []
    for directory, folders, files in os.walk(folder):
        folders[:] = [name for name in folders if not (Path(directory) / name).is_symlink()]
        for name in files:
            entry = Path(directory) / name
            if _is_interrupted_write(entry):
                entry.unlink()
                removed.append(entry)
    return removed


def _is_chunk_name(name: str) -> bool:
    """A zarr chunk key part: ``0``, ``12`` (v3 ``c/0/12``) or ``0.12`` (v2)."""
    return all(part.isdigit() for part in name.split("."))


def _foreign_in_chunks(folder: Path, prefix: str) -> list[str]:
    """Entries under a v3 chunk folder (``c/``) whose names are not chunk keys, links, or neither file nor folder."""
    foreign = []
    for entry in sorted(folder.iterdir()):
        name = f"{prefix}/{entry.name}"
        if _is_interrupted_write(entry):
            continue
        if entry.is_symlink() or not _is_chunk_name(entry.name):
            foreign.append(name)
        elif entry.is_dir():
            foreign.extend(_foreign_in_chunks(entry, name))
        elif not entry.is_file():
            foreign.append(name)
    return foreign


def _foreign_in_node(folder: Path, prefix: str) -> list[str]:
    """Entries of a zarr array or group folder that zarr did not write: anything but its metadata, its chunks
    (v3 under ``c/``, v2 named ``0.1``) and nested arrays or groups (checked the same way)."""
    foreign = []
    for entry in sorted(folder.iterdir()):
        name = f"{prefix}{entry.name}"
        if entry.is_symlink():
            foreign.append(name)
        elif (entry.name in _ZARR_NODE_METADATA and entry.is_file()) or _is_interrupted_write(entry):
            continue
        elif entry.is_dir() and entry.name == "c":
            foreign.extend(_foreign_in_chunks(entry, name))
        elif _is_zarr_node(entry):
            foreign.extend(_foreign_in_node(entry, f"{name}/"))
        elif entry.is_file() and _is_chunk_name(entry.name):
            continue
        else:
            foreign.append(name)
    return foreign


def foreign_store_entries(folder: Path | str) -> list[str]:
    """Entries of an owned store, at any depth, that neither zarr nor thermogear wrote (a user's ``notes.txt`` at
    the top or inside an array's folder), as paths relative to the store: the marker, zarr's metadata files, the
    arrays' and groups' folders with their metadata and chunk files are its own."""
    root = Path(folder)
    foreign = []
    for entry in sorted(root.iterdir()):
        if entry.name in (MARKER, *ZARR_METADATA) and entry.is_file() and not entry.is_symlink():
            continue
        if _is_zarr_node(entry):
            foreign.extend(_foreign_in_node(entry, f"{entry.name}/"))
            continue
        foreign.append(entry.name)
    return foreign


def require_no_foreign_entries(folder: Path | str, option: str = "--out") -> None:
    """Refuse (CaseError, nothing touched) to replace an owned store that holds entries thermogear did not write,
    naming them: thermogear deletes only what it wrote."""
    foreign = foreign_store_entries(folder)
    if foreign:
        shown = ", ".join(foreign[:5]) + (f" and {len(foreign) - 5} more" if len(foreign) > 5 else "")
        raise CaseError(option, str(folder), "a store holding only what thermogear wrote",
                        f"it also holds {shown}, which thermogear did not write and never deletes; move them "
                        "out of the store and run again (nothing was changed)")


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


def _check_name_lengths(target: Path, option: str, given) -> None:
    """Refuse a path the file system cannot name: a component longer than NAME_MAX or a whole path longer than
    PATH_MAX of the nearest existing folder (a 5000-character --out failed with "File name too long" after the
    computation, issue 25)."""
    existing = _nearest_existing(target)
    try:
        name_max = os.pathconf(existing, "PC_NAME_MAX")
        path_max = os.pathconf(existing, "PC_PATH_MAX")
    except (OSError, ValueError, AttributeError):  # no pathconf (Windows) or no answer: the usual limits
        name_max, path_max = 255, 4096
    longest = max((len(os.fsencode(part)) for part in target.parts), default=0)
    if longest > name_max:
        raise CaseError(option, str(given), f"names of at most {name_max} bytes",
                        f"a part of the path is {longest} bytes long; the file system cannot create it")
    if len(os.fsencode(str(target))) >= path_max:
        raise CaseError(option, str(given), f"a path shorter than {path_max} bytes",
                        "the file system cannot create a path this long")


def _nearest_existing(target: Path) -> Path:
    """The nearest folder of ``target`` (or ``target``) that exists; names that cannot be looked up count as absent."""
    existing = target
    while existing != existing.parent:
        try:
            if existing.exists():
                return existing
        except (OSError, ValueError):
            pass
        existing = existing.parent
    return existing


def check_figure_file(path: Path | str, option: str = "--plot", suffixes: tuple[str, ...] = FIGURE_SUFFIXES) -> Path:
    """Check a figure file target before any work: a known suffix, a name the file system can hold, not an existing
    folder, in an existing writable folder. Returns the resolved path; raises CaseError naming the option (a file
    of that name is replaced). Every command that writes a figure calls it before it computes anything."""
    target = resolve_output(path)
    if target.suffix.lower() not in suffixes:
        raise CaseError(option, str(path), "a file name ending in " + ", ".join(suffixes),
                        "the figure format is taken from the suffix")
    _check_name_lengths(target, option, path)
    try:
        if target.is_dir():
            raise CaseError(option, str(path), "a file name (not a folder)", "a folder of that name exists")
        if not target.parent.is_dir():
            raise CaseError(option, str(path), "a file in an existing folder", f"no folder {target.parent}")
        if not os.access(target.parent, os.W_OK | os.X_OK) or (target.exists() and not os.access(target, os.W_OK)):
            raise CaseError(option, str(path), "a file in a writable folder", f"cannot write {target}")
    except OSError as error:
        raise CaseError(option, str(path), "a file path thermogear can write",
                        error.strerror or str(error)) from None
    return target


def check_output_folder(path: Path | str, option: str = "--plot") -> Path:
    """Check a folder that thermogear writes into (created if absent) before any work: a name the file system can
    hold, not an existing file, creatable or writable. Returns the resolved path; raises CaseError naming the
    option. Every command that writes a folder (reports, stores, figure folders) calls it first."""
    target = resolve_output(path)
    _check_name_lengths(target, option, path)
    try:
        if target.exists() and not target.is_dir():
            raise CaseError(option, str(path), "a folder (thermogear writes into it)", "a file of that name exists")
        existing = _nearest_existing(target)
        if not existing.is_dir() or not os.access(existing, os.W_OK | os.X_OK):
            raise CaseError(option, str(path), "a folder thermogear can create and write",
                            f"cannot write there: {existing} is not a writable folder")
    except OSError as error:
        raise CaseError(option, str(path), "a folder thermogear can create and write",
                        error.strerror or str(error)) from None
    return target


@contextmanager
def exclusive_writer(target: Path | str, option: str = "--out") -> Iterator[None]:
    """Hold the one-writer lock of an output (a sweep store) for the block; a second thermogear process asking
    for the same output is refused at once with a CaseError (two ``sweep --overwrite`` into one store raced and
    left a store without its marker, issue 25). The lock is an advisory ``flock`` on ``.NAME.lock`` beside the
    output, released by the system however the holder ends (even SIGKILL); the file is removed on release.
    Where ``flock`` does not exist (Windows) the block runs unlocked."""
    try:
        import fcntl  # noqa: PLC0415
    except ImportError:  # pragma: no cover  (not POSIX)
        yield
        return
    resolved = resolve_output(target)
    lock_path = resolved.parent / f".{resolved.name}.lock"
    try:
        resolved.parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise CaseError(option, str(target), "a folder thermogear can create and write",
                        f"cannot write there: {error.strerror or error}") from None
    while True:
        try:
            handle = os.open(lock_path, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as error:
            raise CaseError(option, str(target), "a folder thermogear can create and write",
                            f"cannot create its lock file: {error.strerror or error}") from None
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(handle)
            raise CaseError(option, str(target), "an output no other thermogear process is writing",
                            f"another thermogear process is writing it now (lock {lock_path.name}); wait for it to "
                            "finish, or choose another --out") from None
        try:  # the holder before us may have removed the file after we opened it: lock the file on disk
            same = os.path.samestat(os.fstat(handle), os.stat(lock_path))
        except OSError:
            same = False
        if same:
            break
        os.close(handle)
    try:
        os.ftruncate(handle, 0)
        os.write(handle, json.dumps({"writer": "thermogear", "pid": os.getpid(),
                                     "host": socket.gethostname()}).encode())
        yield
    finally:
        try:
            os.unlink(lock_path)
        except OSError:
            pass
        os.close(handle)
