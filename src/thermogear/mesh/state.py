"""The state of one mesh period at one operating point: what the dynamics solvers take from the mesh model."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.errors import CaseError
from thermogear.geometry.mesh_cycle import MeshCycle, MeshGrid


@dataclass(frozen=True, eq=False)
class MeshState:
    """One mesh period of a model at a pinion speed and normal load, on the mesh-cycle grid (totals over the face).

    ``pair_stiffness``, ``pair_damping`` [N/m, N·s/m] and ``pair_deviation`` [m] are (slots, n) on the grid
    intervals, 0 where a pair slot is out of contact; ``mesh_damping`` c(τ) (n,) under the case's rule;
    ``normal_load`` w [N]; ``mass`` me [kg]; ``backlash`` the normal backlash [m] or None. ``pair_engaged``
    (slots, n): the pairs that carry load under the static load (on the path, and where they have deviations, the
    static approach beyond them); ``static_transmission_error`` (n,) the loaded static transmission error [m]
    where the pairs have deviations (None otherwise: it is then w/k(τ)).
    """

    model: str
    speed_rpm: float
    normal_load: float
    mass: float
    grid: MeshGrid
    pair_stiffness: np.ndarray
    pair_damping: np.ndarray
    mesh_damping: np.ndarray
    pair_deviation: np.ndarray
    pair_engaged: np.ndarray
    static_transmission_error: np.ndarray | None
    backlash: float | None
    face_width: float
    mesh_frequency_hz: float

    @property
    def period(self) -> float:
        """Mesh period T_m [s]."""
        return float(self.grid.nodes[-1])

    @property
    def mesh_stiffness(self) -> np.ndarray:
        """k(τ) [N/m] (n,): the pairs that carry load, in parallel."""
        return MeshCycle.total(self.pair_stiffness, self.pair_engaged)

    @property
    def mean_mesh_stiffness(self) -> float:
        """Time mean of k(τ) over one period [N/m]."""
        return float(self.grid.time_average(self.mesh_stiffness))

    @property
    def damping_ratio(self) -> float:
        """Mean damping ratio ζ = c̄ / (2·sqrt(k̄·me)) [–] of the period: time means of c(τ) and k(τ) (the viscous
        damping ratio of the mean oscillator, Den Hartog 1956 §2.6)."""
        stiffness = self.mean_mesh_stiffness
        if not stiffness > 0.0:
            return float("nan")
        return float(self.grid.time_average(self.mesh_damping)) / (2.0 * float(np.sqrt(stiffness * self.mass)))

    @property
    def excitation(self) -> np.ndarray:
        """Σ_i k_i·e_i (n,) [N] over the pairs that carry load: the force the unloaded deviations add to the static
        load in me·ẍ + c·ẋ + Σ k_i·(x − e_i) = w."""
        return MeshCycle.total(self.pair_stiffness * self.pair_deviation, self.pair_engaged)

    def problem(self) -> MeshDynamicsProblem:
        """The linear mesh-dynamics problem me·ẍ + c(τ)ẋ + k(τ)(x − e(τ)) = w over this period (the pairs that
        carry the static load; where the dynamic response would unload one, the nonlinear model is the one)."""
        excitation = self.excitation
        force = self.normal_load + excitation if np.any(excitation) else self.normal_load
        engaged = np.where(self.pair_engaged, self.pair_stiffness, 0.0)
        deviation = np.where(self.pair_engaged, self.pair_deviation, 0.0) if np.any(excitation) else None
        return MeshDynamicsProblem(mass=self.mass, nodes=self.grid.nodes, stiffness=self.mesh_stiffness,
                                   damping=self.mesh_damping, force=force, contact_count=self.pair_engaged.sum(axis=0),
                                   pair_stiffness=engaged, face_width=self.face_width, pair_deviation=deviation)

    def backlash_problem(self, damping_in_flight: str = "always") -> BacklashMeshProblem:
        """The nonlinear mesh-dynamics problem over this period: every pair on the path acts only while it touches,
        k_i⟨x − e_i⟩₊ on the driving flanks and −k_i⟨−x − j − e_i⟩₊ across the normal backlash j on the back flanks.

        The back flanks of the same teeth are taken with the driving flanks' stiffness and deviation at the same
        mesh position (symmetric teeth whose two lines of action carry the same mesh-stiffness cycle; the phase
        between the two cycles is neglected, which matters only where the teeth strike the back flanks).
        """
        if self.backlash is None:
            raise CaseError("dynamics.mesh", "nonlinear", "'linear', or a case whose backlash is known",
                            "the nonlinear mesh needs the normal backlash")
        stiffness = np.where(self.grid.in_contact, self.pair_stiffness, 0.0)
        deviation = np.where(self.grid.in_contact, self.pair_deviation, 0.0)
        return BacklashMeshProblem(mass=self.mass, nodes=self.grid.nodes, pair_stiffness=stiffness,
                                   pair_deviation=deviation, back_pair_stiffness=stiffness,
                                   back_pair_deviation=deviation, backlash=self.backlash, damping=self.mesh_damping,
                                   force=self.normal_load, damping_mode=damping_in_flight, face_width=self.face_width)


def mesh_state_from_arrays(phase, stiffness, *, speed_rpm: float, normal_load: float, mass: float | None = None,
                           damping=None, deviation=None, period: float | None = None,
                           pinion_teeth: int | None = None, inertias: tuple[float, float] | None = None,
                           base_radii: tuple[float, float] | None = None, backlash: float | None = None,
                           face_width: float = 1.0, model: str = "table") -> MeshState:
    """A :class:`MeshState` from a user's arrays over one mesh period: a k(τ) from a table, a measurement, another
    tool or a finite-element contact analysis, for every solver that takes a mesh state (the 1-DOF periodic,
    transient and backlash solvers through :meth:`MeshState.problem` / :meth:`MeshState.backlash_problem`, and the
    drivetrain's ``drivetrain_periodic_response``, ``drivetrain_backlash_response``, …).

    ``phase`` τ_i [-] (N,): the start of each interval as a fraction of the mesh period, τ_0 = 0, strictly
    increasing, below 1; the values hold on [τ_i, τ_{i+1}) (τ_N = 1), piecewise constant as the solvers take them.
    ``stiffness`` k_i [N/m] (N,) > 0: the total mesh stiffness; ``damping`` c_i [N·s/m] (N,) >= 0 (default 0);
    ``deviation`` e_i [m] (N,): the unloaded deviation of the mesh (positive: material missing; it excites the
    mesh through k·e, default none). ``speed_rpm`` [rpm] the pinion speed (the drivetrain's gyroscopic terms) and
    the period T_m [s]: ``period`` or ``pinion_teeth`` z1 (T_m = 60/(z1·n1)). ``normal_load`` w [N] > 0 the static
    normal load; ``mass`` me [kg] the equivalent mass, or ``inertias`` (J1, J2) [kg·m²] with ``base_radii``
    (r_b1, r_b2) [m], me = J1·J2/(J1·r_b2² + J2·r_b1²) (Luo & Li Eq. 5). ``backlash`` [m] the normal backlash (the
    nonlinear mesh needs it), ``face_width`` [m] (loads per unit width in the metrics).

    The table is one pair slot carrying the whole mesh: the pair metrics (Kv as max pair load over w) are those of
    the total mesh force. Bad input raises :class:`~thermogear.errors.CaseError` naming the array, the value, the
    allowed range and the reason.
    """
    phase = _finite_vector("phase", phase)
    count = phase.size
    if count < 1 or phase[0] != 0.0 or np.any(np.diff(phase) <= 0.0) or phase[-1] >= 1.0:
        raise CaseError("phase", _shown(phase), "0 first, strictly increasing, < 1",
                        "the interval starts of one mesh period as fractions of it (the last interval ends at 1)")
    stiffness = _finite_vector("stiffness", stiffness, count)
    if np.any(stiffness <= 0.0):
        raise CaseError("stiffness", float(stiffness.min()), "> 0 N/m", "a mesh in contact has positive stiffness")
    damping = np.zeros(count) if damping is None else _finite_vector("damping", damping, count)
    if np.any(damping < 0.0):
        raise CaseError("damping", float(damping.min()), ">= 0 N·s/m", "a damper must not inject energy")
    deviation = np.zeros(count) if deviation is None else _finite_vector("deviation", deviation, count)
    speed = _positive("speed_rpm", speed_rpm, "rpm", "the pinion speed")
    if (period is None) == (pinion_teeth is None):
        raise CaseError("period", period, "one of period [s] or pinion_teeth", "the mesh period is given once")
    if period is None:
        if int(pinion_teeth) != pinion_teeth or pinion_teeth < 1:
            raise CaseError("pinion_teeth", pinion_teeth, "an integer >= 1", "T_m = 60/(z1·n1)")
        period = 60.0 / (int(pinion_teeth) * speed)
    period = _positive("period", period, "s", "the mesh period")
    load = _positive("normal_load", normal_load, "N", "the static normal load")
    if mass is None:
        if inertias is None or base_radii is None:
            raise CaseError("mass", None, "mass [kg], or inertias (J1, J2) with base_radii (r_b1, r_b2)",
                            "the equivalent mass of the mesh")
        (j1, j2) = (_positive("inertias", value, "kg·m²", "the gears' polar inertias") for value in inertias)
        (r1, r2) = (_positive("base_radii", value, "m", "the base radii") for value in base_radii)
        mass = j1 * j2 / (j1 * r2**2 + j2 * r1**2)
    mass = _positive("mass", mass, "kg", "the equivalent mass")
    if backlash is not None:
        backlash = _positive("backlash", backlash, "m", "the normal backlash")
    nodes = np.append(phase, 1.0) * period
    engaged = np.ones((1, count), dtype=bool)
    grid = MeshGrid(nodes=nodes, midpoints=0.5 * (nodes[1:] + nodes[:-1]), roll=np.zeros((1, count)),
                    in_contact=engaged, contact_count=np.ones(count, dtype=int))
    static = load / stiffness + deviation if np.any(deviation) else None
    return MeshState(model=model, speed_rpm=speed, normal_load=load, mass=mass, grid=grid,
                     pair_stiffness=stiffness[None].copy(), pair_damping=damping[None].copy(),
                     mesh_damping=damping.copy(), pair_deviation=deviation[None].copy(), pair_engaged=engaged,
                     static_transmission_error=static, backlash=backlash,
                     face_width=_positive("face_width", face_width, "m", "loads per unit face width"),
                     mesh_frequency_hz=1.0 / period)


def _shown(values: np.ndarray) -> list[float]:
    return [float(value) for value in values[:6]]


def _finite_vector(name: str, values, count: int | None = None) -> np.ndarray:
    array = np.asarray(values, dtype=float)
    if array.ndim != 1 or (count is not None and array.size != count):
        raise CaseError(name, f"array of shape {array.shape}", f"shape ({count if count is not None else 'N'},)",
                        "one value per interval of the mesh period")
    if not np.all(np.isfinite(array)):
        raise CaseError(name, "non-finite entries", "finite numbers", "NaN or infinity has no meaning here")
    return array


def _positive(name: str, value, unit: str, reason: str) -> float:
    number = float(value)
    if not math.isfinite(number) or number <= 0.0:
        raise CaseError(name, value, f"> 0 {unit}, finite", reason)
    return number


__all__ = ["MeshState", "mesh_state_from_arrays"]
