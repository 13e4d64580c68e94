"""The metrics of a response as frozen dataclasses (typed results); ``thermogear run`` writes its JSON and table
from them (:func:`typed_metrics`), other consumers still read the dicts.

:func:`~thermogear.dynamics.results.metrics.compute_metrics` (linear response) and the nonlinear response's metrics are
dicts read key by key; :class:`LinearMetrics` and :class:`NonlinearMetrics` hold the same values as typed, frozen
fields, built from such a dict (:meth:`from_dict`, which refuses a missing or an unknown key) and written back by
:meth:`as_dict` to exactly the dict they came from: the same keys in the same order and the same values, so JSON
written from either is identical. Definitions of every quantity: :mod:`thermogear.dynamics.results.metrics` (linear) and
:mod:`thermogear.dynamics.backlash.backlash_metrics` (nonlinear). Sequences are tuples and per-region values read-only
mappings here (frozen), lists and dicts in the dict form.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import ProblemError

__all__ = ["ContactLoss", "EXTRA_KEYS", "LinearMetrics", "NonlinearContactLoss", "NonlinearMetrics", "typed_metrics"]

#: Keys a response's metrics dict may carry beside the typed metrics: a transient's bookkeeping (periods run, the
#: change over the last period, the largest |ẋ| from rest) and the damping ratio the simulation adds.
EXTRA_KEYS = frozenset({"transient_periods", "transient_last_period_change", "max_velocity_from_rest",
                        "damping_ratio"})


def _frozen(value: Any) -> Any:
    """A read-only form of a metric value: tuple for a list, read-only mapping for a dict."""
    if isinstance(value, list | tuple):
        return tuple(_frozen(item) for item in value)
    if isinstance(value, Mapping):
        return MappingProxyType({key: _frozen(item) for key, item in value.items()})
    return value


def _plain(value: Any) -> Any:
    """The dict form of a metric value: list for a tuple, dict for a mapping, as_dict for a nested result."""
    if dataclasses.is_dataclass(value):
        return value.as_dict()
    if isinstance(value, tuple):
        return [_plain(item) for item in value]
    if isinstance(value, Mapping):
        return {key: _plain(item) for key, item in value.items()}
    return value


class _MetricRecord:
    """from_dict / as_dict of a frozen metric dataclass whose field order is the dict's key order."""

    _nested: dict[str, type] = {}

    @classmethod
    def from_dict(cls, metrics: Mapping[str, Any]):
        """The typed metrics of a metrics dict; ProblemError naming the keys that are missing or unknown."""
        names = [item.name for item in dataclasses.fields(cls)]
        missing = [name for name in names if name not in metrics]
        unknown = [key for key in metrics if key not in names]
        if missing or unknown:
            raise ProblemError("metrics", f"missing {missing}, unknown {unknown}", f"the keys of {cls.__name__}",
                               "the typed metrics hold exactly the keys the solver writes")
        values = {}
        for name in names:
            nested = cls._nested.get(name)
            values[name] = nested.from_dict(metrics[name]) if nested is not None else _frozen(metrics[name])
        return cls(**values)

    def as_dict(self) -> dict[str, Any]:
        """The metrics dict: the keys in field order, lists for tuples, dicts for mappings and nested results."""
        return {item.name: _plain(getattr(self, item.name)) for item in dataclasses.fields(self)}

    def scalars(self) -> dict[str, Any]:
        """The single-number metrics (SI), nested results flattened as ``<field>_<name>``."""
        values: dict[str, Any] = {}
        for item in dataclasses.fields(self):
            value = getattr(self, item.name)
            if isinstance(value, _MetricRecord):
                values.update({f"{item.name}_{key}": inner for key, inner in value.scalars().items()})
            elif value is None or isinstance(value, bool | int | float | str):
                values[item.name] = value
        return values

    def to_dataframe(self):
        """The single-number metrics as one row (pandas)."""
        import pandas as pd  # noqa: PLC0415

        return pd.DataFrame([self.scalars()])

    def to_dataset(self):
        """The single-number metrics as scalar variables, the per-region ones along ``region`` (xarray)."""
        import xarray as xr  # noqa: PLC0415

        data = {name: ((), value) for name, value in self.scalars().items() if value is not None}
        regions = getattr(self, "equilibrium_per_region", None)
        if regions:
            names = list(regions)
            for field in ("equilibrium_per_region", "amplitude_per_region"):
                data[field] = ("region", [getattr(self, field).get(name, float("nan")) for name in names])
            return xr.Dataset(data, coords={"region": names})
        return xr.Dataset(data)


@dataclass(frozen=True)
class ContactLoss(_MetricRecord):
    """Runs of negative mesh force over the period of a linear response: start times [s], durations [s], their
    total [s], the minimum mesh force [N] and its ratio to the static load [-]."""

    detected: bool
    start_times: tuple[float, ...]
    durations: tuple[float, ...]
    total_duration: float
    min_force: float
    min_force_ratio: float


