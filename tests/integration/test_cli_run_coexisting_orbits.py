"""Issue 36, "What a start-up reaches": on a backlash drivetrain where two stable orbits coexist, `thermogear run`
reports the orbit a start from rest settles on, lists the other (the one shot from the linear solution) beside it
with a note, and `run --multistart N` lists both with their basin shares.

The case (tests/data/two_shaft_coexisting_orbits.toml) is the worked two-shaft case cut to two elements per shaft
(36 DOF) at 9750 rpm, just below the wheel shaft's mesh-coupled lateral mode, with the backlash mesh and shaft
material damping 3.4e-6 s. Measured on it: from rest Kv 2.460, contact loss 0.4475 of the period; from the linear
solution Kv 1.833, contact loss 0.1291.

Tolerances: on the mesh grid of 512 intervals instead of the case's 256 the four numbers move by at most 1.4e-4
(relative, Kv) and 1e-5 (contact-loss fraction); the orbits are shot to a relative residual of 1e-8. Kv is asserted
to 2e-3 relative and the contact-loss fraction to 2e-3 absolute: over ten times the grid's error, still some 300
times smaller than the difference between the two orbits (0.63 in Kv, 0.32 in contact loss), so a solver that found
one orbit twice, or swapped them, fails.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from inprocess_cli import invoke

CASE = Path(__file__).resolve().parents[1] / "data" / "two_shaft_coexisting_orbits.toml"

FROM_REST = {"kv": 2.460, "contact_loss_fraction": 0.4475}
FROM_LINEAR = {"kv": 1.833, "contact_loss_fraction": 0.1291}
KV_RELATIVE = 2e-3
CONTACT_LOSS_ABSOLUTE = 2e-3


def _matches(orbit: dict, expected: dict) -> bool:
    return (orbit["kv"] == pytest.approx(expected["kv"], rel=KV_RELATIVE)
            and orbit["contact_loss_fraction"] == pytest.approx(expected["contact_loss_fraction"],
                                                                abs=CONTACT_LOSS_ABSOLUTE))


def test_the_case_is_the_two_shaft_rotor_cut_to_36_dof():
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import case_drivetrain

    built = case_drivetrain(load_case(CASE), ("elastic",))
    assert built.assembled("elastic").size == 36 and built.backlash_mesh


@pytest.fixture(scope="module")
def searched():
    # one run: the reported orbit, the coexisting one and the multi-start search of six starts (rest, the linear
    # solution and four grid points over the mesh coordinate and its rate)
    code, stdout, stderr = invoke("run", str(CASE), "--model", "elastic", "--multistart", "6", "--json")
    assert code == 0, stderr
    return json.loads(stdout)["drivetrain"]


@pytest.mark.slow
def test_run_reports_the_start_up_s_orbit_and_lists_the_other(searched):
    reported = searched["models"]["elastic"]
    assert reported["converged"] and reported["stable"]
    assert reported["reached_from"] == "rest" and reported["branch"] == "high"
    assert _matches(reported, FROM_REST), reported
    (other,) = reported["coexisting_orbits"]
    assert other["reached_from"] == "the linear solution" and other["branch"] == "low" and other["stable"]
    assert _matches(other, FROM_LINEAR), other
    notes = " ".join(searched["notes"])
    assert "two stable orbits coexist" in notes and "--multistart" in notes


@pytest.mark.slow
def test_multistart_lists_both_orbits_with_their_basin_shares(searched):
    search = searched["multistart"]["elastic"]
    assert search["starts"] == 6
    orbits = search["orbits"]
    assert len(orbits) == 2 and all(orbit["stable"] for orbit in orbits)
    (high,) = [orbit for orbit in orbits if orbit["reached_from_rest"]]
    (low,) = [orbit for orbit in orbits if not orbit["reached_from_rest"]]
    assert _matches(high, FROM_REST) and _matches(low, FROM_LINEAR), orbits
    # each start is counted once: on an orbit, unresolved or unbounded; each orbit holds at least its own start
    assert all(orbit["start_count"] >= 1 for orbit in orbits)
    shares = sum(orbit["basin_share"] for orbit in orbits)
    assert shares + search["unresolved_share"] + search["unbounded_share"] == pytest.approx(1.0)
    assert [orbit["basin_share"] for orbit in orbits] == sorted((orbit["basin_share"] for orbit in orbits),
                                                                reverse=True)
