"""Example 1 — reproduce Luo & Li (2020): run the paper's case, compare every number, plot the predictions.

    python examples/01_reproduce_luo2019.py [OUTPUT_FOLDER]

The command line does the same and more (`thermogear reproduce luo2019` writes the full report). Here the
Python API: load the built-in case, evaluate the whole chain, judge every row of the paper table, and draw one
figure — each prediction of the paper as thermogear/paper with its argued tolerance band.
"""

from __future__ import annotations

import sys
import tempfile
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear import load_case  # noqa: E402
from thermogear.report.evaluate import evaluate_case, paper_verdicts  # noqa: E402
from thermogear.luo2020.report.table import Absolute, Relative, known_gaps, table_counts  # noqa: E402


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    case = load_case("luo2019")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the report lists the model's warnings; not needed here
        evaluation = evaluate_case(case)
    verdicts = paper_verdicts(evaluation)
    counts = table_counts(verdicts)

    # --- checks: every prediction computed; every one outside its tolerance has a documented cause
    prediction = counts["prediction"]
    assert prediction["not computed"] == 0, prediction
    assert all(gap.row.gap for gap in known_gaps(verdicts)), "a difference without a documented cause"
    # physics the paper states and the model must reproduce, checked on the responses themselves:
    elastic, thermal = (evaluation.responses[m].metrics for m in ("elastic", "thermal"))
    assert thermal["natural_frequency_hz"] < elastic["natural_frequency_hz"]  # heat softens the mesh
    assert thermal["equilibrium_per_region"]["single"] > elastic["equilibrium_per_region"]["single"]
    assert thermal["kv"] < elastic["kv"]  # the larger thermal damping lowers the overshoot (paper: 1.13 < 1.21)

    # --- figure: each numeric prediction's deviation in units of its argued tolerance (|x| <= 1: within)
    rows = [v for v in verdicts if v.row.kind == "prediction" and isinstance(v.row.check, (Relative, Absolute))]
    tolerance = np.array([v.row.check.tolerance * abs(float(v.row.paper)) if isinstance(v.row.check, Relative)
                          else v.row.check.tolerance for v in rows])
    scaled = np.array([float(v.value) - float(v.row.paper) for v in rows]) / tolerance
    within = np.array([bool(v.within) for v in rows])
    assert np.array_equal(within, np.abs(scaled) <= 1.0 + 1e-12)  # the verdicts are the tolerance test
    limit = 6.0
    shown = np.clip(scaled, -limit, limit)
    figure, ax = plt.subplots(figsize=(7.5, 0.25 * len(rows) + 1.5), constrained_layout=True)
    y = np.arange(len(rows))
    ax.axvspan(-1.0, 1.0, color="tab:green", alpha=0.12, label="within the argued tolerance")
    ax.scatter(shown[within], y[within], color="tab:green", zorder=3, label="prediction within")
    ax.scatter(shown[~within], y[~within], color="tab:red", marker="s", zorder=3,
               label=f"known gap (clipped at ±{limit:g})")
    ax.axvline(0.0, color="0.3", lw=0.8)
    ax.set_yticks(y, [v.row.key for v in rows], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlim(-limit - 0.5, limit + 0.5)
    ax.set_xlabel("(thermogear − paper) / tolerance  [–]")
    ax.set_title(f"Luo & Li (2020): {prediction['within']} of {prediction['total']} predictions within tolerance",
                 fontsize=10)
    figure.legend(loc="outside lower center", ncol=3, fontsize=8)
    path = out / "example_01_luo2019_predictions.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    print(f"predictions: {prediction['within']} of {prediction['total']} within; figure: {path}")
    return {"counts": counts, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
