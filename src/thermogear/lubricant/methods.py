"""How the mesh of a gearbox is lubricated, chosen once: ``[gearbox.oil] lubrication`` resolved here into what the
loss model and the load-time checks ask (is there an into-mesh oil jet, does the wheel dip into the sump by
default), never compared as a string.

* ``"dip"``: dip (splash) lubrication, the gears churning the sump; the wheel dips to its centre unless
  ``wheel_immersion_mm`` is given;
* ``"injection"``: an into-mesh oil jet (its impulse loss, :mod:`thermogear.gearbox.injection`), which needs the
  jet's flow and speed; the gears stand above the oil unless immersions are given.

A new method is one :class:`LubricationMethod` line in :data:`LUBRICATION_METHODS` (and the ``Literal`` of
:class:`thermogear.schema.gearbox.GearboxOilSection`, tested equal). This module imports nothing of thermogear but
its errors (through :mod:`thermogear.registry`), so every layer may read it.
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.registry import registered

__all__ = ["LUBRICATION_METHODS", "LubricationMethod", "lubrication_method"]


@dataclass(frozen=True)
class LubricationMethod:
    """A lubrication method: ``name`` (the ``[gearbox.oil] lubrication`` value), whether an into-mesh jet feeds
    the mesh (``oil_jet``: its flow and speed are then required, and refused otherwise) and whether the wheel
    dips into the sump when ``wheel_immersion_mm`` is not given (``wheel_dipped``: to its operating pitch radius,
    else 0)."""

    name: str
    oil_jet: bool
    wheel_dipped: bool


#: Every lubrication method by name (the first the default): the one place the names are compared.
LUBRICATION_METHODS: dict[str, LubricationMethod] = {method.name: method for method in (
    LubricationMethod("dip", oil_jet=False, wheel_dipped=True),
    LubricationMethod("injection", oil_jet=True, wheel_dipped=False))}


def lubrication_method(name: str) -> LubricationMethod:
    """The lubrication method called ``name``; a CaseError naming ``gearbox.oil.lubrication`` for any other."""
    return registered(LUBRICATION_METHODS, name, "gearbox.oil.lubrication", "unknown lubrication method")
