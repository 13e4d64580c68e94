"""The choices of a ``[drivetrain]`` section made by name, each resolved here into what the rest of the package asks,
never compared as a string:

* an end's ``kind`` (``[drivetrain.driving]``, ``[drivetrain.driven]``): ``"torque"``, a constant torque (the train
  turns freely), or ``"speed"``, a motor held at speed by its controller (a torsional spring and dashpot to ground
  at a point of a shaft: the end ``held_at_speed``);
* ``pinion_rotation``: ``"counter-clockwise"`` or ``"clockwise"`` about +z, the rotation ``sense`` s = +1 or −1 of
  the mesh element.

A new choice is one line in its table (and the ``Literal`` of :mod:`thermogear.schema.drivetrain`, tested equal).
This module imports nothing of thermogear, so every layer may read it (the schema's checks included).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["END_KINDS", "ROTATIONS", "EndKind", "Rotation"]


@dataclass(frozen=True)
class EndKind:
    """How an end of the train is driven or braked: ``name`` (its ``kind``) and whether a motor holds it at speed
    (``held_at_speed``: a torsional support to ground, which needs a shaft, a position and a stiffness), else a
    constant torque."""

    name: str
    held_at_speed: bool


@dataclass(frozen=True)
class Rotation:
    """The pinion's turning sense about +z: ``name`` (the ``pinion_rotation`` value) and ``sense`` (+1
    counter-clockwise, −1 clockwise)."""

    name: str
    sense: int


#: Every kind of a train's end by name (the first the default): the one place the names are compared.
END_KINDS: dict[str, EndKind] = {kind.name: kind for kind in (EndKind("torque", held_at_speed=False),
                                                             EndKind("speed", held_at_speed=True))}
#: Every turning sense of the pinion by name (the first the default): the one place the names are compared.
ROTATIONS: dict[str, Rotation] = {rotation.name: rotation for rotation in (Rotation("counter-clockwise", 1),
                                                                          Rotation("clockwise", -1))}
