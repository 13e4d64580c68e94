"""Example 7 — the paper's pair on its shafts and bearings: modes, and the bearing forces over speed.

    python examples/08_drivetrain.py [OUTPUT_FOLDER]

The luo2019 pair (27/35 teeth, thermal mesh model) is put on two 150 mm shafts (bore diameters: 30 and 40 mm)
with each gear at mid-span and a rolling bearing at each end (2.5e8 N/m, damping 1.25e-5 s·k — an assumed
typical value, not a measured one). The gear bodies are the discs of the operating pitch radius with their bores,
as the 1-DOF model uses, so the two models share the gears' inertias. The script lists the lowest modes with their
labels and the share of strain energy in the mesh, then sweeps the pinion speed through the mesh-dominated mode
and compares the drivetrain's Kv with the 1-DOF pair's and shows the first mesh harmonic of the force a bearing
puts on the housing — what an accelerometer there would see.
"""

from __future__ import annotations

import math
import sys
import tempfile
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear import load_case  # noqa: E402
from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation,  # noqa: E402
                                   RigidDisk, Shaft, ShaftSegment)
from thermogear.drivetrain.modes import drivetrain_modes  # noqa: E402
from thermogear.drivetrain.response import drivetrain_periodic_response  # noqa: E402
from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state  # noqa: E402
from thermogear.dynamics.results.metrics import compute_metrics  # noqa: E402
from thermogear.errors import ModelLimitError  # noqa: E402
from thermogear.mesh.model import MeshModel  # noqa: E402

BEARING_STIFFNESS = 2.5e8  # [N/m], a rolling bearing of this size (assumed)
POINTS_PER_PERIOD = 24  # mesh grid intervals per period: enough for the mesh harmonics shown, and fast
CUTOFF_HZ = 6e4  # modes kept (plus the static corrections): 10× the mesh-dominated mode; Kv within 3e-6 of all modes


def build_drivetrain(model: MeshModel, mean_stiffness: float) -> Drivetrain:
    """Two shafts with the gears at mid-span and two bearings each (the input docs/drivetrain.md describes)."""
    pair, density = model.gear_pair, model.case.material.density
    steel = Material(youngs_modulus=206e9, density=density, poisson_ratio=0.3)
    pitch_1, pitch_2 = pair.operating_pitch_radii
    shafts, disks, bearings = [], [], []
    for name, bore, pitch in (("pinion shaft", pair.pinion.bore_radius, pitch_1),
                              ("wheel shaft", pair.wheel.bore_radius, pitch_2)):
        shafts.append(Shaft(name, (ShaftSegment(0.15, CrossSection(2 * bore), steel),), 0.0375,
                            material_damping=3e-8))
        disks.append(RigidDisk.annulus(name.split()[0], NodeLocation(name, 0.075), density, pair.face_width,
                                       2 * pitch, 2 * bore))
        for end, position in (("A", 0.0), ("B", 0.15)):
            damping = 1.25e-5 * BEARING_STIFFNESS
            bearings.append(Bearing(f"{name} bearing {end}", NodeLocation(name, position), BEARING_STIFFNESS,
                                    BEARING_STIFFNESS, 1e8 if end == "A" else 0.0, damping, damping,
                                    damping if end == "A" else 0.0))
    mesh = GearMesh("mesh", NodeLocation("pinion shaft", 0.075), NodeLocation("wheel shaft", 0.075),
                    pair.pinion.base_radius, pair.wheel.base_radius, pair.operating_pressure_angle, mean_stiffness)
    return Drivetrain(tuple(shafts), tuple(disks), tuple(bearings), meshes=(mesh,))


