"""The names of the two mesh models a simulation runs, defined once.

``"elastic"``: the elastic pair stiffness k_e with the oil at its reference temperature (Luo & Li (2020) Eq. 5);
``"thermal"``: the case's thermal pair model (``[thermal] model``: the predictive ``"thermoelastic"`` or the paper's
``"luo2020"``) with the viscosity at the flank temperature (Eq. 6). Which pair model answers for each is resolved in
one place, :func:`thermogear.mesh.pair_models.pair_model_class`.
"""

from __future__ import annotations

from typing import Literal

Model = Literal["elastic", "thermal"]
#: The two simulation models, each name once: callers that pick one of the two runs (a report column, a user's
#: ``--model`` choice) use these constants, never the string.
ELASTIC, THERMAL = "elastic", "thermal"
MODELS: tuple[str, ...] = (ELASTIC, THERMAL)

__all__ = ["ELASTIC", "MODELS", "Model", "THERMAL"]
