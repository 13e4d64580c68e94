"""The report section that puts the predictive thermo-elastic model beside the paper's model for the paper's pair."""

from __future__ import annotations

import html

__all__ = ["thermoelastic_section"]

_ROWS = (("mean mesh stiffness per width", "N/(mm·μm)", "mean_mesh_stiffness_n_per_mm_um", "{:.3f}"),
         ("change against the elastic model", "%", "stiffness_change_percent", "{:+.2f}"),
         ("natural frequency f_n", "Hz", "natural_frequency_hz", "{:.0f}"),
         ("normal backlash", "μm", "backlash_normal_um", "{:.1f}"),
         ("loaded static transmission error, peak-to-peak", "μm", "static_transmission_error_peak_to_peak_um",
          "{:.2f}"),
         ("dynamic transmission error, peak-to-peak", "μm", "dte_peak_to_peak_um", "{:.2f}"),
         ("dynamic load factor Kv", "–", "kv", "{:.3f}"))


def _cell(values: dict, key: str, pattern: str) -> str:
    value = values.get(key)
    return "not modelled" if value is None else pattern.format(value)


def thermoelastic_section(data: dict | None) -> str:
    """HTML of the comparison (empty when the stage did not run)."""
    if not data:
        return ""
    from thermogear.luo2020.report.table import row  # the paper's number, from the paper table only
    rows = "".join(
        f"<tr><td>{html.escape(label)}</td><td>{html.escape(unit)}</td>"
        + "".join(f"<td class='num'>{html.escape(_cell(data[name], key, pattern))}</td>"
                  for name in data) + "</tr>"  # the models in the order the comparison ran them
        for label, unit, key, pattern in _ROWS)
    predictive = data["thermoelastic"]
    jamming = predictive.get("jamming_bulk_temperature_c")
    notes = [f"Backlash {predictive['backlash_cold_um']:.1f} μm cold → {predictive['backlash_hot_um']:.1f} μm at the "
             f"operating temperatures" + (f"; the mesh would jam at a bulk temperature of {jamming:.0f} °C." if jamming
                                          else "."),
             "Young's modulus at the tooth temperature: " + " / ".join(f"{value:.1f}" for value in
                                                                      predictive["youngs_modulus_gpa"]) + " GPa."]
    if predictive.get("flags"):
        notes.append("Flagged: " + "; ".join(predictive["flags"]) + ".")
    return ("<h2 id='thermoelastic'>The paper's pair under the predictive thermo-elastic model</h2>"
            "<p>The paper's thermal stiffness (model <code>luo2020</code>) needs the factor X_te, here calibrated to the "
            f"paper's {row('fig4.drop_at_C').paper:g} % drop at the pitch point. The thermo-elastic model "
            "(<code>thermoelastic</code>, the default for any other pair) takes none: Young's modulus at temperature, the gears and the housing expanded, the "
            "backlash and the flank distortion of the non-uniform temperature field. Same pair, same temperatures, "
            "same operating point:</p>"
            "<table><tr><th>quantity</th><th>unit</th><th>elastic</th><th>paper's model (luo2020)</th>"
            "<th>thermo-elastic</th></tr>" + rows + "</table>"
            + "".join(f"<p class='small'>{html.escape(note)}</p>" for note in notes))
