"""The block-diagonal step of :mod:`~thermogear.dynamics.linear_algebra.modal_chain` in one compiled pass: the
product of e^{τΛ} (a 2×2 block [[a, b], [−b, a]] per complex pair, a scalar per real eigenvalue) with the modal
coordinates, added to the rank-q term already formed. NumPy takes about eight passes over the coordinates for it
(a product, a sum and an update per half of each pair), which cost as much as the rank-q products themselves on a
167-coordinate chain; here each coordinate is read and written once. Knows nothing of gears."""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["add_block_product"]


@numba.njit(cache=True)
def add_block_product(following: np.ndarray, coordinates: np.ndarray, real: np.ndarray, imaginary: np.ndarray,
                      alone: np.ndarray) -> None:
    """following += e^{τΛ}·coordinates, in place: rows i and pairs + i of ``coordinates`` (m, k) are the two halves of
    pair i (``real`` a, ``imaginary`` b, each (pairs,)), the rows from 2·pairs on the real eigenvalues' (``alone``)."""
    pairs = real.shape[0]
    columns = coordinates.shape[1]
    for pair in range(pairs):
        a, b = real[pair], imaginary[pair]
        for column in range(columns):
            first, second = coordinates[pair, column], coordinates[pairs + pair, column]
            following[pair, column] += a * first + b * second
            following[pairs + pair, column] += a * second - b * first
    for row in range(alone.shape[0]):
        factor = alone[row]
        for column in range(columns):
            following[2 * pairs + row, column] += factor * coordinates[2 * pairs + row, column]
