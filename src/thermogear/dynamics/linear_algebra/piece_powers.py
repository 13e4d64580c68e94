"""The powers B_j^(2^k) of the distinct pieces' step maps that the run route multiplies
(:func:`~thermogear.dynamics.periodic_orbits.periodic_runs.by_runs`), formed on demand.

A piece's sub-step (h_j/s of it) is S_j = B_j^(n_j): the map over the common step of the pieces (n_j = 1 where the
sub-steps themselves are the steps, :class:`DensePowers`; n_j > 1 where the pieces' sub-steps are whole multiples
of one step δ and B_j = e^{A_j δ}, :class:`~thermogear.dynamics.linear_algebra.shared_pade.SharedPowers`). A run of L
sub-steps is B_j^(n_j·L), the product of the binary powers its exponent names (Moler & Van Loan, SIAM Review 45 (2003)
3–49, §3). The powers may be kept in balanced coordinates X_b = D⁻¹XD (``scale`` the diagonal d, with the augmented
state's last entry unscaled, d_m = 1): a state z is then carried as D⁻¹z. Knows nothing of gears: matrices only.
"""

from __future__ import annotations

import numpy as np

__all__ = ["DensePowers", "power_factors"]


class DensePowers:
    """The powers of given step maps ``steps`` (D, m, m) by repeated squaring: n_j = 1, no balancing."""

    def __init__(self, steps: np.ndarray):
        self.multiples = np.ones(steps.shape[0], dtype=int)
        self.scale = None
        self._chains = [[step] for step in steps]

    def power(self, piece: int, level: int) -> np.ndarray:
        """B_j^(2^level) (m, m), squared from the one below on first request."""
        chain = self._chains[piece]
        while len(chain) <= level:
            chain.append(chain[-1] @ chain[-1])
        return chain[level]


def power_factors(powers, piece: int, exponent: int, top: int) -> list[np.ndarray]:
    """Binary powers of piece ``piece``'s step whose product (in list order, each applied after the one before) is
    B^``exponent``: the powers below 2^``top`` that the exponent's low bits name, then B^(2^top) as often as the
    rest needs (the highest power used at most ``top``)."""
    factors = [powers.power(piece, bit) for bit in range(top) if (exponent % 2 ** top) >> bit & 1]
    return factors + [powers.power(piece, top)] * (exponent >> top)
