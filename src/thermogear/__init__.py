"""thermogear: thermo-elastic dynamics of spur gear transmissions.

Start with :func:`load_case` (a built-in parameter set such as ``"luo2019"`` or a TOML case file), or with
:func:`run`, which runs every system of a case (the 1-DOF pair, its drivetrain) under both models and returns their
typed results (``thermogear.run("luo2019").to_dataframe()``).
"""

from __future__ import annotations

import time as _time

#: When Python began importing thermogear [s, time.perf_counter]: the origin of the command line's start-up time.
IMPORT_STARTED = _time.perf_counter()

from importlib.metadata import PackageNotFoundError, version  # noqa: E402

try:
    __version__ = version("thermogear")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

from thermogear.errors import CaseError, ExtrapolationWarning, ThermogearError  # noqa: E402

# The components load on first use (PEP 562), so that `import thermogear.cli` (`thermogear --help`) does not pay
# for NumPy and pydantic: name → module that defines it.
_LAZY = {"Case": "thermogear.case", "load_case": "thermogear.case", "parameter_set_names": "thermogear.case",
         "Gear": "thermogear.geometry", "GearPair": "thermogear.geometry", "Material": "thermogear.materials",
         "OperatingPoint": "thermogear.operating", "run": "thermogear.orchestrator",
         "RunResults": "thermogear.orchestrator"}


def __getattr__(name: str):
    if name == "sweep":  # the studies' package, callable: thermogear.sweep(case, vary={...}, out=...)
        import importlib  # noqa: PLC0415

        return importlib.import_module("thermogear.sweep")
    if name not in _LAZY:
        raise AttributeError(f"module 'thermogear' has no attribute {name!r}")
    import importlib  # noqa: PLC0415

    value = getattr(importlib.import_module(_LAZY[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


__all__ = ["Case", "CaseError", "ExtrapolationWarning", "Gear", "GearPair", "Material", "OperatingPoint", "RunResults",
           "ThermogearError", "__version__", "load_case", "parameter_set_names", "run"]
