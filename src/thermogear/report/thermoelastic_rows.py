"""The thermo-elastic model's results as table rows beside the elastic model (``thermogear run``'s table and the
report's results table): what the model is for — the operating geometry, the backlash cold and hot, the jamming
temperature and its margin, E(T) and the loaded static transmission error. The numbers are those of
:func:`thermogear.summaries.thermoelastic.thermoelastic_summary`; this module only names and orders them.

Each row is ``(quantity, unit, elastic, thermal, note)``: the elastic column holds the cold mesh (at the reference
temperature, E at 20 °C: what the elastic model computes with), the thermal column the mesh at its operating
temperatures; None where a quantity has no elastic counterpart.
"""

from __future__ import annotations

__all__ = ["thermoelastic_rows"]


def thermoelastic_rows(summary: dict) -> list[tuple[str, str, float | None, float | None, str]]:
    """Rows of the thermo-elastic summary (module docstring)."""
    cold, hot = summary["cold"], summary["operating"]
    rows = [("operating centre distance", "mm", cold["centre_distance_mm"], hot["centre_distance_mm"], ""),
            ("operating pressure angle", "°", cold["pressure_angle_deg"], hot["pressure_angle_deg"], ""),
            ("contact ratio at temperature", "–", cold["contact_ratio"], hot["contact_ratio"], ""),
            ("normal backlash", "μm", cold["backlash_normal_um"], hot["backlash_normal_um"],
             "cold: at the reference temperature; thermal: at the operating temperatures"
             + ("; of a helical pair along the transverse line of action, j_bn/cos β_b" if "helical" in summary
                else ""))]
    for gear in ("pinion", "wheel"):
        rows.append((f"Young's modulus E(T), {gear}", "GPa", summary["elastic"]["youngs_modulus_gpa"][gear],
                     summary["youngs_modulus_gpa"][gear], ""))
    elastic_ste, ste = summary["elastic"]["loaded_transmission_error_um"], summary["loaded_transmission_error_um"]
    rows += [("loaded static transmission error, mean", "μm", elastic_ste["mean"], ste["mean"], ""),
             ("loaded static transmission error, peak-to-peak", "μm", elastic_ste["peak_to_peak"],
              ste["peak_to_peak"], "")]
    if "helical" in summary:  # the slice model's load along the face (summaries.helical)
        helical = summary["helical"]
        cold_face, hot_face = helical["cold"], helical["hot"]
        rows += [("temperature across the face, outlet − inlet", "K", None, helical["face_gradient_k"],
                  "temperature.face_gradient_k"),
                 ("face load factor max w̄/mean w̄", "–", cold_face["face_load_factor"], hot_face["face_load_factor"],
                  "the load distribution across the face (ISO 6336-1's K_Hβ describes it)"),
                 ("load centre from the outlet-side end face", "mm", cold_face["load_centre_mm"],
                  hot_face["load_centre_mm"], "")]
    jamming, margin = summary["jamming_bulk_temperature_c"], summary["jamming_margin_k"]
    note = "" if jamming is not None else "the backlash does not close at any bulk temperature the model allows"
    rows += [("jamming bulk temperature", "°C", None, jamming, note),
             ("jamming margin above the operating bulk temperature", "K", None, margin, "")]
    return rows
