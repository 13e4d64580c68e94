"""One meaning, one definition: the material temperature limit is defined once and used by every check."""

from __future__ import annotations

import re
from pathlib import Path

import thermogear
from thermogear.temperature import field as temperature_field
from thermogear.thermoelastic import inputs

SOURCE = Path(thermogear.__file__).parent


def definitions(name: str, root: Path = SOURCE) -> list[str]:
    """Modules (relative paths) that assign ``name`` at module level."""
    pattern = re.compile(rf"^{re.escape(name)}\s*(:[^=]+)?=", re.MULTILINE)
    return sorted(str(path.relative_to(root)) for path in root.rglob("*.py")
                  if pattern.search(path.read_text(encoding="utf-8")))


def test_material_maximum_is_defined_once():
    # defined with the other temperature limits (issue 35: one set of limits for every command)
    assert definitions("MATERIAL_MAXIMUM_C") == ["temperature/limits.py"]
    assert inputs.MATERIAL_MAXIMUM_C is temperature_field.MATERIAL_MAXIMUM_C


def test_the_scan_finds_a_second_definition(tmp_path):
    (tmp_path / "a.py").write_text("MATERIAL_MAXIMUM_C = 200.0\n")
    (tmp_path / "b.py").write_text("MATERIAL_MAXIMUM_C: float = 200.0\nuse = MATERIAL_MAXIMUM_C\n")
    (tmp_path / "c.py").write_text("from x import MATERIAL_MAXIMUM_C\n")
    assert definitions("MATERIAL_MAXIMUM_C", tmp_path) == ["a.py", "b.py"]
