"""Case-file sections [damping] and [dynamics]."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from thermogear.dynamics.problems.solution_methods import solution_method
from thermogear.errors import CaseError

from thermogear.schema.base import Section
from thermogear.schema.friction_inputs import check_friction_inputs


#: Most mesh periods a transient run integrates [–]. The history of every sample is kept (about 1.1 MB per period
#: of 1024 samples: 100 000 periods grew to 24 GB, issue 25). A lightly damped mesh (damping ratio 0.02) at twice
#: its natural frequency decays by e^(−2π·0.02·500/2) ≈ e^(−31) over 500 periods: more is never needed to settle.
MAX_TRANSIENT_PERIODS = 500
#: Most samples of a transient history (periods × points per period) [–]: 500 periods of 1024 samples, ≈ 0.55 GB.
MAX_TRANSIENT_SAMPLES = MAX_TRANSIENT_PERIODS * 1024
#: Most samples of one periodic orbit (points_per_period × samples_per_interval) [–]. Each sample keeps the state,
#: the mesh force and the metrics' series of both models, about 300 bytes: 100 000 × 256 samples took 7.3 GB and
#: 5 min (and a memory traceback on a smaller machine, issue 36); 2²⁰ samples stay near 0.3 GB, and 1024 points
#: of 1024 samples each resolve a mesh period far finer than any plot or spectrum needs.
MAX_ORBIT_SAMPLES = 1024 * 1024


class DampingSection(Section):
    """Equivalent viscous damping of tooth friction (Luo & Li Eqs. 26–28; docs/damping.md).

    ``rule``: how the pairs in contact combine into c(τ): ``"paper"`` (Luo & Li Fig. 7: the arithmetic mean of
    the pairs in contact, so the double-pair value stays below the single-pair one, as the per-pair values are)
    or ``"parallel"`` (dampers of the pairs in contact add, the physically consistent reading of the same
    energy argument).
    ``stiffness``: the pair stiffness k in Eq. 28 (and in the load share of the friction formula) for the
    thermal model: ``"elastic"`` k_e (the paper: c_r differs from c_e by the viscosity only) or ``"thermal"``
    k_T. The elastic model always uses k_e.
    ``friction_model``: the mean friction law μ of Eq. 28, from the registry of the loss model
    (:data:`thermogear.friction.models.FRICTION_MODELS`), applied locally along the path like the paper's:
    ``"paper"`` (Luo & Li Eq. 27, the default: the reproduction keeps every number), ``"schlenk"``,
    ``"iso_tr_13989_2"`` or ``"constant"`` (then ``friction_coefficient``).
    """

    rule: Literal["paper", "parallel"] = "parallel"
    lubricant_factor: Annotated[float, Field(gt=0.0, le=3.0, description="X_L; default from the base oil")] | None = None
    stiffness: Literal["elastic", "thermal"] = Field(
        "elastic", description="pair stiffness of Eq. 28 in the thermal model: k_e (paper) or k_T")
    friction_model: Literal["paper", "schlenk", "iso_tr_13989_2", "constant"] = Field(
        "paper", description="mean friction law of the friction damping (Eq. 28): paper (Luo & Li Eq. 27, the "
                             "default), schlenk (FZG power-loss work), iso_tr_13989_2, constant")
    friction_coefficient: Annotated[float, Field(gt=0.0, le=0.3, allow_inf_nan=False)] | None = Field(
        None, description="the friction coefficient [–] of friction_model = 'constant' (only there)")

    @model_validator(mode="after")
    def _friction_inputs(self):
        check_friction_inputs("damping", self.friction_model, self.friction_coefficient, self.lubricant_factor)
        return self


class DynamicsSection(Section):
    """Solver settings of the torsional model me·ẍ + c(τ)ẋ + k(τ)x = w.

    ``mesh``: ``"nonlinear"`` (default) — the teeth may separate and strike the back flanks across the backlash
    (each pair acts only while it touches: the driving force k_i⟨x − e_i⟩₊ and the back-flank force); ``"linear"``
    — every pair stays in contact (Luo & Li's model; the paper's set keeps it). ``damping_in_flight``: whether the
    mesh damping also acts while no flank touches (``"always"``, the default: the oil between the flanks is
    squeezed and the shafts' own damping acts on the same coordinate) or only in contact (``"in_contact"``).
    """

    mesh: Literal["nonlinear", "linear"] = Field(
        "nonlinear", description="'nonlinear': contact loss and back-side contact across the backlash; 'linear': "
                                 "permanent contact (Luo & Li)")
    damping_in_flight: Literal["always", "in_contact"] = Field(
        "always", description="mesh damping while the teeth fly through the backlash")
    method: Literal["periodic", "transient"] = "periodic"
    points_per_period: Annotated[int, Field(ge=64, le=100000)] = 1024
    samples_per_interval: Annotated[int, Field(ge=1, le=256, description="samples of the periodic orbit inside "
                                                             "each interval, for metrics and plots")] = 4
    transient_periods: Annotated[int, Field(ge=1, le=MAX_TRANSIENT_PERIODS, description=(
        "mesh periods integrated from rest (the history is kept: about 1 kB per sample)"))] = 60
    include_damping_force: bool = Field(False, description="dynamic load k·x + c·ẋ instead of the paper's k·x")
    mesh_table: str | None = Field(None, description=(
        "CSV table of one mesh period (columns 'phase [-]', 'stiffness [N/m]', optional 'damping [N*s/m]', "
        "'deviation [um]'; relative to the case file) that replaces the models' k(τ) in the dynamics"))

    @model_validator(mode="after")
    def _orbit_memory(self):
        samples = self.points_per_period * self.samples_per_interval
        if samples > MAX_ORBIT_SAMPLES:
            raise CaseError("dynamics.samples_per_interval", self.samples_per_interval,
                            f"<= {MAX_ORBIT_SAMPLES // self.points_per_period} with points_per_period = "
                            f"{self.points_per_period}", f"the periodic orbit keeps every sample (about 300 bytes "
                            f"each): {samples:,} samples would need about {samples * 3e-7:.1f} GB; at most "
                            f"{MAX_ORBIT_SAMPLES:,} samples per period")
        return self

    @model_validator(mode="after")
    def _transient_memory(self):
        samples = self.transient_periods * self.points_per_period
        if solution_method(self.method).from_rest and samples > MAX_TRANSIENT_SAMPLES:
            raise CaseError("dynamics.transient_periods", self.transient_periods,
                            f"<= {MAX_TRANSIENT_SAMPLES // self.points_per_period} with points_per_period = "
                            f"{self.points_per_period}", f"the transient keeps every sample (about 1 kB each): "
                            f"{samples:,} samples would need over {samples * 1.1e-6:.1f} GB")
        return self
