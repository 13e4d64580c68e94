"""The transitions of a chunk of pieces (sub-steps e^{A_j h_j/s} or whole pieces), as the periodic solvers step
states and products through them:
either their matrices, or (the rank-update route) the parts they are made of, which act on a state at O(m² + q·m)
without the (m, m) matrix of each piece being formed and held
(:class:`~thermogear.dynamics.linear_algebra.batched_exponential. RankUpdateExponentials`). Both give the same
transitions to the unit roundoff: the parts add the shared
exponential's product and the rank-q update's instead of forming their sum first. Given the real eigenbasis of the
state matrix the parts share (:mod:`~thermogear.dynamics.linear_algebra.modal_chain`), the parted chain runs in its
modal coordinates at O(q·m²) a piece. Knows nothing of gears."""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.linear_algebra.batched_exponential import RankUpdateExponentials
from thermogear.dynamics.linear_algebra.modal_chain import FactoredStarts, ModalBasis

__all__ = ["DenseSteps", "PartedSteps", "as_steps"]


class DenseSteps:
    """The transitions of a chunk's pieces as matrices: ``matrices`` (k, m, m) of its distinct pieces, ``which`` (c,)
    each piece's (None: one matrix per piece, in order)."""

    def __init__(self, matrices: np.ndarray, which: np.ndarray | None = None):
        self.matrices = matrices
        self.which = np.arange(matrices.shape[0]) if which is None else which

    def __len__(self) -> int:
        return self.which.size

    def walk(self, index: int, state: np.ndarray, count: int, out: np.ndarray) -> np.ndarray:
        """Write the states before each of ``count`` steps of piece ``index`` from ``state`` into ``out`` (count, m);
        return the state after them."""
        step = self.matrices[self.which[index]]
        for sample in range(count):
            out[sample] = state
            state = step @ state
        return state

    def apply_left_all(self, rows: np.ndarray) -> np.ndarray:
        """rows_j·X_j of every piece j of the chunk at once, for rows (c, r, m)."""
        return rows @ self.matrices[self.which]

    def chain(self, total: np.ndarray, starts: np.ndarray | None = None) -> np.ndarray:
        """X_{c−1}···X₀·``total`` (m, m), the pieces one after another; ``starts`` (c, m, m) receives the product
        before each piece."""
        for index in range(len(self)):
            if starts is not None:
                starts[index] = total
            total = self.matrices[self.which[index]] @ total
        return total

    def chain_starts(self, total: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(:meth:`chain`'s product, the (c, m, m) products before each piece)."""
        starts = np.empty((len(self), *total.shape))
        return self.chain(total, starts), starts


class PartedSteps:
    """The sub-step transitions of a chunk as the parts of their exponentials (no squarings): ``parts`` of the
    chunk's distinct pieces and ``which`` (c,) the distinct piece of each piece of the chunk; ``modal`` the real
    eigenbasis of the state matrix the parts were formed from, where the chain is to run in its coordinates
    (:mod:`~thermogear.dynamics.linear_algebra.modal_chain`; None: in the parts' balanced coordinates). Parts without
    their shared exponentials (formed for the modal chain only) serve :meth:`chain` and :meth:`chain_starts`
    alone."""

    def __init__(self, parts: RankUpdateExponentials, which: np.ndarray, modal: ModalBasis | None = None):
        self.parts, self.which = parts, which
        self.modal = modal if parts.times is not None and not parts.squarings else None

    def __len__(self) -> int:
        return self.which.size

    def walk(self, index: int, state: np.ndarray, count: int, out: np.ndarray) -> np.ndarray:
        """As :meth:`DenseSteps.walk`: in the balanced coordinates D·z of the parts, D⁻¹(E + L R)D per sub-step."""
        parts, distinct = self.parts, self.which[index]
        shared, left, right = parts.exponentials[parts.which[distinct]], parts.left[distinct], parts.right[distinct]
        scaled = parts.scale * state
        for sample in range(count):
            out[sample] = state
            scaled = shared @ scaled + left @ (right @ scaled)
            state = scaled / parts.scale
        return state

    def apply_left_all(self, rows: np.ndarray) -> np.ndarray:
        """rows_j·X_j of every piece j of the chunk at once, for rows (c, r, m): D(rows D⁻¹)(E + L_j R_j)D⁻¹…, each
        shared exponential as one product with the rows of the pieces of its width."""
        parts, distinct = self.parts, self.which
        scaled = rows / parts.scale
        exponential = parts.which[distinct]
        shared = np.empty_like(scaled)
        for index in range(parts.exponentials.shape[0]):  # one product per shared exponential, not a copy per piece
            chosen = exponential == index
            block = scaled[chosen]
            shared[chosen] = (block.reshape(-1, block.shape[-1]) @ parts.exponentials[index]).reshape(block.shape)
        return (shared + (scaled @ parts.left[distinct]) @ parts.right[distinct]) * parts.scale

    def chain(self, total: np.ndarray, starts: np.ndarray | None = None) -> np.ndarray:
        """As :meth:`DenseSteps.chain`, in the balanced coordinates D·T of the parts: (E + L_j R_j)·B per piece,
        O(m³ + q·m²), without forming the piece's matrix; in the modal coordinates (O(q·m²)) where it has them (the
        ``starts`` then formed from them at O(m³) each: :meth:`chain_starts` keeps them factored)."""
        if self.modal is not None:
            total, modal_starts = self.modal.chain(self.parts, self.which, total, keep_starts=starts is not None)
            if starts is not None:
                starts[:] = modal_starts.basis @ modal_starts.coordinates
            return total
        parts, scale = self.parts, self.parts.scale[:, None]
        balanced = scale * total
        for index in range(len(self)):
            if starts is not None:
                starts[index] = balanced / scale
            distinct = self.which[index]
            balanced = (parts.exponentials[parts.which[distinct]] @ balanced
                        + parts.left[distinct] @ (parts.right[distinct] @ balanced))
        return balanced / scale

    def chain_starts(self, total: np.ndarray) -> tuple[np.ndarray, np.ndarray | FactoredStarts]:
        """(:meth:`chain`'s product, the products before each piece: (c, m, m), or as their modal coordinates where
        the chain runs in them)."""
        if self.modal is not None:
            return self.modal.chain(self.parts, self.which, total, keep_starts=True)
        starts = np.empty((len(self), *total.shape))
        return self.chain(total, starts), starts


def as_steps(steps) -> DenseSteps | PartedSteps:
    """Either form as given; a (c, m, m) array as :class:`DenseSteps`."""
    return steps if isinstance(steps, (DenseSteps, PartedSteps)) else DenseSteps(np.asarray(steps))
