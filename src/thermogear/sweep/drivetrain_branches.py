"""The settings of a drivetrain's study with the backlash mesh (:mod:`thermogear.sweep.drivetrain_study`): the
periodic orbit followed up and down in speed.

Near a mesh resonance softened by contact loss the orbit has two stable branches over a band of speeds; a run-up
stays on one, a run-down on the other, and each jumps where its branch ends (Kahraman & Singh, J. Sound Vib. 142
(1990) 49–75). Per model (cold elastic, hot thermal) and direction the orbit is continued over the speeds, one
task per point (:func:`~thermogear.sweep.drivetrain_study.backlash_task`: each speed starts from its neighbour's
orbit, run in where that branch is lost), each speed on the modes of its mean system up to the section's
``response_cutoff_hz``. At each speed whose orbit was found the response
(:func:`~thermogear.drivetrain.backlash_response.drivetrain_backlash_response`, on the same modal basis) starts at
the branch's converged state, so its shooting ends at its first residual: Kv, DTE, contact loss, back-flank
contact, the Floquet multipliers and each bearing's force on its housing in the first mesh harmonics. A speed whose
state could not be built or whose orbit was not found is stored as missing (NaN) with its status saying why, never
as valid; an orbit found but unstable keeps its numbers, marked "unstable".
"""

from __future__ import annotations

from thermogear.dynamics.problems.continuation_directions import DIRECTIONS as CONTINUATION_DIRECTIONS

__all__ = ["DIRECTIONS", "SAMPLES_PER_PIECE", "SUBSTEPS"]

DIRECTIONS = tuple(CONTINUATION_DIRECTIONS)  # the branches of a backlash study, up first
#: Sub-steps per mesh-grid interval in which the shooting looks for contact switches: the backlash solver's default
#: (fewer let a switch go unseen on stiff supports, the solver's tests), the same for the branch and the response,
#: so the response re-solves exactly the system whose orbit the branch found.
SUBSTEPS = 16
#: Samples per mesh-grid interval of the response (bearing-force RMS and harmonics, DTE), as the linear drivetrain
#: sweep: with ``sweep_points_per_period`` intervals (≥ 16, 128 by default) that is ≥ 64 samples per mesh period
#: besides both sides of every contact switch, which the trajectory samples exactly; the sampling costs about
#: half of a point's time.
SAMPLES_PER_PIECE = 4
