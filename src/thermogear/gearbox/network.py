"""A lumped thermal network: steady state by a nonlinear solve and transients as a stiff ODE. Knows no gears.

Nodes i = 0..n−1 with heat capacities C_i [J/K] exchange heat through conductances G_ij(T) = G_ji(T) [W/K] and
with one boundary (the ambient) at T_a(t) through g_i(T) [W/K]; sources P_i(T, t) [W]:

    C_i·dT_i/dt = Σ_j G_ij·(T_j − T_i) + g_i·(T_a − T_i) + P_i                                (1)

(the standard lumped-capacitance network, e.g. Incropera et al., Fundamentals of Heat and Mass Transfer, §5.2 and
§3.1 for thermal resistances; Changenet, Oviedo-Marlot & Velex (2006), J. Mech. Des. 128(3):618, for gearboxes).
Summing (1) over the nodes, the internal exchanges cancel because G is symmetric, so

    d/dt Σ C_i T_i = Σ P_i − Q_out,   Q_out = Σ g_i·(T_i − T_a)                               (2)

which gives the checks: at steady state Σ P = Q_out, and over a transient ∫ΣP dt = Δ(Σ C T) + ∫Q_out dt.

The steady state solves (1) with dT/dt = 0 by :func:`scipy.optimize.root` (Powell hybrid, finite-difference
Jacobian, from the linear solution with G, g, P frozen at the initial temperatures); where it fails or ends above
``temperature_limit`` :class:`NoSteadyStateError` says so. Whether a steady state is stable is decided by the
eigenvalues of C⁻¹J (:func:`stability_eigenvalues`), and :func:`continue_steady_states` follows the stable branch
in a parameter to where it ends (a fold: thermal runaway beyond it). Transients integrate (1) with
:func:`scipy.optimize.solve_ivp` (Radau or BDF: the node time constants span decades) with two extra states, the
integrals of ΣP and Q_out, for identity (2). Temperatures are in the caller's unit (the gearbox uses °C).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from thermogear.errors import ModelLimitError, ProblemError

Conductances = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]  # T -> (G (n, n) symmetric, g (n,))
Sources = Callable[[np.ndarray, float], np.ndarray]  # (T, t) -> P (n,)


class NoSteadyStateError(ModelLimitError):
    """The network has no steady state: the sources grow with temperature faster than the cooling (runaway),
    or a node with a source has no path to the boundary."""


@dataclass(frozen=True, eq=False)
class ThermalNetwork:
    """Capacities C [J/K] (n,), conductances (function of T: symmetric G [W/K] with any diagonal, ignored, and
    boundary conductances g [W/K]), sources P(T, t) [W] and the boundary temperature T_a(t)."""

    capacities: np.ndarray
    conductances: Conductances
    sources: Sources
    boundary: Callable[[float], float]

    def __post_init__(self) -> None:
        capacities = np.asarray(self.capacities, dtype=float)
        if capacities.ndim != 1 or capacities.size == 0 or not np.all(np.isfinite(capacities)) or np.any(
                capacities <= 0.0):
            raise ProblemError("capacities", capacities.tolist(), "a 1-D array of finite values > 0 J/K",
                               "every node stores heat")
        object.__setattr__(self, "capacities", capacities)

    @property
    def size(self) -> int:
        return int(self.capacities.size)

    def raw_exchange(self, temperatures: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(G with a zero diagonal, g) at temperatures, unchecked (the integrator's inner loop; :meth:`exchange`
        checks them once at the start of every solve)."""
        internal, boundary = self.conductances(temperatures)
        internal = np.array(internal, dtype=float)
        np.fill_diagonal(internal, 0.0)
        return internal, np.asarray(boundary, dtype=float)

    def exchange(self, temperatures: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(G, g) at temperatures, checked: symmetric, finite, non-negative; G's diagonal set to zero."""
        internal, boundary = self.conductances(temperatures)
        internal = np.array(internal, dtype=float)
        boundary = np.asarray(boundary, dtype=float)
        np.fill_diagonal(internal, 0.0)
        if internal.shape != (self.size, self.size) or boundary.shape != (self.size,):
            raise ProblemError("conductances", (internal.shape, boundary.shape), f"({self.size}, {self.size}) and "
                               f"({self.size},)", "one row per node")
        if not (np.all(np.isfinite(internal)) and np.all(np.isfinite(boundary))) or np.any(internal < 0.0) or np.any(
                boundary < 0.0):
            raise ProblemError("conductances", "negative or not finite", ">= 0 W/K", "heat flows from hot to cold")
        if not np.allclose(internal, internal.T, rtol=1e-12, atol=0.0):
            raise ProblemError("conductances", "not symmetric", "G_ij = G_ji", "a conductance joins two nodes")
        return internal, boundary

    def heat_balance(self, temperatures, time: float = 0.0) -> np.ndarray:
        """Right side of (1), Σ_j G_ij(T_j − T_i) + g_i(T_a − T_i) + P_i [W] (n,)."""
        temperatures = np.asarray(temperatures, dtype=float)
        internal, boundary = self.raw_exchange(temperatures)
        flow = internal @ temperatures - internal.sum(axis=1) * temperatures
        return flow + boundary * (self.boundary(time) - temperatures) + np.asarray(
            self.sources(temperatures, time), dtype=float)

    def heat_out(self, temperatures, time: float = 0.0) -> float:
        """Q_out = Σ g_i(T_i − T_a) [W]."""
        temperatures = np.asarray(temperatures, dtype=float)
        return float(self.exchange(temperatures)[1] @ (temperatures - self.boundary(time)))

    def linear_matrix(self, temperatures) -> np.ndarray:
        """K = G − diag(Σ_j G_ij + g_i) [W/K] with G, g frozen at the temperatures (dT/dt = C⁻¹(K T + …))."""
        internal, boundary = self.exchange(np.asarray(temperatures, dtype=float))
        return internal - np.diag(internal.sum(axis=1) + boundary)

    def time_constants(self, temperatures) -> np.ndarray:
        """τ = −1/λ of the eigenvalues λ of C⁻¹K (frozen conductances), ascending [s]; inf for a node with no
        path to the boundary."""
        matrix = self.linear_matrix(temperatures) / self.capacities[:, None]
        eigenvalues = np.sort(np.real(np.linalg.eigvals(matrix)))
        with np.errstate(divide="ignore"):
            return np.sort(np.where(eigenvalues < 0.0, -1.0 / np.minimum(eigenvalues, -0.0), np.inf))


@dataclass(frozen=True)
class SteadyState:
    """Steady temperatures (n,), sources P (n,) [W], heat to the boundary [W], the relative energy residual
    |ΣP − Q_out|/ΣP and the time constants of the linearised network [s]."""

    temperatures: np.ndarray
    sources: np.ndarray
    heat_out: float
    energy_residual: float
    time_constants: np.ndarray
    iterations: int


def solve_steady_state(network: ThermalNetwork, initial, time: float = 0.0, temperature_limit: float = 1000.0,
                       tolerance: float = 1e-12) -> SteadyState:
    """Steady state of (1) at time ``time`` (module docstring); raises :class:`NoSteadyStateError` where none
    exists below ``temperature_limit``."""
    from scipy.optimize import root

    start = np.asarray(initial, dtype=float)
    ambient = network.boundary(time)
    matrix = network.linear_matrix(start)  # checks the conductances once
    internal, boundary = network.exchange(start)
    right = -(np.asarray(network.sources(start, time), dtype=float) + boundary * ambient)
    try:
        guess = np.linalg.solve(matrix, right)
    except np.linalg.LinAlgError as error:
        raise NoSteadyStateError("thermal network: a node has no conductive path to the ambient, so it has no "
                                 "steady state (an adiabatic node with a source heats without bound)") from error
    if not np.all(np.isfinite(guess)) or np.max(guess) > temperature_limit:
        guess = np.minimum(np.where(np.isfinite(guess), guess, start), temperature_limit)
    scale = max(float(np.sum(np.abs(network.sources(guess, time)))), 1e-300)
    if scale < 1e-6 * float(np.sum(internal) + np.sum(boundary)):
        # vanishing losses (a crawl speed): the balance is measured against 1 K across every conductance, else
        # rounding in G·T would read as an enormous relative residual and the ambient as "no steady state"
        scale = float(np.sum(internal) + np.sum(boundary))
    solution = root(lambda temperatures: network.heat_balance(temperatures, time) / scale, guess, method="hybr",
                    options={"xtol": tolerance})
    temperatures = np.asarray(solution.x, dtype=float)
    balance = None
    if np.all(np.isfinite(temperatures)) and np.max(temperatures) <= temperature_limit:
        temperatures, balance = _polish(lambda values: network.heat_balance(values, time) / scale, temperatures)
    # accepted on the residual itself (hybr may report slow progress once it sits at rounding level): the energy
    # balance ΣP − Q_out is the sum of the node residuals, so 1e-10 per node keeps it within 1e-9 of ΣP
    if (balance is None or np.max(np.abs(balance)) > 1e-10
            or np.max(temperatures) > temperature_limit):
        raise NoSteadyStateError(
            "thermal network: no steady state below " f"{temperature_limit:g} (the losses grow with temperature faster "
            "than the cooling: thermal runaway; the solver says: " f"{solution.message.strip()})")
    return steady_state_at(network, temperatures, time, int(solution.nfev))


def steady_state_at(network: ThermalNetwork, temperatures, time: float = 0.0, iterations: int = 0) -> SteadyState:
    """The :class:`SteadyState` record of solved steady ``temperatures``: sources, heat out, relative energy
    residual, time constants (conductances checked there)."""
    temperatures = np.asarray(temperatures, dtype=float)
    network.exchange(temperatures)  # and at the solution
    sources = np.asarray(network.sources(temperatures, time), dtype=float)
    out = network.heat_out(temperatures, time)
    total = float(np.sum(sources))
    residual = abs(total - out) / abs(total) if total != 0.0 else abs(out)
    return SteadyState(temperatures, sources, out, residual, network.time_constants(temperatures), iterations)


def _polish(residual, values: np.ndarray, iterations: int = 6) -> tuple[np.ndarray, np.ndarray]:
    """A few Newton steps with a forward-difference Jacobian, kept only while they lower the residual."""
    current = residual(values)
    for _ in range(iterations):
        if np.max(np.abs(current)) < 1e-14:
            break
        step = 1e-7 * np.maximum(np.abs(values), 1.0)
        jacobian = np.column_stack([(residual(values + step[i] * np.eye(values.size)[i]) - current) / step[i]
                                    for i in range(values.size)])
        try:
            trial = values - np.linalg.solve(jacobian, current)
        except np.linalg.LinAlgError:
            break
        trial_residual = residual(trial)
        if not (np.all(np.isfinite(trial_residual)) and np.max(np.abs(trial_residual)) < np.max(np.abs(current))):
            break
        values, current = trial, trial_residual
    return values, current


def heat_balance_jacobian(network: ThermalNetwork, temperatures, time: float = 0.0) -> np.ndarray:
    """∂(right side of (1))/∂T [W/K] (n, n) by central differences (steps 1e-4·max(|T|, 1)): the linearisation
    that decides whether a steady state is stable."""
    values = np.asarray(temperatures, dtype=float)
    columns = []
    for index in range(values.size):
        step = 1e-4 * max(abs(values[index]), 1.0)
        shift = np.zeros_like(values)
        shift[index] = step
        columns.append((network.heat_balance(values + shift, time) - network.heat_balance(values - shift, time))
                       / (2.0 * step))
    return np.column_stack(columns)


def stability_eigenvalues(network: ThermalNetwork, temperatures, time: float = 0.0) -> np.ndarray:
    """Eigenvalues [1/s] of C⁻¹·J, J the Jacobian of the heat balance at ``temperatures`` (sources and
    conductances following the temperatures), sorted by real part, largest last. A steady state is (linearly)
    stable when every real part is negative: a small disturbance then decays; one eigenvalue crossing zero along
    a branch marks a fold, where the stable branch ends (thermal runaway beyond it)."""
    matrix = heat_balance_jacobian(network, temperatures, time) / network.capacities[:, None]
    eigenvalues = np.linalg.eigvals(matrix)
    return eigenvalues[np.argsort(np.real(eigenvalues))]


def corrected_steady_state(network: ThermalNetwork, guess, time: float = 0.0,
                           bounds: tuple[float, float] = (-np.inf, np.inf)) -> np.ndarray | None:
    """A steady state of (1) by Newton-type iteration (Powell hybrid, then polished) from ``guess``, or None where
    it does not converge to 1e-10 of the scale ΣG·1 K + Σ|P| per node or leaves ``bounds``: the corrector of a
    continuation (:func:`continue_steady_states`)."""
    from scipy.optimize import root

    start = np.asarray(guess, dtype=float)
    internal, boundary = network.raw_exchange(start)
    scale = max(float(np.sum(np.abs(network.sources(start, time)))) + float(np.sum(internal) + np.sum(boundary)),
                1e-300)

    def residual(values):
        return network.heat_balance(values, time) / scale

    solution = root(residual, start, method="hybr", options={"xtol": 1e-12})
    values = np.asarray(solution.x, dtype=float)
    if not (np.all(np.isfinite(values)) and bounds[0] <= np.min(values) and np.max(values) <= bounds[1]):
        return None
    values, balance = _polish(residual, values)
    if not (np.all(np.isfinite(balance)) and np.max(np.abs(balance)) <= 1e-10):
        return None
    return values


@dataclass(frozen=True)
class Fold:
    """Where a branch of stable steady states ends in a continuation: the last stable parameter reached and its
    temperatures (n,), the largest real part of the stability eigenvalues there [1/s] (near 0 at a fold) and
    whether the branch reached the target parameter (then no fold lies before it)."""

    parameter: float
    temperatures: np.ndarray
    largest_eigenvalue: float
    reached: bool


def continue_steady_states(network_at: Callable[[float], ThermalNetwork], start: float, target: float,
                           initial, bounds: tuple[float, float] = (-np.inf, np.inf), first_step: float = 0.1,
                           smallest_step: float = 1e-4) -> Fold:
    """Follow the stable steady states of ``network_at(p)`` from ``p = start`` (its state found from ``initial``)
    towards ``target`` (natural-parameter continuation: a secant predictor, :func:`corrected_steady_state` as
    corrector, a step accepted only where the corrected state is stable and near the prediction, halved otherwise).
    Where the step falls below ``smallest_step``·|target − start| the stable branch has ended: a fold (saddle-node),
    beyond which no nearby steady state exists, lies within that step. Returns the :class:`Fold` (``reached``
    True where the target was reached on the stable branch)."""
    span = float(target) - float(start)
    parameter = float(start)
    current = corrected_steady_state(network_at(parameter), initial, bounds=bounds)
    if current is None or np.max(np.real(stability_eigenvalues(network_at(parameter), current))) >= 0.0:
        values = np.asarray(initial, dtype=float) if current is None else current
        return Fold(parameter, values, float("nan") if current is None else float(
            np.max(np.real(stability_eigenvalues(network_at(parameter), current)))), False)
    previous: tuple[float, np.ndarray] | None = None
    step = first_step
    while True:
        if abs(parameter - start - span) <= 1e-15 * max(abs(span), 1.0):
            eigenvalue = float(np.max(np.real(stability_eigenvalues(network_at(parameter), current))))
            return Fold(parameter, current, eigenvalue, True)
        fraction = (parameter - start) / span if span else 1.0
        trial = start + span * min(1.0, fraction + step)
        predictor = current if previous is None else current + (current - previous[1]) * (
            (trial - parameter) / (parameter - previous[0]))
        network = network_at(trial)
        corrected = corrected_steady_state(network, predictor, bounds=bounds)
        accepted = False
        if corrected is not None and np.max(np.abs(corrected - predictor)) <= 25.0 + 0.5 * np.max(
                np.abs(predictor - current)):
            accepted = float(np.max(np.real(stability_eigenvalues(network, corrected)))) < 0.0
        if accepted:
            previous, parameter, current = (parameter, current), trial, corrected
            step = min(2.0 * step, first_step)
            continue
        step *= 0.5
        if step < smallest_step:
            eigenvalue = float(np.max(np.real(stability_eigenvalues(network_at(parameter), current))))
            return Fold(parameter, current, eigenvalue, False)


@dataclass(frozen=True)
class Transient:
    """A transient of the network: times (m,) [s], temperatures (n, m), the integrals of ΣP and Q_out [J] (m,)."""

    times: np.ndarray
    temperatures: np.ndarray
    energy_in: np.ndarray
    energy_out: np.ndarray
    capacities: np.ndarray

    @property
    def stored(self) -> np.ndarray:
        """Σ C_i (T_i(t) − T_i(0)) [J] (m,)."""
        return self.capacities @ (self.temperatures - self.temperatures[:, :1])

    @property
    def energy_residual(self) -> float:
        """max |∫ΣP − ΔΣCT − ∫Q_out| / max(∫ΣP) over the output times (identity (2)) [–]."""
        scale = max(float(np.max(np.abs(self.energy_in))), 1e-300)
        return float(np.max(np.abs(self.energy_in - self.stored - self.energy_out)) / scale)


def integrate_transient(network: ThermalNetwork, initial, times, method: str = "Radau", rtol: float = 1e-6,
                        atol: float = 1e-6) -> Transient:
    """Integrate (1) from ``initial`` at times[0] and report at ``times`` [s] (increasing). ``method``: an
    implicit solve_ivp method (Radau or BDF) for the stiff network; ``rtol``, ``atol`` [K and J] its tolerances
    (the energy integrals are states too, so identity (2) holds to about rtol)."""
    from scipy.integrate import solve_ivp

    times = np.asarray(times, dtype=float)
    if times.ndim != 1 or times.size < 2 or np.any(np.diff(times) <= 0.0):
        raise ProblemError("times", times.size, "an increasing array of at least 2 times", "output times")
    start = np.asarray(initial, dtype=float)
    if start.shape != (network.size,) or not np.all(np.isfinite(start)):
        raise ProblemError("initial", start.tolist(), f"{network.size} finite temperatures", "one per node")
    count = network.size
    network.exchange(start)  # checked once; the inner loop uses the raw conductances

    def rate(time, state):
        temperatures = state[:count]
        power = np.asarray(network.sources(temperatures, time), dtype=float)
        internal, boundary = network.raw_exchange(temperatures)
        ambient = network.boundary(time)
        flow = internal @ temperatures - internal.sum(axis=1) * temperatures + boundary * (ambient - temperatures)
        return np.concatenate([(flow + power) / network.capacities,
                               [power.sum(), float(boundary @ (temperatures - ambient))]])

    solution = solve_ivp(rate, (times[0], times[-1]), np.concatenate([start, [0.0, 0.0]]), method=method,
                         t_eval=times, rtol=rtol, atol=atol)
    if not solution.success:
        raise ModelLimitError(f"thermal network transient failed: {solution.message}")
    return Transient(times, solution.y[:count], solution.y[count], solution.y[count + 1], network.capacities)
