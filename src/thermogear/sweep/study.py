"""Study definition: a grid over case parameters, its points, its chunks, and the case each point runs.

A study varies one or more case parameters over lists of values; the points are the Cartesian product, in the
order the parameters are given (the last one varies fastest). Parameters are named by short aliases
(``speed_rpm``, ``oil_temperature_c``) or by any dotted case-file key (``gears.pinion.profile_shift``).

Values are written ``a:b:n`` (n values from a to b, both included, evenly spaced), ``v1,v2,...`` (a list) or one
number. Every value is checked against the case schema when the study is defined, so a bad value fails at once
with a :class:`~thermogear.errors.CaseError` naming the parameter, not after an hour of computing.

The chunks (blocks of the grid computed by one task and written as one region of the result store) depend only
on the study definition, never on the number of workers: a study gives the same chunks, hence the same numbers
bit for bit, on a laptop, on a cluster and after any number of interruptions.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import tomllib
import typing
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pydantic

from thermogear.temperature.kinds import temperature_source
from thermogear.errors import CaseError, JammingError, closest_key
from thermogear.schema.values import MAX_POINTS, parse_values
from thermogear.sweep.load_held import DEFAULT_HOLD, HOLDS, fixed_load_changes, held_load

__all__ = ["ALIASES", "HOLDS", "Block", "Parameter", "Study", "load_study_case", "parse_values", "resolve_key"]

#: Short names of the parameters engineers sweep most, and the case-file keys they set.
ALIASES: dict[str, str] = {
    "speed_rpm": "operating.speed_rpm",
    "torque_nm": "operating.torque_nm",
    "power_kw": "operating.power_kw",
    "fzg_load_stage": "operating.fzg_load_stage",
    "oil_temperature_c": "lubricant.operating_temperature_c",
    "oil_reference_temperature_c": "lubricant.reference_temperature_c",
    "x_te": "thermal.x_te",
    "module_mm": "gears.module_mm",
    "face_width_mm": "gears.face_width_mm",
    "pinion_profile_shift": "gears.pinion.profile_shift",
    "wheel_profile_shift": "gears.wheel.profile_shift",
    "roughness_ra_um": "gears.roughness_ra_um",
    "bulk_temperature_c": "temperature.bulk_c",
    "flank_temperature_offset_c": "temperature.flank_offset_c",
    "wheel_flank_offset_c": "temperature.wheel_flank_offset_c",
    "ambient_c": "gearbox.ambient_c",
}

#: Keys set together with a parameter so that the case stays consistent (exactly one load input; a given X_te).
COMPANION_CHANGES: dict[str, dict[str, Any]] = {
    "operating.torque_nm": {"operating.power_kw": None, "operating.fzg_load_stage": None},
    "operating.power_kw": {"operating.torque_nm": None, "operating.fzg_load_stage": None},
    "operating.fzg_load_stage": {"operating.power_kw": None, "operating.torque_nm": None},
    "thermal.x_te": {"thermal.x_te_source": "given"},
}

#: A derived parameter: a shift of every tabulated flank temperature (the case's flank table + offset).
FLANK_OFFSET_KEY = "temperature.flank_offset_c"

#: The ``model`` choices of a study by name → the simulation models it runs: the one place they are compared.
MODEL_CHOICES: dict[str, tuple[str, ...]] = {"elastic": ("elastic",), "thermal": ("thermal",),
                                             "both": ("elastic", "thermal")}
DEFAULT_CHUNK_POINTS = 4096  # points per task and zarr chunk: amortises the per-block cost (tables, writes)
#: Large studies get larger chunks, about this many tasks, up to LARGEST_DEFAULT_CHUNK points: at 10⁶ points the
#: per-task cost of 4096-point chunks kept two workers at 1.55× of serial; 20 000-point chunks give 1.68× (and
#: a chunk is still only a few MB of results, so memory stays flat).
DEFAULT_TASK_COUNT = 50
LARGEST_DEFAULT_CHUNK = 65536


def default_chunk_points(size: int) -> int:
    """Points per task and zarr chunk of a study of ``size`` grid points when the user sets none."""
    return int(min(LARGEST_DEFAULT_CHUNK, max(DEFAULT_CHUNK_POINTS, math.ceil(size / DEFAULT_TASK_COUNT))))
#: Values of one parameter checked by building a case (about 0.3 ms each; 10⁶ took minutes).
CHECKED_VALUES = 65


# ---------------------------------------------------------------------------------------------- parsing
def _case_file_model():
    from thermogear.schema import CaseFile

    return CaseFile


def _field_annotation(key: str):
    """Annotation of a dotted case-file key in the schema, or raise CaseError with the closest valid key."""
    model = _case_file_model()
    parts = key.split(".")
    for depth, part in enumerate(parts):
        fields = model.model_fields
        if part not in fields:
            prefix = ".".join(parts[:depth])
            valid = [f"{prefix}.{name}" if prefix else name for name in fields]
            suggestion = closest_key(key, valid + list(ALIASES))
            hint = f" (did you mean '{suggestion}'?)" if suggestion else ""
            raise CaseError("vary", key, "an alias (" + ", ".join(sorted(ALIASES)) + ") or a dotted case key",
                            f"unknown case parameter{hint}")
        annotation = fields[part].annotation
        if depth == len(parts) - 1:
            return annotation
        candidates = [annotation, *typing.get_args(annotation)]
        nested = [c for c in candidates if isinstance(c, type) and issubclass(c, pydantic.BaseModel)]
        if not nested:
            raise CaseError("vary", key, "a key that names a single number", f"'{part}' is not a section")
        model = nested[0]
    raise AssertionError("unreachable")  # pragma: no cover


def _is_integer_field(annotation) -> bool:
    """True when the schema field holds an integer (teeth, FZG load stage)."""
    candidates = [annotation, *typing.get_args(annotation)]
    for candidate in candidates:
        candidates.extend(typing.get_args(candidate))
    numeric = [c for c in candidates if c in (int, float)]
    return bool(numeric) and all(c is int for c in numeric)


def resolve_key(name: str) -> str:
    """Dotted case key of an alias or of a dotted key (checked against the schema)."""
    key = ALIASES.get(name, name)
    if key != FLANK_OFFSET_KEY:
        _field_annotation(key)
    return key


# --------------------------------------------------------------------------------------------- the study
@dataclass(frozen=True)
class Parameter:
    """One swept parameter: its dimension ``name`` (alias or dotted key), case ``key`` and ``values``."""

    name: str
    key: str
    values: tuple[float | int, ...]

    @property
    def size(self) -> int:
        return len(self.values)


@dataclass(frozen=True)
class Block:
    """A chunk of the grid: ``index`` (chunk coordinates) and ``slices`` (one per parameter, in grid order)."""

    index: tuple[int, ...]
    number: int
    slices: tuple[slice, ...]

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(s.stop - s.start for s in self.slices)

    @property
    def size(self) -> int:
        return int(np.prod(self.shape))


def _chunk_shape(sizes: tuple[int, ...], target: int) -> tuple[int, ...]:
    """Chunk shape of about ``target`` points: whole trailing dimensions first, then slices of the next one."""
    shape = []
    budget = max(int(target), 1)
    for size in reversed(sizes):
        take = max(min(size, budget), 1)
        shape.append(take)
        budget = max(budget // take, 1)
    return tuple(reversed(shape))


@dataclass(frozen=True)
class Study:
    """A parameter study of one case: the grid of ``parameters`` for the ``models`` (elastic and/or thermal).

    ``chunk_points``: about how many grid points one task computes and the store writes as one chunk (each
    point runs every model of the study).
    """

    case: Any  # thermogear.case.Case
    parameters: tuple[Parameter, ...]
    models: tuple[str, ...] = ("elastic", "thermal")
    chunk_points: int = DEFAULT_CHUNK_POINTS
    fixed_changes: tuple[tuple[str, Any], ...] = ()
    hold: str = "torque"
    _flank_table: tuple[float, ...] | None = field(default=None, repr=False, compare=False)

    # ------------------------------------------------------------------------------ construction
    @classmethod
    def define(cls, case, vary: dict[str, Any] | list[str], model: str = "both",
               chunk_points: int | None = None, hold: str = "torque") -> "Study":
        """A checked study. ``vary``: ``{"speed_rpm": "500:12000:240", ...}`` or ``["speed_rpm=500:12000:240"]``
        (the command-line form). ``model``: ``"elastic"``, ``"thermal"`` or ``"both"``. ``hold``: the load a speed
        sweep keeps, ``"torque"`` (default) or ``"power"`` (:data:`HOLDS`)."""
        held_load(hold)  # a CaseError naming --hold for a load no speed sweep keeps
        if model not in MODEL_CHOICES:
            raise CaseError("model", model, " | ".join(MODEL_CHOICES), "unknown model choice")
        models = MODEL_CHOICES[model]
        if isinstance(vary, dict):
            items = list(vary.items())
        else:
            items = []
            for entry in vary:
                name, sep, spec = str(entry).partition("=")
                if not sep or not name.strip() or not spec.strip():
                    raise CaseError("vary", entry, "NAME=VALUES, e.g. speed_rpm=500:12000:240",
                                    "each --vary names one parameter and its values")
                items.append((name.strip(), spec.strip()))
        if not items:
            raise CaseError("vary", [], "at least one parameter", "a sweep needs something to vary")
        parameters = []
        seen: dict[str, str] = {}
        for name, spec in items:
            key = resolve_key(name)
            if key in seen:
                raise CaseError("vary", name, "each case key once", f"'{seen[key]}' already sets {key}")
            seen[key] = name
            values = parse_values(spec, name=f"vary.{name}")
            if key != FLANK_OFFSET_KEY and _is_integer_field(_field_annotation(key)):
                if np.any(values != np.round(values)):
                    raise CaseError(f"vary.{name}", spec, "whole numbers", f"{key} is an integer")
                typed = tuple(int(v) for v in values)
            else:
                typed = tuple(float(v) for v in values)
            parameters.append(Parameter(name=name, key=key, values=typed))
            if (size := math.prod(p.size for p in parameters)) > MAX_POINTS:
                raise CaseError("vary", " × ".join(f"{p.name} {p.size:,}" for p in parameters),
                                f"at most {MAX_POINTS:,} grid points", f"this grid has {size:,} points")
        size = math.prod(p.size for p in parameters)
        chunk = default_chunk_points(size) if chunk_points is None else int(chunk_points)
        if chunk < 1:
            raise CaseError("chunk_points", chunk_points, ">= 1", "a chunk holds at least one point")
        flank = None
        if any(p.key == FLANK_OFFSET_KEY for p in parameters):
            flank = _flank_table_of(case.temperature)
        study = cls(case=case, parameters=tuple(parameters), models=models, chunk_points=chunk,
                    fixed_changes=fixed_load_changes(case.document.get("operating", {}),
                                                  case.operating_point, parameters, hold), hold=hold, _flank_table=flank)
        study.check_values()
        return study

    def check_values(self) -> None:
        """Build the case of each value of each parameter alone (others at the case's values); a bad one raises
        CaseError naming the parameter and value (except where the gears jam: the study marks those points
        ``jammed`` and computes the others). Above :data:`CHECKED_VALUES` values, the smallest, the largest
        and evenly spaced ones between are checked: the case checks are bounds and conditions that change once
        along one parameter (undercut, contact ratio), which the ends and the samples catch."""
        for parameter in self.parameters:
            values = sorted(parameter.values)
            if len(values) > CHECKED_VALUES:
                values = [values[i] for i in np.unique(np.linspace(0, len(values) - 1, CHECKED_VALUES).round()
                                                       .astype(int))]
            for value in values:
                try:
                    self.case.with_changes(**self._changes_for(((parameter, value),)))
                except JammingError:  # a point whose gears jam is computed as such (marked, no result)
                    continue
                except CaseError as error:
                    raise CaseError(f"vary.{parameter.name}", value, error.allowed,
                                    f"{error.key}: {error.reason}") from None

    # ------------------------------------------------------------------------------ the grid
    @property
    def dims(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.parameters)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(p.size for p in self.parameters)

    @property
    def size(self) -> int:
        """Number of grid points (each runs every model)."""
        return int(np.prod(self.shape))

    @property
    def chunk_shape(self) -> tuple[int, ...]:
        return _chunk_shape(self.shape, self.chunk_points)

    @property
    def block_grid(self) -> tuple[int, ...]:
        """Number of chunks along each dimension."""
        return tuple(-(-size // chunk) for size, chunk in zip(self.shape, self.chunk_shape))

    def blocks(self) -> list[Block]:
        """Every chunk of the grid, in C order (the block number is the flat index in that order)."""
        chunk = self.chunk_shape
        result = []
        for number, index in enumerate(itertools.product(*(range(n) for n in self.block_grid))):
            slices = tuple(slice(i * c, min((i + 1) * c, size)) for i, c, size in zip(index, chunk, self.shape))
            result.append(Block(index=index, number=number, slices=slices))
        return result

    def block_values(self, block: Block) -> list[tuple[float | int, ...]]:
        """Parameter values of every point of a block, in C order of the block."""
        axes = [p.values[s] for p, s in zip(self.parameters, block.slices)]
        return list(itertools.product(*axes))

    # ------------------------------------------------------------------------------ cases of points
    def _changes_for(self, pairs) -> dict[str, Any]:
        changes: dict[str, Any] = dict(self.fixed_changes)
        for parameter, value in pairs:
            if parameter.key == FLANK_OFFSET_KEY:
                table = self._flank_table if self._flank_table is not None else _flank_table_of(self.case.temperature)
                changes["temperature.flank_c"] = [t + float(value) for t in table]
                continue
            changes.update(COMPANION_CHANGES.get(parameter.key, {}))
            changes[parameter.key] = value
        return changes

    def changes(self, values: tuple[float | int, ...]) -> dict[str, Any]:
        """Dotted-key changes of the case for one point's parameter values (grid order)."""
        return self._changes_for(zip(self.parameters, values))

    def case_at(self, values: tuple[float | int, ...]):
        """The validated case of one point."""
        return self.case.with_changes(**self.changes(values))

    # ------------------------------------------------------------------------------ identity
    def describe(self) -> dict[str, Any]:
        """JSON-ready definition (stored in the result attributes; resume checks it)."""
        return {
            "parameters": [{"name": p.name, "key": p.key, "values": list(p.values)} for p in self.parameters],
            "models": list(self.models),
            "chunk_points": self.chunk_points,
            "fixed_changes": {key: value for key, value in self.fixed_changes},
            **({"hold": self.hold} if self.hold != DEFAULT_HOLD else {}),
            "case_document_sha256": case_fingerprint(self.case.document),
        }


def case_fingerprint(document: dict) -> str:
    """SHA-256 of a case's document (sorted JSON): two runs of one study must start from the same case."""
    text = json.dumps(document, sort_keys=True, default=str)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _flank_table_of(section) -> tuple[float, ...]:
    """The inline flank temperatures [°C] of a ``[temperature]`` section (the table a flank offset shifts)."""
    if not temperature_source(section.model).tabulated or section.flank_c is None:
        raise CaseError("vary.flank_temperature_offset_c", section.model,
                        "a case with temperature.model = 'tabulated' and flank_c given inline",
                        "the offset shifts the tabulated flank temperatures; for a uniform temperature vary "
                        "bulk_temperature_c")
    return tuple(float(t) for t in section.flank_c)


# ----------------------------------------------------------------------------------------- case files
def load_study_case(name_or_path: str | Path):
    """Load a case and its optional ``[sweep]`` table: returns ``(case, sweep_section or None)``.

    The ``[sweep]`` table is taken out of the document before the case is validated, so the case of every point
    is the case without its study (and a case file with a [sweep] table loads the same as one without).
    """
    from thermogear.case import case_from_document, load_case

    from thermogear.text_files import is_existing_file, read_user_text

    path = Path(str(name_or_path))
    if not (path.suffix == ".toml" and is_existing_file(path)):
        return load_case(name_or_path), None
    try:  # the same reading and the same errors as load_case
        document = tomllib.loads(read_user_text(path, "case", str(path), "TOML"))
    except tomllib.TOMLDecodeError as error:
        raise CaseError("case", str(path), "valid TOML", f"the file cannot be parsed: {error}") from None
    except RecursionError:
        raise CaseError("case", str(path), "TOML nested a few levels deep",
                        "the file nests tables or arrays too deeply to be a case file") from None
    from thermogear.case.errors import case_error_from_validation
    from thermogear.schema import CaseFile

    try:  # the whole file as `check` validates it: a bad [sweep] table gets check's message (check = sweep)
        section = CaseFile.model_validate(document).sweep
    except pydantic.ValidationError as error:
        raise case_error_from_validation(error) from None
    document.pop("sweep", None)
    return case_from_document(document, source=str(path)), section
