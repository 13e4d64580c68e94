"""Common base of the case-file sections: frozen, unknown keys refused, strict about types.

Strict types: a number key takes a number and a switch takes ``true``/``false``. Pydantic's lax mode would read
``speed_rpm = true`` as 1 rpm, ``speed_rpm = "2000"`` as 2000 and ``include_damping_force = 1`` as ``true``;
here each is refused, naming the key. An integer is accepted where a real number is asked for (TOML writes
``speed_rpm = 2000``), and a whole real number where an integer is asked for (a sweep's grid holds floats).
"""

from __future__ import annotations

import numbers
import types
import typing
from collections.abc import Callable
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, model_validator


def _leaf_kinds(annotation: Any) -> set[str]:
    """The kinds of plain values a field annotation admits: 'number', 'integer', 'bool', 'str', 'list', 'dict',
    'model' (unions, Optional and Annotated unwrapped)."""
    origin = typing.get_origin(annotation)
    if origin is typing.Annotated:
        return _leaf_kinds(typing.get_args(annotation)[0])
    if origin in (typing.Union, types.UnionType):
        kinds: set[str] = set()
        for argument in typing.get_args(annotation):
            kinds |= _leaf_kinds(argument)
        return kinds
    if origin is Literal:
        return {"bool" if isinstance(v, bool) else "str" if isinstance(v, str) else "number"
                for v in typing.get_args(annotation)}
    if origin in (list, tuple):
        return {"list"}
    if origin is dict:
        return {"dict"}
    if annotation is bool:
        return {"bool"}
    if annotation is int:
        return {"integer"}
    if annotation is float:
        return {"number"}
    if annotation is str:
        return {"str"}
    if annotation is type(None):
        return {"none"}
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return {"dict"}
    return {"any"}


def _member_annotations(annotation: Any, members: Callable[[Any, tuple], list[Any]]) -> list[Any]:
    """``members(origin, arguments)`` of each plain annotation inside a field annotation (through ``Annotated`` and
    unions)."""
    origin = typing.get_origin(annotation)
    if origin is typing.Annotated:
        return _member_annotations(typing.get_args(annotation)[0], members)
    if origin in (typing.Union, types.UnionType):
        return [item for argument in typing.get_args(annotation) for item in _member_annotations(argument, members)]
    return members(origin, typing.get_args(annotation))


def _items_annotation(annotation: Any) -> list[Any]:
    """Annotations of the items of the list/tuple members of a field annotation."""
    return _member_annotations(annotation, lambda origin, arguments: [
        argument for argument in arguments if argument is not Ellipsis] if origin in (list, tuple) else [])


def _dict_value_annotations(annotation: Any) -> list[Any]:
    """Annotations of the values of the plain ``dict[str, X]`` members of a field annotation (not sections)."""
    return _member_annotations(annotation, lambda origin, arguments: list(arguments[1:2]) if origin is dict else [])


def strict_type_problem(value: Any, annotation: Any) -> str | None:
    """Why ``value`` is not of the kind ``annotation`` asks for, or None when it is (recursing into lists)."""
    kinds = _leaf_kinds(annotation)
    if "any" in kinds or value is None:
        return None
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        if "bool" in kinds:
            return None
        if kinds & {"number", "integer"}:
            return "a number is asked for, not true/false"
        return None  # another type mismatch: pydantic names it
    if isinstance(value, str):
        if "str" in kinds:
            return None
        if kinds & {"number", "integer"}:
            return "a number is asked for, not a string (write it without quotes)"
        if "bool" in kinds:
            return "true or false is asked for, not a string (write it without quotes)"
        return None
    if isinstance(value, numbers.Number):
        if "bool" in kinds and not kinds & {"number", "integer"}:
            return "true or false is asked for, not a number"
        return None
    if isinstance(value, dict):  # a table of values (sweep.vary): each value as the table's value type asks
        for value_annotation in _dict_value_annotations(annotation):
            for item in value.values():
                problem = strict_type_problem(item, value_annotation)
                if problem is not None:
                    return problem
        return None
    if isinstance(value, (list, tuple)):
        for item_annotation in _items_annotation(annotation):
            for item in value:
                problem = strict_type_problem(item, item_annotation)
                if problem is not None:
                    return problem
    return None


_KINDS: dict[tuple[type, str], frozenset[str]] = {}
_SCALAR_PROBLEMS: dict[tuple[type, str, type], str | None] = {}
_UNKNOWN = object()


def _numbers_only(values: list) -> bool:
    """True for a list (of lists) of plain floats and ints, no booleans: nothing for the strict check to find."""
    return all(type(item) in (float, int) or (type(item) is list and _numbers_only(item)) for item in values)


def _field_kinds(model: type[BaseModel], name: str | None) -> frozenset[str]:
    """:func:`_leaf_kinds` of a model's field, computed once per field."""
    key = (model, name or "")
    kinds = _KINDS.get(key)
    if kinds is None:
        field = model.model_fields.get(name or "")
        kinds = _KINDS[key] = frozenset(_leaf_kinds(field.annotation) if field is not None else {"any"})
    return kinds


class StrictTypeError(ValueError):
    """A value of the wrong kind (a boolean or a string for a number, a number for a switch)."""

    def __init__(self, name: str, allowed: str, reason: str) -> None:
        self.name = name
        self.allowed = allowed
        self.reason = reason
        super().__init__(f"wrong type: {reason}")


class Section(BaseModel):
    """A case-file section: immutable, strict about unknown keys and types, ints accepted as floats."""

    model_config = ConfigDict(extra="forbid", frozen=True, validate_default=True)

    @model_validator(mode="before")
    @classmethod
    def _strict_types(cls, data: Any) -> Any:
        """One pass over the section's given keys (one call per section, not per field: the case schema is
        validated for every point of a sweep)."""
        if not isinstance(data, dict):
            return data
        for name, value in data.items():
            if value is None or (type(value) is list and _numbers_only(value)):
                continue  # nothing to find
            field = cls.model_fields.get(name)
            if field is None:
                continue  # an unknown key: refused by extra="forbid", with the closest key
            scalar = type(value) in (bool, int, float, str)
            key = (cls, name, type(value))
            problem = _SCALAR_PROBLEMS.get(key, _UNKNOWN) if scalar else _UNKNOWN
            if problem is _UNKNOWN:
                problem = strict_type_problem(value, field.annotation)
                if scalar:  # for a scalar the verdict depends on its type only: decided once per field and type
                    _SCALAR_PROBLEMS[key] = problem
            if problem is not None:
                kinds = _field_kinds(cls, name)
                allowed = ("a number" if kinds & {"number", "integer"} else "true or false" if "bool" in kinds
                           else "a list of numbers" if "list" in kinds
                           else "text, numbers or lists of numbers" if "dict" in kinds
                           else "a value of the documented type")
                raise StrictTypeError(name, allowed, f"wrong type: {problem}")
        return data