def one_dof_kv(state) -> float:
    problem = state.problem()
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    interval = np.minimum(np.arange(orbit.time.size) // 8, problem.stiffness.size - 1)
    return compute_metrics(problem, orbit.time, orbit.displacement, orbit.velocity, interval,
                           orbit.multipliers)["kv"]


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = MeshModel(load_case("luo2019"), "thermal")
        reference = model.state(points_per_period=POINTS_PER_PERIOD)
    drivetrain = build_drivetrain(model, reference.mean_mesh_stiffness)
    assembled = drivetrain.assemble()
    modes = drivetrain_modes(assembled, count=16)
    mesh_share = modes.mesh_share("mesh")
    dominant = int(np.argmax(mesh_share))
    rigid_hz = model.natural_frequency_hz(reference)  # the 1-DOF pair on rigid supports
    teeth = model.gear_pair.pinion.teeth
    speeds = np.linspace(0.5, 1.3, 9) * 60.0 * modes.frequencies_hz[dominant] / teeth

    kv_drivetrain, kv_pair, bearing_first = [], [], []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for speed in speeds:
            state = model.state(speed_rpm=speed, points_per_period=POINTS_PER_PERIOD)
            try:
                kv_pair.append(one_dof_kv(state))
            except ModelLimitError:  # parametric instability of the 1-DOF pair: no periodic state to show
                kv_pair.append(math.nan)
            response = drivetrain_periodic_response(assembled, state, samples_per_piece=4, cutoff_hz=CUTOFF_HZ)
            kv_drivetrain.append(response.kv)
            _, amplitudes = response.bearing_spectrum("pinion shaft bearing A", points=256)
            bearing_first.append(float(np.hypot(amplitudes[0, 1], amplitudes[1, 1])))
            # each pinion bearing carries half the mean mesh force (gear at mid-span): 1 % (quadrature)
            mean = np.hypot(amplitudes[0, 0], amplitudes[1, 0])
            assert abs(mean / (0.5 * state.normal_load) - 1.0) < 0.01, (speed, mean)
    kv_drivetrain, kv_pair = np.array(kv_drivetrain), np.array(kv_pair)

    # --- checks
    for shares in (sum(modes.strain_energy_shares.values()),):
        assert np.allclose(shares, 1.0, atol=1e-9)  # modal strain energy shared out completely
    # the mode that stores most energy in the mesh is torsional and within 30 % of the rigid-support pair's
    # frequency: the shafts' inertia and compliance and the lateral motion of the gears on their bearings move
    # it (the interlacing theorem only says that the lowest drivetrain mode lies below the pair's)
    assert modes.labels[dominant] == "torsional" and mesh_share[dominant] > 0.5
    assert abs(modes.frequencies_hz[dominant] / rigid_hz - 1.0) < 0.3
    assert modes.frequencies_hz[0] < rigid_hz
    assert np.all(np.isfinite(kv_drivetrain)) and np.all(np.isfinite(bearing_first))
    # the drivetrain's Kv peaks near the speed where the mesh frequency meets the mesh-dominated mode
    # (a linear mesh: at the peak the teeth would separate, which the nonlinear mesh of example 6 describes), and
    # the bearing force's first mesh harmonic peaks there too
    peak = speeds[int(np.argmax(kv_drivetrain))] * teeth / 60.0 / modes.frequencies_hz[dominant]
    assert 0.9 < peak < 1.1, peak
    assert int(np.argmax(bearing_first)) == int(np.argmax(kv_drivetrain))

    # --- figure
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 5.5), sharex=True, constrained_layout=True)
    top.plot(speeds, kv_drivetrain, "o-", label="pair on shafts and bearings")
    top.plot(speeds, kv_pair, "s--", color="0.4", label="1-DOF pair on rigid supports")
    top.set_ylabel("Kv [-]")
    top.legend(fontsize=8)
    top.set_title(f"luo2019 pair on its shafts: mesh-dominated mode {modes.frequencies_hz[dominant]:.0f} Hz "
                  f"(rigid supports {rigid_hz:.0f} Hz)", fontsize=10)
    bottom.plot(speeds, bearing_first, "o-", color="tab:red")
    bottom.set_xlabel("pinion speed [rpm]")
    bottom.set_ylabel("bearing force, 1st mesh harmonic [N]")
    path = out / "example_08_drivetrain.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    print("lowest modes: " + "; ".join(f"{f:.0f} Hz {label} (mesh {s:.2f})" for f, label, s
                                      in zip(modes.frequencies_hz[:8], modes.labels, mesh_share)))
    print(f"mesh-dominated mode {modes.frequencies_hz[dominant]:.0f} Hz vs {rigid_hz:.0f} Hz on rigid supports; "
          f"Kv max {kv_drivetrain.max():.3f} (1-DOF {np.nanmax(kv_pair):.3f}); figure: {path}")
    return {"modes": modes, "speeds": speeds, "kv": kv_drivetrain, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
