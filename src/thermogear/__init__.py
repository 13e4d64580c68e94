"""thermogear: thermo-elastic dynamics of spur gear transmissions.

Start with :func:`load_case` (a built-in parameter set such as ``"luo2019"`` or a TOML case file).
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("thermogear")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

from thermogear.case import Case, load_case, parameter_set_names  # noqa: E402
from thermogear.errors import CaseError, ExtrapolationWarning, ThermogearError  # noqa: E402
from thermogear.geometry import Gear, GearPair  # noqa: E402
from thermogear.materials import Material  # noqa: E402
from thermogear.operating import OperatingPoint  # noqa: E402

__all__ = ["Case", "CaseError", "ExtrapolationWarning", "Gear", "GearPair", "Material", "OperatingPoint",
           "ThermogearError", "__version__", "load_case", "parameter_set_names"]
