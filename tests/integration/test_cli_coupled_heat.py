"""`run` on a drivetrain case under the gearbox thermal model (issue 35, one heated system): the shafts' temperatures
come from the network and the output says so, beside each bearing's rings, play, static load and loss."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

COUPLED = Path(__file__).resolve().parents[1] / "data" / "gearbox" / "fzg_gearbox_drivetrain.toml"


def test_run_json_shows_the_networks_shaft_temperatures_and_the_table_prints_them():
    environment = {**os.environ, "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
    result = subprocess.run([sys.executable, "-m", "thermogear", "run", str(COUPLED), "--model", "thermal", "--json",
                             "-q"], capture_output=True, text=True, timeout=600, env=environment)
    assert result.returncode == 0, result.stderr
    warm = json.loads(result.stdout)["drivetrain"]["warm_state"]
    network = warm["network_c"]
    assert network["pinion"] > network["pinion_shaft"] + 5.0 > network["housing"] + 5.0
    assert network["pinion_shaft"] > network["wheel_shaft"] > network["housing"]  # each shaft its own node
    nodes = {"pinion shaft": "pinion_shaft", "wheel shaft": "wheel_shaft"}
    for name, shaft in warm["shafts"].items():
        assert shaft["temperature_c"] == network[nodes[name]]
        assert shaft["source"].startswith("gearbox thermal network, each shaft at its shaft node")
    for name, bearing in warm["bearings"].items():
        node = "pinion_shaft" if name.startswith("pinion") else "wheel_shaft"
        assert (bearing["inner_ring_c"], bearing["outer_ring_c"]) == (network[node], network["housing"])
        assert bearing["loss_w"] > 0.0 and bearing["static_radial_load_n"] > 0.0

    from rich.console import Console

    from thermogear.cli.run_drivetrain import _print_warm_state

    console = Console(record=True, width=200)
    _print_warm_state(warm, console)
    text = console.export_text()
    for words in ("drivetrain warm state", "pinion shaft", f"{network['pinion_shaft']:.1f}", f"{network['wheel_shaft']:.1f}", "gearbox thermal network",
                  "wheel bearing B", "clearance mounted → hot"):
        assert words in text, words
