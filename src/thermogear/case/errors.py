"""A pydantic validation error of a case file as one CaseError: the dotted key, the value, the allowed range and
the reason, with the closest valid key suggested for an unknown one (looked for in the same section first, then
across sections)."""

from __future__ import annotations

from typing import Any

import pydantic

from thermogear.errors import CaseError, closest_key
from thermogear.schema import CaseFile
from thermogear.schema.base import StrictTypeError


def case_error_from_validation(error: pydantic.ValidationError) -> CaseError:
    """The first pydantic error as a CaseError naming key, value, allowed range and reason. An unknown key is
    reported before a missing one (a misspelt section name is both: ``[gear]`` for ``[gears]``), and a wrong value
    before a missing key (a wrong value in a section the case had not started yet is the one the user wrote)."""
    errors = error.errors(include_url=False)
    first = next((item for item in errors if item["type"] == "extra_forbidden"),
                 next((item for item in errors if item["type"] != "missing"), errors[0]))
    raised = (first.get("ctx") or {}).get("error")
    if isinstance(raised, CaseError):  # a schema validator that names its key, range and reason itself
        return raised
    location = [str(part) for part in first["loc"] if not isinstance(part, int)]
    key = ".".join(location) or "case"
    value = first.get("input")
    if isinstance(raised, StrictTypeError):  # raised by the section (a model validator): its key is added here
        key = ".".join([*location, raised.name])
        value = value.get(raised.name) if isinstance(value, dict) else value
        return CaseError(key, value, raised.allowed, raised.reason)
    kind = first["type"]
    context = first.get("ctx") or {}
    if kind == "extra_forbidden":
        valid = _valid_keys(location[:-1])
        suggestion = _suggested_key(location, valid)
        hint = f"did you mean '{suggestion}'?" if suggestion else "see `thermogear schema`"
        if isinstance(value, dict):  # a whole table: a misspelt section
            hint = f"did you mean '{suggestion}'?" if suggestion else hint
            return CaseError(key, "{...}", "one of the sections: " + ", ".join(sorted(valid)),
                             f"unknown section [{key}] ({hint})")
        return CaseError(key, value, "one of: " + ", ".join(sorted(valid)), f"unknown key ({hint})")
    if kind == "missing":
        return CaseError(key, None, "a value", "this key is required")
    bounds = {"greater_than": "> {gt}", "greater_than_equal": ">= {ge}", "less_than": "< {lt}",
              "less_than_equal": "<= {le}"}
    if kind in bounds:
        allowed = bounds[kind].format(**context)
        reason = "out of range" + (_unit_hint(key, value, context))
        return CaseError(key, value, allowed, reason)
    if kind in ("finite_number", "float_parsing") and isinstance(value, float):
        return CaseError(key, value, "a finite number", "NaN or infinity has no meaning here")
    if kind == "literal_error":
        return CaseError(key, value, str(context.get("expected", "")), "not one of the choices")
    if kind == "value_error":
        message = str(context.get("error", first["msg"]))
        name, _, reason = message.partition(": ")
        return CaseError(f"{key}.{name}" if key != "case" and reason else (name if reason else key), value,
                         "see the message", reason or message)
    return CaseError(key, value, first["msg"].lower(), f"wrong type ({kind})")


def _unit_hint(key: str, value: Any, context: dict) -> str:
    if key.endswith("_c") and isinstance(value, (int, float)):
        if value <= -273.15:
            return ": below absolute zero"
        if "le" in context:
            return (": above what the material data cover (room-temperature E, ν and a constant expansion "
                    "coefficient; gear steels temper at 150–200 °C)")
    if key.endswith("_mm") and isinstance(value, (int, float)) and 0 < value < 0.1:
        return ": this looks like metres, the key is in millimetres"
    if key.endswith("_gpa") and isinstance(value, (int, float)) and value > 1e6:
        return ": this looks like Pa, the key is in GPa"
    return ""


def _section_model(annotation) -> type[pydantic.BaseModel] | None:
    candidates = [annotation, *getattr(annotation, "__args__", ())]
    return next((c for c in candidates if isinstance(c, type) and issubclass(c, pydantic.BaseModel)), None)


def _valid_keys(location: list[str]) -> list[str]:
    model: type[pydantic.BaseModel] = CaseFile
    for part in location:
        model = _section_model(model.model_fields[part].annotation)
    return list(model.model_fields)


def _key_paths(model: type[pydantic.BaseModel] = CaseFile, prefix: str = "") -> list[str]:
    """Every key of the case file as a dotted path (``gears.pinion.teeth``), sections themselves excluded."""
    paths = []
    for name, field in model.model_fields.items():
        inner = _section_model(field.annotation)
        paths += _key_paths(inner, f"{prefix}{name}.") if inner is not None else [f"{prefix}{name}"]
    return paths


def _suggested_key(location: list[str], valid: list[str]) -> str | None:
    """What an unknown key probably meant: the same key in the section where it belongs (``pressure_angle_deg``
    under ``[operating]`` → ``gears.pressure_angle_deg``), else the closest key of its own section, else the
    closest key of any section (as a dotted path)."""
    name, here = location[-1], ".".join(location[:-1])
    elsewhere = [path for path in _key_paths() if path.rpartition(".")[2] == name and path.rpartition(".")[0] != here]
    if elsewhere:
        return elsewhere[0]
    suggestion = closest_key(name, valid)
    if suggestion is not None:
        return suggestion
    by_name = {path.rpartition(".")[2]: path for path in reversed(_key_paths())}  # first section wins a tie
    suggestion = closest_key(name, by_name)
    return by_name[suggestion] if suggestion is not None else None
