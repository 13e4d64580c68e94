"""Interference (Campbell) diagram of a geared drivetrain: the modal frequencies against the pinion speed, which the
gyroscopic terms make move, with the mesh-harmonic lines f = j·z₁·n/60 and their crossings.

A crossing of harmonic j with mode i is a speed where the mesh excitation meets that mode; the modes that store a
large share of their strain energy in the mesh are the tooth-critical ones, whose crossings are the critical speeds
of the gear (Velex & Berthe, "Dynamic tooth loads on geared train", Proc. ASME Int. Power Transmission and Gearing
Conf., Chicago 1989, pp. 447–454).

How it is solved. The speed enters only through Ω·G, so the modes at every speed are sought in one basis fixed at
rest: the undamped modes Φ of the drivetrain (rigid motions removed, mean mesh stiffness) up to a cut-off, which
make M diagonal (Φᵀ M Φ = I) and K diagonal (Φᵀ K Φ = Λ). On it the damped, spinning problem
η̈ + Φᵀ(C + Ω G)Φ η̇ + Λ η = 0 is small (a Rayleigh–Ritz projection: Friswell et al., Dynamics of Rotating Machines,
CUP 2010, §7.2; Meirovitch, Computational Methods in Structural Dynamics, 1980, ch. 7), solved by one eigen-solve
of its state matrix per speed. The modes left out couple to the kept ones only through C and Ω·G. Bearing dampers
act at points, so that coupling reaches far up the spectrum and the plain modal truncation converges only as
1/cut-off (2.4 % on the FZG rig set's most damped mode at three times its frequency). The basis therefore also
holds the quasi-static response of the left-out modes to the damping and gyroscopic forces of the modes drawn,
K⁻¹·C·φ_i and K⁻¹·G·φ_i made M-orthogonal to the kept modes (modal truncation augmentation: Dickens, Nakagawa &
Wittbrodt, "A critique of mode acceleration and modal truncation augmentation methods for modal response
analysis", Computers & Structures 62 (1997) 985–998), and the whole basis is re-diagonalised (Rayleigh–Ritz). The
error left is that of the left-out modes' dynamics, second order over the frequency gap (the tests state it against
the full solve). A cut-off of ``math.inf`` keeps every mode: the projection is then a change of coordinates and the
result is the full solve's.

Modes are followed from speed to speed by their shapes (the modal assurance criterion, MAC = |η_aᴴη_b|² /
(‖η_a‖²‖η_b‖²), mass-weighted since M = I in the basis, matched one to one by the assignment that maximises the
sum), so a forward and a backward whirl mode keep their names where their frequencies cross. Each crossing is found
by Brent's method on h(n) = f_i(n) − j·z₁·n/60, the mode at a trial speed being the one whose shape is closest to
the mode's at the bracket's two ends. Frequencies are |λ|/2π of the damped system.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain, Drivetrain
from thermogear.drivetrain.backlash_response import one_blas_thread
from thermogear.drivetrain.modes import mode_labels
from thermogear.dynamics.modes.modal import undamped_modes
from thermogear.dynamics.modes.rigid_body import rigid_body_reduction
from thermogear.errors import CaseError

__all__ = ["BASIS_FACTOR", "Crossing", "CampbellDiagram", "as_assembled", "campbell_diagram"]

#: Default cut-off of the basis: this many times the frequency at rest of the highest mode drawn [-]. With the
#: quasi-static vectors of the damping and gyroscopic forces added (module docstring) the kept frequencies converge
#: fast in the cut-off: on the FZG rig set 6.5e-5, 1.2e-5 and 7.8e-7 relative at factors 1, 1.5 and 3 up to
#: 15 000 rpm; the tests measure it against the full solve.
BASIS_FACTOR = 1.5
#: Extra modes beyond those drawn that each speed's eigen-solve offers to the shape matching (a mode may move
#: above one that was higher at rest).
_SPARE_MODES = 6


def as_assembled(drivetrain: Drivetrain | AssembledDrivetrain) -> AssembledDrivetrain:
    """The assembled matrices of what a case or the Python API gives: a :class:`Drivetrain` (assembled here) or an
    :class:`AssembledDrivetrain` (as is)."""
    if isinstance(drivetrain, AssembledDrivetrain):
        return drivetrain
    if isinstance(drivetrain, Drivetrain):
        return drivetrain.assemble()
    raise CaseError("drivetrain", type(drivetrain).__name__, "a Drivetrain or an AssembledDrivetrain",
                    "the diagram is solved on the drivetrain's matrices (of a case's CaseDrivetrain: give "
                    "its .drivetrains[model])")


@dataclass(frozen=True)
class Crossing:
    """Harmonic ``harmonic`` j of the mesh frequency meets mode ``mode`` (its column in the diagram, numbered by
    frequency at the lowest speed) at ``speed_rpm`` [rpm] and ``frequency_hz`` [Hz]; the mode's ``mesh_share`` of
    strain energy there [-] and its ``label``."""

    harmonic: int
    mode: int
    speed_rpm: float
    frequency_hz: float
    mesh_share: float
    label: str


@dataclass(frozen=True, eq=False)
class CampbellDiagram:
    """``speeds_rpm`` (S,) of the pinion; ``frequencies_hz`` (S, modes) natural frequencies of each mode followed
    by its shape; ``mesh_shares`` (S, modes) [-]; ``labels`` per mode at the lowest speed; ``teeth`` z₁ of the
    pinion; ``harmonics``; the ``crossings`` found; ``basis_size`` the modes of the basis the speeds were solved
    on."""

    speeds_rpm: np.ndarray
    frequencies_hz: np.ndarray
    mesh_shares: np.ndarray
    labels: tuple[str, ...]
    teeth: int
    harmonics: tuple[int, ...]
    crossings: tuple[Crossing, ...]
    basis_size: int = 0

    def tooth_critical(self, minimum_share: float = 0.1) -> tuple[Crossing, ...]:
        """The crossings whose mode stores at least ``minimum_share`` of its strain energy in the mesh."""
        return tuple(crossing for crossing in self.crossings if crossing.mesh_share >= minimum_share)

    def plot_campbell(self, ax=None, label_share: float = 0.01):
        """Draw the diagram on ``ax`` (a new figure if None) and return the figure: each mode a line coloured by
        its mesh share of strain energy at each speed (colour bar), the mesh harmonics as dashed lines labelled
        "j× mesh", every crossing marked (one marker per crossing, in the artist with gid "crossings"), and
        those of modes with a mesh share ≥ ``label_share`` numbered in order of speed, the legend saying for each
        its harmonic, speed, frequency, mode and mesh share."""
        from thermogear.drivetrain.plots import plot_campbell

        return plot_campbell(self, ax, label_share)


class _ReducedSpinningModes:
    """The modes of the drivetrain at any speed on the undamped basis of rest (module docstring)."""

    def __init__(self, assembled: AssembledDrivetrain, mesh_stiffness: float | None, basis_cutoff_hz: float | None,
                 mode_count: int) -> None:
        from scipy.linalg import eigh, solve

        stiffness = None if mesh_stiffness is None else np.array([mesh_stiffness])
        reduction = rigid_body_reduction(assembled.mass, assembled.connection_stiffness(stiffness),
                                         assembled.rigid_candidates())
        mass_q, stiffness_q = reduction.project(assembled.mass), reduction.project(assembled.stiffness(stiffness))
        modes = undamped_modes(mass_q, stiffness_q)
        frequencies = modes.angular_frequencies
        wanted = min(mode_count, frequencies.size)
        cutoff = (BASIS_FACTOR * frequencies[wanted - 1] if basis_cutoff_hz is None
                  else 2.0 * math.pi * basis_cutoff_hz)
        kept = max(int(np.searchsorted(frequencies, cutoff, side="right")), min(wanted + _SPARE_MODES,
                                                                                 frequencies.size))
        shapes = modes.shapes[:, :kept]
        # the quasi-static response of the modes left out to the damping and gyroscopic forces of the modes drawn
        # (modal truncation augmentation): K⁻¹·(C, G)·φ_i, made M-orthogonal to the kept modes
        loads = np.hstack([reduction.project(assembled.damping(0.0)) @ modes.shapes[:, :wanted],
                           reduction.project(assembled.gyroscopic) @ modes.shapes[:, :wanted]])
        loads = loads[:, np.abs(loads).max(axis=0, initial=0.0) > 0.0]  # no damping or spin: no such vectors
        static = solve(stiffness_q, loads, assume_a="pos") if loads.shape[1] else loads
        static /= np.sqrt(np.einsum("ij,ij->j", static, mass_q @ static))  # unit M-norm before the projection
        static -= shapes @ (shapes.T @ (mass_q @ static))
        gram_values, gram_vectors = eigh(static.T @ mass_q @ static)
        independent = gram_values > 1e-10  # what is left of a unit vector beyond the kept modes' span, or rounding
        static = static @ (gram_vectors[:, independent] / np.sqrt(gram_values[independent]))
        ritz = np.hstack([shapes, static])  # M-orthonormal columns
        values, vectors = eigh(ritz.T @ stiffness_q @ ritz)
        self.basis = reduction.expand(ritz @ vectors)  # (DOFs, m), Vᵀ M V = I
        self.stiffness = np.clip(values, 0.0, None)  # Vᵀ K V = Λ
        self.damping = self.basis.T @ assembled.damping(0.0) @ self.basis
        self.gyroscopic = self.basis.T @ assembled.gyroscopic @ self.basis
        mesh = assembled.drivetrain.meshes[0]
        self.mesh_vector = self.basis.T @ assembled.mesh_vectors[0]
        self.mesh_stiffness = mesh.stiffness if mesh_stiffness is None else float(mesh_stiffness)
        self.candidates = min(wanted + _SPARE_MODES, self.stiffness.size)
        self.count = wanted

    @property
    def size(self) -> int:
        return self.stiffness.size

    def solve(self, speed_rpm: float) -> tuple[np.ndarray, np.ndarray]:
        """(eigenvalues λ, shapes η (m, candidates)) of the lowest modes at one pinion speed, by |λ|."""
        from scipy.linalg import eig

        size = self.size
        state = np.zeros((2 * size, 2 * size))
        state[:size, size:] = np.eye(size)
        state[size:, :size] = -np.diag(self.stiffness)
        state[size:, size:] = -(self.damping + speed_rpm * math.pi / 30.0 * self.gyroscopic)
        values, vectors = eig(state)
        scale = np.abs(values).max()
        keep = (values.imag > 1e-12 * scale) | ((np.abs(values.imag) <= 1e-12 * scale) & (values.real < 0))
        keep &= np.abs(values) > 1e-6
        values, shapes = values[keep], vectors[:size, keep]
        order = np.argsort(np.abs(values), kind="stable")[:self.candidates]
        return values[order], shapes[:, order]

    def mesh_shares(self, shapes: np.ndarray) -> np.ndarray:
        """Share of each mode's strain energy in the mesh: k̄|wᵀVη|² / ηᴴΛη [-]."""
        mesh = self.mesh_stiffness * np.abs(self.mesh_vector @ shapes) ** 2
        return mesh / np.real(np.sum(shapes.conj() * (self.stiffness[:, None] * shapes), axis=0))


