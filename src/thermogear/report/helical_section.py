"""The report's helical section: the contact lines on the plane of action, the load along the face cold and hot,
the mesh stiffness and the loaded static transmission error over one mesh period — drawn and tabled from the
``helical`` part of the thermo-elastic summary (:func:`thermogear.summaries.helical.helical_thermoelastic_summary`);
no physics here."""

from __future__ import annotations

import html

__all__ = ["draw_helical", "helical_figure", "helical_figure_absent", "helical_section"]

_STYLE = {"cold": {"color": "tab:blue", "ls": "--", "label": "elastic (cold)"},
          "hot": {"color": "tab:red", "ls": "-", "label": "thermo-elastic (hot)"}}


def helical_figure_absent(evaluation) -> str | None:
    """Why the report has no helical figure: "" for a spur pair (nothing to draw, nothing missing), the reason where
    the thermo-elastic summary has no helical part, None where it can be drawn."""
    if evaluation.case.helical_pair is None:
        return ""
    if not (evaluation.thermoelastic_summary or {}).get("helical"):
        return evaluation.problem("thermal stiffness") or "the thermo-elastic model was not run"
    return None


def draw_helical(evaluation):
    """The report's helical figure of an evaluation (:func:`helical_figure` of its thermo-elastic summary)."""
    return helical_figure(evaluation.thermoelastic_summary["helical"])


def helical_figure(helical: dict):
    """Four panels: the zone of action with the contact lines at phase 0; the mean line load across the face cold
    and hot with the temperature rise; K_t per width over one period; the loaded static transmission error."""
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(2, 2, figsize=(9.0, 6.4), constrained_layout=True)
    zone, cold = helical["cold"]["zone_of_action_mm"], helical["cold"]
    ax = axes[0, 0]
    ax.add_patch(plt.Rectangle((0.0, 0.0), zone["path_length"], zone["face_width"], fill=False, color="0.4"))
    for (s_start, z_start), (s_end, z_end) in cold["contact_lines_at_phase_0_mm"]:
        ax.plot([s_start, s_end], [z_start, z_end], color="tab:green")
    ax.set_xlim(-0.05 * zone["path_length"], 1.05 * zone["path_length"])
    ax.set_ylim(-0.05 * zone["face_width"], 1.05 * zone["face_width"])
    ax.set_xlabel("path of contact from A [mm]")
    ax.set_ylabel("face z from the outlet side [mm]")
    ax.set_title("contact lines on the plane of action", fontsize=9)
    ax = axes[0, 1]
    for state in ("cold", "hot"):
        ax.plot(helical[state]["z_mm"], helical[state]["mean_line_load_n_per_mm"], **_STYLE[state])
    ax.set_xlabel("face z from the outlet side [mm]")
    ax.set_ylabel("mean line load [N/mm]")
    ax.set_title(f"load along the face (gradient {helical['face_gradient_k']:g} K)", fontsize=9)
    twin = ax.twinx()
    twin.plot(helical["hot"]["z_mm"], helical["hot"]["face_temperature_rise_k"], color="0.5", lw=0.8,
              label="ΔT across the face")
    twin.set_ylabel("ΔT across the face [K]")
    for ax, key, label in ((axes[1, 0], "mesh_stiffness_curve_n_per_mm_um", "K_t per width [N/(mm·μm)]"),
                           (axes[1, 1], "static_transmission_error_um", "loaded static TE [μm]")):
        for state in ("cold", "hot"):
            ax.plot(helical[state]["phase_mm"], helical[state][key], **_STYLE[state])
        ax.set_xlabel("mesh phase along the transverse path [mm]")
        ax.set_ylabel(label)
    axes[0, 1].legend()
    axes[1, 0].legend()
    return figure


def helical_section(summary: dict | None) -> str:
    """HTML of the helical pair's numbers (empty for a spur pair or without the thermo-elastic model)."""
    if not summary or "helical" not in summary:
        return ""
    helical = summary["helical"]
    geometry = helical["geometry"]
    lengths = geometry["contact_line_length_mm"]
    rows = [("helix angle β / base helix angle β_b", "°",
             f"{geometry['helix_angle_deg']:.3f} / {geometry['base_helix_angle_deg']:.3f}"),
            ("hand of the pinion", "", geometry["hand"]),
            ("module m_n / m_t", "mm", f"{geometry['normal_module_mm']:.4f} / {geometry['transverse_module_mm']:.4f}"),
            ("pressure angle α_n / α_t", "°",
             f"{geometry['normal_pressure_angle_deg']:.3f} / {geometry['transverse_pressure_angle_deg']:.3f}"),
            ("ε_α / ε_β / ε_γ", "–", f"{geometry['transverse_contact_ratio']:.4f} / {geometry['overlap_ratio']:.4f}"
                                     f" / {geometry['total_contact_ratio']:.4f}"),
            ("contact-line length mean / min / max", "mm",
             f"{lengths['mean']:.2f} / {lengths['min']:.2f} / {lengths['max']:.2f}")]
    for state, label in (("cold", "elastic (cold)"), ("hot", "thermo-elastic (hot)")):
        face = helical[state]
        stiffness = face["mesh_stiffness_n_per_mm_um"]
        rows += [(f"K_t min / mean / max, {label}", "N/(mm·μm)",
                  f"{stiffness['min']:.3f} / {stiffness['mean']:.3f} / {stiffness['max']:.3f}"),
                 (f"face load factor max w̄/mean w̄, {label}", "–", f"{face['face_load_factor']:.3f}"),
                 (f"loaded static TE mean / peak-to-peak, {label}", "μm",
                  f"{face['static_transmission_error_mean_um']:.2f} / "
                  f"{face['static_transmission_error_peak_to_peak_um']:.2f}")]
    body = "".join(f"<tr><td>{html.escape(name)}</td><td>{html.escape(unit)}</td><td class='num'>"
                   f"{html.escape(value)}</td></tr>" for name, unit, value in rows)
    return ("<h2 id='helical'>Helical pair</h2><p>The pair as thin transverse slices across the face (each the "
            "potential-energy stiffness of ISO 6336-1's virtual spur pair of the normal section), cold under the "
            "elastic model and hot under the thermo-elastic one, whose temperature varies linearly across the face "
            f"by {helical['face_gradient_k']:g} K (outlet minus inlet side) and distorts the lead "
            "(docs/helical.md).</p><table><tr><th>quantity</th><th>unit</th><th>value</th></tr>" + body
            + "</table>")
