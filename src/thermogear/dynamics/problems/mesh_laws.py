"""The contact law of the mesh, chosen once: ``[dynamics] mesh = "linear" | "nonlinear"`` resolved here into what
the rest of the package asks (does the mesh have a dead zone, how is it described), never compared as a string.

* ``"linear"``: permanent contact, the linear periodic problem (Floquet) or its motion from rest;
* ``"nonlinear"``: the backlash dead zone (free flight, back-flank contact), solved by shooting or from rest.

A new contact law is one :class:`MeshLaw` line in :data:`MESH_LAWS` (and its solvers in
:data:`thermogear.simulation` ``_SOLVERS``).
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.errors import CaseError

__all__ = ["LINEAR", "MESH_LAWS", "MeshLaw", "NONLINEAR", "mesh_law"]


@dataclass(frozen=True)
class MeshLaw:
    """A contact law of the mesh: ``name`` (the ``[dynamics] mesh`` value and the ``mesh`` of a response's metrics),
    whether it has the backlash dead zone (``backlash``), and how outputs describe it (``description``)."""

    name: str
    backlash: bool
    description: str


LINEAR = MeshLaw("linear", False, "linear (permanent contact)")
NONLINEAR = MeshLaw("nonlinear", True, "nonlinear (backlash)")

#: Every contact law by name: the one place the names are compared.
MESH_LAWS: dict[str, MeshLaw] = {law.name: law for law in (LINEAR, NONLINEAR)}


def mesh_law(name: str | None) -> MeshLaw:
    """The contact law called ``name`` (None: the linear one, as a metrics dict without ``mesh`` is)."""
    if name is None:
        return LINEAR
    law = MESH_LAWS.get(name)
    if law is None:
        raise CaseError("dynamics.mesh", name, " | ".join(MESH_LAWS), "unknown contact law of the mesh")
    return law