def _mac(first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """MAC matrix between the columns of two sets of shapes (M = I in the basis)."""
    products = np.abs(first.conj().T @ second) ** 2
    norms = np.outer(np.sum(np.abs(first) ** 2, axis=0), np.sum(np.abs(second) ** 2, axis=0))
    return products / norms


def campbell_diagram(drivetrain: Drivetrain | AssembledDrivetrain, speeds_rpm: np.ndarray, teeth: int,
                     harmonics: tuple[int, ...] = (1, 2, 3), mode_count: int = 12,
                     mesh_stiffness: float | None = None, basis_cutoff_hz: float | None = None) -> CampbellDiagram:
    """Modes at each pinion speed [rpm] (mean mesh stiffness of the mesh element, or ``mesh_stiffness`` [N/m]),
    the lowest ``mode_count`` at the first speed followed by their shapes, and every crossing of the harmonics
    j·z₁·n/60 with them inside the speed range. ``drivetrain``: a :class:`Drivetrain` or its assembly.
    ``basis_cutoff_hz`` [Hz]: the highest undamped mode of the basis (default :data:`BASIS_FACTOR` times the
    highest mode drawn; ``math.inf``: every mode, the full solve)."""
    from scipy.optimize import brentq, linear_sum_assignment

    assembled = as_assembled(drivetrain)
    speeds = np.asarray(speeds_rpm, dtype=float)
    if speeds.ndim != 1 or speeds.size < 2 or np.any(np.diff(speeds) <= 0) or speeds[0] < 0:
        raise CaseError("speeds_rpm", speeds_rpm, "increasing speeds >= 0 rpm, at least two", "the speed axis")
    if int(teeth) != teeth or teeth < 1:
        raise CaseError("teeth", teeth, "an integer >= 1", "the pinion's tooth count z₁")
    if not harmonics or any(int(j) != j or j < 1 for j in harmonics):
        raise CaseError("harmonics", harmonics, "integers >= 1", "mesh harmonics j of j·z₁·n/60")
    if int(mode_count) != mode_count or mode_count < 1:
        raise CaseError("mode_count", mode_count, "an integer >= 1", "the modes drawn")
    if basis_cutoff_hz is not None and not basis_cutoff_hz > 0.0:
        raise CaseError("basis_cutoff_hz", basis_cutoff_hz, "> 0 Hz (math.inf: every mode)",
                        "the highest undamped mode of the basis")
    if not assembled.drivetrain.meshes:
        raise CaseError("meshes", 0, "at least one mesh", "the diagram's lines are the mesh harmonics")
    # one BLAS thread: the eigen-solves are of ~90 rows, where BLAS threads only contend (measured on fzg_rig_type_c,
    # 100 speeds: 4.4 s CPU and 27 s wall with two OpenBLAS threads against 0.8 s CPU and 5–6 s wall on one, on the
    # loaded 2-core development machine)
    with one_blas_thread():
        system = _ReducedSpinningModes(assembled, mesh_stiffness, basis_cutoff_hz, int(mode_count))
        count = system.count

        @lru_cache(maxsize=None)
        def solved(speed: float) -> tuple[np.ndarray, np.ndarray]:
            return system.solve(speed)

        values, shapes = solved(float(speeds[0]))
        count = min(count, values.size)
        tracked = [np.arange(count)]  # per speed: the candidate that is each mode
        for speed in speeds[1:]:
            previous_values, previous_shapes = solved(float(speeds[len(tracked) - 1]))
            _, current_shapes = solved(float(speed))
            match = _mac(previous_shapes[:, tracked[-1]], current_shapes)
            _, columns = linear_sum_assignment(-match)
            tracked.append(columns)
        eigenvalues = np.array([solved(float(s))[0][columns] for s, columns in zip(speeds, tracked)])
        frequencies = np.abs(eigenvalues) / (2.0 * math.pi)
        shares = np.array([system.mesh_shares(solved(float(s))[1][:, columns]) for s, columns in zip(speeds, tracked)])
        labels = mode_labels(assembled, system.basis @ shapes[:, :count])

        def follow(speed: float, reference: np.ndarray) -> tuple[complex, float]:
            """(λ, mesh share) of the mode at ``speed`` whose shape is closest to the mode's at both ends of the
            bracket, ``reference`` (m, 2) (at one end alone, a pair degenerate at standstill would not choose)."""
            found_values, found_shapes = solved(float(speed))
            best = int(np.argmax(_mac(reference, found_shapes).sum(axis=0)))
            return found_values[best], float(system.mesh_shares(found_shapes[:, best:best + 1])[0])

        crossings = []
        for harmonic in harmonics:
            for mode in range(count):
                values_on_line = frequencies[:, mode] - harmonic * teeth * speeds / 60.0
                for index in np.flatnonzero(np.sign(values_on_line[:-1]) * np.sign(values_on_line[1:]) <= 0):
                    if values_on_line[index] == 0.0 and index > 0:
                        continue  # a root on a grid speed is found from the interval on its left
                    reference = np.column_stack([solved(float(speeds[end]))[1][:, tracked[end][mode]]
                                                 for end in (index, index + 1)])

                    def gap(speed: float, reference: np.ndarray = reference, harmonic: int = harmonic) -> float:
                        return abs(follow(speed, reference)[0]) / (2.0 * math.pi) - harmonic * teeth * speed / 60.0

                    low, high = float(speeds[index]), float(speeds[index + 1])
                    if gap(low) * gap(high) > 0.0:  # the shape match jumped inside the interval: keep the grid's root
                        root = low - values_on_line[index] * (high - low) / (values_on_line[index + 1]
                                                                             - values_on_line[index])
                    else:
                        root = float(brentq(gap, low, high, xtol=1e-9 * speeds[-1], rtol=1e-12))
                    value, share = follow(root, reference)
                    crossings.append(Crossing(int(harmonic), mode, root, abs(value) / (2.0 * math.pi), share,
                                              labels[mode]))
        crossings.sort(key=lambda crossing: crossing.speed_rpm)
        return CampbellDiagram(speeds, frequencies[:, :count], shares[:, :count], labels, int(teeth),
                               tuple(int(j) for j in harmonics), tuple(crossings), system.size)