@dataclass(frozen=True)
class LinearMetrics(_MetricRecord):
    """Metrics of a linear periodic or transient response (the dict of ``compute_metrics``, in its key order).

    Loads [N] and their per-width views [N/mm]; ``kv`` [-] with the basis it was computed on (None where no pair
    load is available); static equilibrium, amplitude and largest deviation of the DTE per contact region [m];
    DTE mean, RMS and peak-to-peak [m]; largest |ẋ| [m/s]; natural and mesh frequencies [Hz] and their ratio;
    Floquet multiplier moduli (larger first); stability; contact loss; validity (stable and no contact loss).
    """

    static_load: float
    static_load_n_per_mm: float
    kv: float | None
    kv_basis: str
    max_pair_load: float | None
    max_pair_load_n_per_mm: float | None
    max_system_load: float
    max_system_load_n_per_mm: float
    max_system_load_ratio: float
    equilibrium_per_region: Mapping[str, float]
    amplitude_per_region: Mapping[str, float]
    deviation_per_region: Mapping[str, float]
    dte_mean: float
    dte_rms: float
    dte_peak_to_peak: float
    max_velocity: float
    natural_frequency_hz: float
    mesh_frequency_hz: float
    frequency_ratio: float
    floquet_multipliers_abs: tuple[float, ...]
    stable: bool
    contact_loss: ContactLoss
    valid: bool

    _nested = {"contact_loss": ContactLoss}

    # the views a nonlinear response gives, as a linear response has them: every pair in contact, one orbit
    @property
    def mesh(self) -> str:
        return "linear"

    @property
    def contact_loss_fraction(self) -> None:
        """None: the linear model has no free flight (its contact loss is a negative mesh force)."""
        return None

    @property
    def back_side_contact(self) -> bool:
        return False

    @property
    def response(self) -> str:
        return "periodic"

    @property
    def branch(self) -> str:
        return "unique"

    @property
    def coexisting_orbits(self) -> bool:
        return False


@dataclass(frozen=True)
class NonlinearContactLoss(_MetricRecord):
    """Contact loss of a backlash orbit: whether the flanks separate, and the fraction of time in free flight [-]."""

    detected: bool
    fraction: float


@dataclass(frozen=True)
class NonlinearMetrics(_MetricRecord):
    """Metrics of a nonlinear (backlash) response, in the key order of its dict.

    The orbit's kind (``response``: periodic, subharmonic, non-periodic), period count, convergence (residual,
    largest multiplier); static load [N]; contact-loss and back-contact fractions [-]; contact switches per period;
    mesh and pair forces [N] and ``kv``; DTE mean, RMS, peak-to-peak [m] and its mesh harmonics [m] over the base
    frequency [Hz]; the branch (unique, low, high) and whether another stable orbit coexists; then the views shared
    with :class:`LinearMetrics` (loads per width, per-region levels, frequencies, multipliers, stability, validity).
    """

    response: str
    period_count: int
    converged: bool
    residual: float
    largest_multiplier: float
    static_load: float
    contact_loss_fraction: float
    back_side_contact: bool
    back_contact_fraction: float
    switches_per_period: float
    max_mesh_force: float
    min_mesh_force: float
    max_pair_force: float
    kv: float
    max_mesh_force_ratio: float
    dte_mean: float
    dte_rms: float
    dte_peak_to_peak: float
    dte_mesh_harmonics: tuple[float, ...]
    dte_spectrum_base_frequency: float
    mesh: str
    branch: str
    coexisting_orbits: bool
    static_load_n_per_mm: float
    max_pair_load: float
    max_pair_load_n_per_mm: float
    max_system_load: float
    max_system_load_n_per_mm: float
    max_system_load_ratio: float
    max_velocity: float
    equilibrium_per_region: Mapping[str, float]
    amplitude_per_region: Mapping[str, float]
    natural_frequency_hz: float
    mesh_frequency_hz: float
    frequency_ratio: float
    floquet_multipliers_abs: tuple[float, ...]
    stable: bool
    contact_loss: NonlinearContactLoss
    valid: bool

    _nested = {"contact_loss": NonlinearContactLoss}


def typed_metrics(metrics: Mapping[str, Any]) -> LinearMetrics | NonlinearMetrics:
    """The typed metrics of a response's metrics dict (nonlinear where its ``mesh`` says so), the keys of
    ``EXTRA_KEYS`` left in the dict."""
    kind = NonlinearMetrics if mesh_law(metrics.get("mesh")).backlash else LinearMetrics
    return kind.from_dict({key: value for key, value in metrics.items() if key not in EXTRA_KEYS})
