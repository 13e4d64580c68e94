"""Reading a text file the user named (a case, a temperature table), with an error that names the key."""

from __future__ import annotations

from pathlib import Path

from thermogear.errors import CaseError

__all__ = ["is_existing_file", "path_exists", "read_user_text"]


def path_exists(path: Path) -> bool:
    """``path.exists()``, False (not an OSError) for a name the system cannot look up (too long, a NUL byte):
    Python 3.11's ``exists`` ignores only "no such file"."""
    try:
        return Path(path).exists()
    except (OSError, ValueError):
        return False


def is_existing_file(path: Path) -> bool:
    """``path.is_file()``, False for a name the system cannot look up (see :func:`path_exists`)."""
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


def read_user_text(path: Path, key: str, value, kind: str) -> str:
    """The UTF-8 text of ``path``; a CaseError naming ``key`` = ``value`` when it is not UTF-8 or cannot be read
    (``kind``: what the file should be, e.g. "TOML", "CSV")."""
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError as error:
        raise CaseError(key, value, f"a UTF-8 text file ({kind})",
                        f"byte {error.start} cannot be read as UTF-8 (a binary or latin-1 file?)") from None
    except OSError as error:
        raise CaseError(key, value, f"a readable {kind} file", error.strerror or str(error)) from None
