"""A drivetrain response as arrays for a results file: over one mesh period the dynamic transmission error, the mesh
force and the force of each bearing on its housing in x, y, z, and each bearing's spectrum in mesh harmonics — what
an accelerometer on the housing sees, as time series and as lines at the mesh harmonics.

The parts are ``(data variables, coordinates, attributes)`` with every variable as ``name → (dims, values,
attributes)``, the form the report's ``results.nc`` writes (one group per model). Samples follow the response's
own times (a backlash orbit samples each contact switch on both sides, so a time may repeat: ``time`` is a
variable along ``sample``, not an index).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["response_dataset_parts"]


def response_dataset_parts(response, harmonics: int, attributes: dict[str, Any] | None = None, points: int = 1024
                           ) -> tuple[dict, dict, dict] | None:
    """The arrays of a periodic drivetrain response (linear :class:`~thermogear.drivetrain.response.
    DrivetrainResponse` or :class:`~thermogear.drivetrain.backlash_response.DrivetrainBacklashResponse`) with the
    bearings' amplitudes at the mesh harmonics 0 … ``harmonics`` [N] (0: the mean force; from ``points`` uniform
    samples of the period, as ``bearing_spectrum``); None for a response that carries no motion (an orbit that was
    not found)."""
    if response.time.size == 0:
        return None
    names = list(response.bearing_forces)
    forces = np.stack([response.bearing_forces[name] for name in names])  # (bearing, sample, axis)
    meshes = getattr(response, "meshes", None) or {}
    if len(meshes) > 1:  # a train: lines of its common period up to every mesh's last harmonic asked for
        harmonics *= max(round(response.period / item.mesh_period) for item in meshes.values())
        points = max(points, 4 * harmonics)
    spectra, frequencies = [], None
    for name in names:
        frequencies, amplitudes = response.bearing_spectrum(name, points)
        spectra.append(amplitudes[:, :harmonics + 1])
    data_vars = {
        "time": ("sample", response.time, {"units": "s", "long_name": "time within one mesh period"}),
        "transmission_error": ("sample", response.transmission_error,
                               {"units": "m", "long_name": "dynamic transmission error along the line of action"}),
        "mesh_force": ("sample", response.mesh_force, {"units": "N", "long_name": "dynamic mesh force"}),
        "bearing_force": (("bearing", "sample", "axis"), forces,
                          {"units": "N", "long_name": "force of the bearing on its housing"}),
        "bearing_harmonic_amplitude": (("bearing", "axis", "harmonic"), np.array(spectra),
                                       {"units": "N", "long_name": "amplitude at the mesh harmonic (0: the mean)"}),
    }
    coords = {"bearing": ("bearing", np.array(names, dtype=object)), "axis": ("axis", np.array(["x", "y", "z"],
                                                                                                  dtype=object)),
              "harmonic": ("harmonic", np.arange(harmonics + 1)),
              "harmonic_frequency": ("harmonic", np.asarray(frequencies[:harmonics + 1]), {"units": "Hz"})}
    attrs = {"mesh_period_s": float(response.period), **(attributes or {})}
    if len(meshes) > 1:  # each mesh's DTE and force over the common period; the lines are multiples of 1/T
        coords["mesh"] = ("mesh", np.array(list(meshes), dtype=object))
        data_vars["stage_transmission_error"] = (("mesh", "sample"), np.array([item.transmission_error for item in
                                                                               meshes.values()]),
                                                 {"units": "m", "long_name": "each mesh's dynamic transmission error"})
        data_vars["stage_mesh_force"] = (("mesh", "sample"), np.array([item.mesh_force for item in meshes.values()]),
                                         {"units": "N", "long_name": "each mesh's dynamic mesh force"})
        attrs.update({"common_period_s": float(response.period), "harmonic": "multiples of 1/common period; mesh m's "
                      "j-th harmonic is line j·L_m, L_m its periods in the common period"})
    return data_vars, coords, attrs
