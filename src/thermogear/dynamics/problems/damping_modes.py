"""How the mesh damping acts while the teeth fly through the backlash, chosen once: ``[dynamics] damping_in_flight``
(a backlash problem's ``damping_mode``) resolved here into what the solvers ask, never compared as a string.

* ``"always"`` (default): c acts on ẋ at all times, also in free flight (Kahraman & Singh 1990); the vector field
  is continuous;
* ``"in_contact"``: c is scaled by the fraction of the pairs present on the interval that are in contact, so it
  vanishes in free flight and the vector field jumps at every contact switch.

(:mod:`thermogear.dynamics.problems.backlash_problem` says why.) A new mode is one :class:`DampingMode` line in
:data:`DAMPING_MODES` (and the ``Literal`` of :class:`thermogear.schema.dynamics.DynamicsSection`, tested equal)
and its law in the solvers. A backlash problem checks its mode against this table and answers
``damping_contact_only``. This module imports nothing of thermogear, so every layer may read it.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["DAMPING_MODES", "DampingMode"]


@dataclass(frozen=True)
class DampingMode:
    """A damping mode: ``name`` (the ``[dynamics] damping_in_flight`` value) and whether the damping acts only in
    proportion to the pairs in contact (``contact_only``: none in free flight), else at all times."""

    name: str
    contact_only: bool


#: Every damping mode by name (the first the default): the one place the names are compared.
DAMPING_MODES: dict[str, DampingMode] = {mode.name: mode for mode in (
    DampingMode("always", contact_only=False),
    DampingMode("in_contact", contact_only=True))}

