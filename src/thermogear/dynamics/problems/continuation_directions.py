"""The directions a continuation follows a branch in, and the branches a study follows, chosen once by name (issue
33: every choice resolved once from a registry, never compared as a string).

* a continuation's ``direction``: ``"up"`` (from the first item, the lowest speed, to the last) or ``"down"`` (back);
* a study's ``--direction``: ``"up"``, ``"down"`` or ``"both"`` (the default: both branches, up first).

The names are also the labels of the ``direction`` dimension of a branch study's store. A new direction is one entry
of :data:`DIRECTIONS`; a new study choice one of :data:`STUDY_DIRECTIONS`. This module reads nothing of gears, so
the solvers and the studies both read it.
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.registry import registered

__all__ = ["DEFAULT_STUDY_DIRECTION", "DIRECTIONS", "STUDY_DIRECTIONS", "Direction", "direction_named",
           "study_directions"]


@dataclass(frozen=True)
class Direction:
    """A direction of a continuation over an ordered sequence: ``name`` and whether it visits the items
    ``ascending`` (first to last)."""

    name: str
    ascending: bool

    @property
    def step(self) -> int:
        """+1 ascending, −1 descending (the stride of the visit)."""
        return 1 if self.ascending else -1

    def order(self, count: int) -> range:
        """The indices of ``count`` items in the order this direction visits them."""
        return range(count) if self.ascending else range(count - 1, -1, -1)


#: The directions of a continuation by name: the one place their names are compared.
DIRECTIONS: dict[str, Direction] = {direction.name: direction for direction in (Direction("up", ascending=True),
                                                                              Direction("down", ascending=False))}
#: The branches a study follows, by its ``--direction`` value (each a tuple of :data:`DIRECTIONS`' names).
STUDY_DIRECTIONS: dict[str, tuple[str, ...]] = {"up": ("up",), "down": ("down",), "both": tuple(DIRECTIONS)}
#: The study's choice unless told: both branches.
DEFAULT_STUDY_DIRECTION = "both"


def direction_named(name: str, key: str = "direction") -> Direction:
    """The continuation direction ``name``; a CaseError naming ``key`` for any other."""
    return registered(DIRECTIONS, name, key, "a branch is followed from the lowest speed up or from the highest down")


def study_directions(name: str | None, key: str = "--direction") -> tuple[str, ...]:
    """The directions a study follows for its ``--direction`` value ``name`` (None: the default, both); a CaseError
    naming ``key`` for any other value."""
    return registered(STUDY_DIRECTIONS, DEFAULT_STUDY_DIRECTION if name is None else name, key,
                      "a branch is followed from the lowest speed up, from the highest down, or both")
