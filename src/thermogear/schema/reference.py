"""The case-file schema as a list of keys: section, key, unit, type, allowed range, default and meaning.

One reading of :meth:`CaseFile.model_json_schema` shared by ``thermogear schema`` (a table on the terminal) and
``docs/generate.py`` (``docs/case-file-reference.md``), so that the two always say the same. Plain text only: the
command and the page each format the rows their own way.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["SchemaKey", "SchemaSection", "case_file_sections"]

#: Meaning of keys whose schema field has no description (section.key → text).
MEANINGS = {
    "case.name": "short identifier of the case, used in file names and reports",
    "case.title": "one-line description shown in reports",
    "case.citation": "where the numbers come from (paper, standard, drawing)",
    "case.assumptions": "everything the source leaves open and the case assumes, one sentence each (may be empty: "
                        "`[]`)",
    "temperature.model": "source of the tooth temperatures: 'uniform' (bulk_c), 'tabulated' (flank table), 'fem' "
                         "(finite-element bulk temperature), 'gearbox' (predicted by the thermal network of the case's gearbox section)",
    "temperature.fit_degree": "degree of the polynomial fitted to the flank table [–]",
    "thermal.x_te_source": "where X_te of model 'luo2020' comes from: 'given' (x_te), 'calibrated' (to "
                           "calibration_drop_percent at calibration_point), 'fem'",
    "thermal.calibration_drop_percent": "stiffness drop k_T below k_e to calibrate X_te to [%]",
    "thermal.calibration_point": "point of the path where the calibration drop applies",
    "thermal.load_basis": "F_n of Luo & Li Eqs. 13–18: the external normal load or the pair's share",
    "damping.rule": "how the pairs in contact combine into c(τ): 'paper' (mean of the pairs, Luo & Li Fig. 7) or "
                    "'parallel' (dampers add)",
    "dynamics.method": "steady state by the exact periodic (Floquet) solution or by integrating from rest",
    "dynamics.points_per_period": "intervals of the mesh-cycle grid per mesh period [–]",
    "dynamics.transient_periods": "mesh periods integrated from rest by the transient method [–]",
    "sweep.model": "models the study runs: 'elastic', 'thermal' or 'both'",
}

#: Keys that are optional alone but required in some combination (section.key → when).
REQUIRED_WHEN = {
    "gears.face_width_mm": "required unless both gears give face_width_mm",
    "operating.power_kw": "give exactly one of power_kw, torque_nm, fzg_load_stage",
    "operating.torque_nm": "give exactly one of power_kw, torque_nm, fzg_load_stage",
    "operating.fzg_load_stage": "give exactly one of power_kw, torque_nm, fzg_load_stage",
    "lubricant.name": "a built-in oil, or give viscosity_points (then name is only a label)",
    "lubricant.viscosity_points": "required unless name is a built-in oil",
    "temperature.bulk_c": "with model = 'uniform'; not set: the oil's operating temperature "
                          "(lubricant.operating_temperature_c), said in a note",
    "temperature.gamma": "with flank_c, or csv, required with model = 'tabulated'",
    "temperature.flank_c": "with gamma, or csv, required with model = 'tabulated'",
    "thermal.x_te": "required with model = 'luo2020' and x_te_source = 'given'",
    "thermal.calibration_drop_percent": "required with x_te_source = 'calibrated'",
    "fem.bore_h_w_per_m2_k": "required with bore = 'convective'",
}

#: Unit of a key from its name's suffix, for descriptions that do not state one (longest suffix first).
UNIT_SUFFIXES = (("_w_per_m2_k", "W/(m² K)"), ("_w_per_m_k", "W/(m K)"), ("_j_per_kg_k", "J/(kg K)"),
                 ("_per_k", "1/K"), ("_kg_m3", "kg/m³"), ("_kg_m2", "kg m²"), ("_percent", "%"), ("_deg", "°"),
                 ("_rpm", "rpm"), ("_gpa", "GPa"), ("_kw", "kW"), ("_nm", "N m"), ("_mm", "mm"), ("_um", "μm"),
                 ("_c", "°C"))

#: The first bracketed text of a description: its unit ("module m [mm]"), unless it names a section.
_UNIT = re.compile(r"\[([^\]\[]{1,16})\]")
#: Bracketed words that name a section, not a unit ("default [material]").
_SECTIONS = {"case", "gears", "material", "operating", "lubricant", "temperature", "thermal", "housing",
             "damping", "dynamics", "fem", "sweep"}


@dataclass(frozen=True)
class SchemaKey:
    """One key of a case-file section, in words."""

    section: str  #: dotted section name, e.g. ``gears.pinion``
    key: str
    kind: str  #: ``number``, ``integer``, ``string``, ``boolean``, ``array of number``, ``'a' | 'b'`` …
    optional: bool  #: the key has no value unless given (no default: the model decides, see the meaning)
    allowed: str  #: the range, e.g. ``> 0, ≤ 2000``; empty when any value of the type is accepted
    default: str | None  #: the default as written in TOML; None when the key has none
    required: bool  #: the key must always be given
    unit: str  #: ``mm``, ``°C``, ``–`` (dimensionless); empty for texts, choices and switches
    description: str  #: the meaning with its unit in brackets, as the schema states it
    required_when: str  #: when an optional key becomes required ("" if never)

    @property
    def meaning(self) -> str:
        """The description without its unit (the unit has a column of its own) and with when it is required."""
        text = self.description
        if self.unit:
            text = text.replace(f" [{self.unit}]", "", 1).replace(f"[{self.unit}]", "", 1).strip()
        if self.required_when:
            text = f"{text}; {self.required_when}" if text else self.required_when
        return text

    @property
    def default_text(self) -> str:
        """``required``, ``not set`` or the default value."""
        if self.required:
            return "required"
        return "not set" if self.default is None else self.default


@dataclass(frozen=True)
class SchemaSection:
    """One ``[section]`` of a case file and its keys (nested tables such as ``[gears.pinion]`` come as their own
    sections)."""

    name: str
    description: str
    required: bool
    keys: tuple[SchemaKey, ...]


def case_file_sections() -> list[SchemaSection]:
    """Every section of a case file, in file order, each with its keys (from :class:`thermogear.schema.CaseFile`)."""
    from thermogear.schema import CaseFile  # noqa: PLC0415  (pydantic: only when asked)

    schema = CaseFile.model_json_schema()
    required = set(schema.get("required", []))
    sections: list[SchemaSection] = []
    for name, node in schema["properties"].items():
        _collect(schema, name, node, name in required, sections)
    return sections


def _resolve(schema: dict, node: dict) -> dict:
    while True:
        if "$ref" in node:
            node = schema["$defs"][node["$ref"].split("/")[-1]]
        elif "anyOf" in node and any("$ref" in option for option in node["anyOf"]):
            node = next(option for option in node["anyOf"] if "$ref" in option)
        else:
            return node


def _collect(schema: dict, name: str, node: dict, required: bool, sections: list[SchemaSection]) -> None:
    node = _resolve(schema, node)
    keys, nested = [], []
    for key, field in node.get("properties", {}).items():
        target = _resolve(schema, field) if "$ref" in field else None
        if target is not None and target.get("type") == "object" and "properties" in target:
            nested.append((key, field, key in node.get("required", [])))
            continue
        keys.append(_key(name, key, field, key in node.get("required", [])))
    sections.append(SchemaSection(name, node.get("description", ""), required, tuple(keys)))
    for key, field, is_required in nested:
        _collect(schema, f"{name}.{key}", field, is_required, sections)


def _key(section: str, key: str, field: dict, required: bool) -> SchemaKey:
    kind, optional, allowed = _type_and_range(field)
    description = field.get("description", "")
    if not description and "anyOf" in field:
        description = next((o.get("description", "") for o in field["anyOf"] if o.get("description")), "")
    description = description or MEANINGS.get(f"{section}.{key}", "")
    unit = _unit(key, description)
    if not unit and kind.split(" or ")[0] in ("number", "integer", "array of number"):
        unit = "–"  # a number whose description and name state no unit is a ratio, a factor or a count
    if unit and unit != "–" and f"[{unit}]" not in description:
        description = f"{description} [{unit}]".strip()
    default = None
    if "default" in field and field["default"] is not None:
        default = _default_text(field["default"])
    return SchemaKey(section, key, kind, optional, allowed, default,
                     required and "default" not in field, unit, description,
                     REQUIRED_WHEN.get(f"{section}.{key}", ""))


def _unit(key: str, description: str) -> str:
    """The first bracketed text of the description that is not a section name, else the unit of the key's suffix."""
    for match in _UNIT.finditer(description):
        if match.group(1) not in _SECTIONS:
            return match.group(1)
    return next((unit for suffix, unit in UNIT_SUFFIXES if key.endswith(suffix)), "")


def _default_text(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, dict):
        return "(see below)"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _type_and_range(field: dict) -> tuple[str, bool, str]:
    options = field.get("anyOf", [field])
    types, ranges = [], []
    for option in options:
        kind = option.get("type")
        if kind == "null":
            continue
        if "enum" in option:
            types.append(" | ".join(f"'{item}'" for item in option["enum"]))
            continue
        if "const" in option:
            types.append(f"'{option['const']}'")
            continue
        if kind == "array":
            item = option.get("items", {})
            inner = item.get("type", "") if isinstance(item, dict) else ""
            types.append(f"array of {inner}".strip() if inner else "array")
        elif "$ref" in option:
            types.append("table")
        elif kind:
            types.append(kind)
        bounds = []
        for key, symbol in (("minimum", "≥"), ("exclusiveMinimum", ">"), ("maximum", "≤"),
                            ("exclusiveMaximum", "<")):
            if key in option:
                bounds.append(f"{symbol} {option[key]:g}")
        if bounds:
            ranges.append(", ".join(bounds))
    optional = any(option.get("type") == "null" for option in options)
    return " or ".join(types) or "any", optional, "; ".join(ranges)
