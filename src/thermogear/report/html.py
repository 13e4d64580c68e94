"""``report.html``: one self-contained page (figures embedded as base64 PNG, inline CSS, no script, no network)."""

from __future__ import annotations

import base64
import html
from datetime import datetime, timezone

from thermogear.report.figures import FIGURES
from thermogear.luo2020.report.checks import format_value
from thermogear.report.drivetrain_section import drivetrain_section
from thermogear.report.helical_section import helical_section
from thermogear.report.thermoelastic_section import thermoelastic_section

__all__ = ["render_report"]

_CSS = """
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;max-width:1180px;margin:2em auto;padding:0 1em;
color:#1d232a;line-height:1.45}
h1{font-size:1.6em;margin-bottom:.2em}h2{border-bottom:2px solid #dde3ea;padding-bottom:.2em;margin-top:2em}
.meta{color:#56606b;font-size:.92em}table{border-collapse:collapse;width:100%;font-size:.86em;margin:.6em 0}
th,td{border:1px solid #d5dbe1;padding:3px 6px;vertical-align:top}th{background:#eef2f6;text-align:left}
td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}td.nc{max-width:18em}
tr.within td.status{background:#e3f4e6}tr.outside td.status{background:#fde2e1}
tr.notcomputed td.status{background:#fff3cd}.badge{display:inline-block;padding:.15em .6em;border-radius:1em;
margin-right:.4em;font-weight:600}.b-within{background:#e3f4e6}.b-outside{background:#fde2e1}
.b-nc{background:#fff3cd}.alert{background:#fde2e1;border-left:5px solid #c62828;padding:.6em 1em;margin:.6em 0}
.warn{background:#fff8e1;border-left:5px solid #f9a825;padding:.4em 1em;margin:.3em 0;font-size:.88em}
figure{margin:1.4em 0;text-align:center}figure img{max-width:100%;height:auto;border:1px solid #e3e7eb}
figcaption{font-size:.9em;color:#3b4550;margin-top:.3em}.small{font-size:.82em;color:#56606b}
details{margin:.3em 0}code{background:#f2f4f7;padding:0 .25em;border-radius:3px}
#headline{border:2px solid #c9d4df;border-radius:8px;padding:.4em 1em;margin:.6em 0;background:#f7fafc}
.headline{font-size:1.15em;margin:.3em 0}.big{font-size:1.5em;font-weight:700}.case-line{margin:.2em 0;color:#3b4550}
ul.gaps{margin:.2em 0;font-size:.85em;columns:2}ul.gaps li{break-inside:avoid}ul.gaps details{display:inline}
.key-figures{display:flex;gap:.5em;align-items:flex-start}.key-figures img{width:100%;max-width:380px;max-height:260px;object-fit:contain;border:1px solid #e3e7eb}
details.section>summary{font-weight:600;cursor:pointer;padding:.2em 0}
"""


def _e(text) -> str:
    return html.escape(str(text), quote=True)


def _num(value) -> str:
    return _e(format_value(value))


def _case_section(evaluation, toml_text: str) -> str:
    case = evaluation.case
    pair = case.gear_pair
    op = case.operating_point
    facts = [
        ("teeth z1 / z2", f"{pair.pinion.teeth} / {pair.wheel.teeth}"),
        ("module", f"{pair.module * 1e3:g} mm"), ("face width", f"{pair.face_width * 1e3:g} mm"),
        ("centre distance", f"{pair.centre_distance * 1e3:g} mm"), ("contact ratio ε", f"{pair.contact_ratio:.4f}"),
        ("pinion speed", f"{op.speed_rpm:g} rpm"), ("torque", f"{op.torque:.4g} N·m"),
        ("power", f"{op.power / 1e3:.4g} kW"), ("load held", op.load_held), ("static normal load", f"{case.normal_load:.5g} N "
                                                                      f"({case.normal_load / pair.face_width / 1e3:.4g} N/mm)"),
        ("equivalent mass me", f"{case.equivalent_mass:.4g} kg"),
        ("mesh frequency", f"{pair.mesh_frequency(op.speed_rpm):.5g} Hz"),
        ("lubricant", f"{case.lubricant.name}; elastic model oil at {case.lubricant.reference_temperature_c:g} °C"),
        ("temperature input", case.temperature.model), ("damping rule", case.damping.rule),
        ("solution method", evaluation.method),
    ]
    rows = "".join(f"<tr><th>{_e(k)}</th><td>{_e(v)}</td></tr>" for k, v in facts)
    assumptions = "".join(f"<li>{_e(item)}</li>" for item in (*case.assumptions, *case.notes)) or "<li>none stated</li>"
    return (f"<h2 id='case'>The case</h2><p><b>{_e(case.title or case.name)}</b><br>"
            f"<span class='small'>source: {_e(case.citation or case.source)}</span></p>"
            f"<table style='width:auto'>{rows}</table><h3>Assumptions (what the source leaves open)</h3>"
            f"<ul>{assumptions}</ul><details><summary>case file (TOML)</summary><pre>{_e(toml_text)}</pre></details>")


def _figures_section(pngs: dict[str, bytes], missing: dict[str, str], remarks: dict[str, str]) -> str:
    parts = ["<h2 id='figures'>Figures</h2>"]
    for name, caption in FIGURES.items():
        if name in pngs:
            data = base64.b64encode(pngs[name]).decode("ascii")
            parts.append(f"<figure id='{name}'><img alt='{_e(caption)}' src='data:image/png;base64,{data}'>"
                         f"<figcaption>{_e(caption)} <span class='small'>(figures/{name}.png, .svg)</span>"
                         f"{'<br>' + _e(remarks[name]) if name in remarks else ''}</figcaption></figure>")
        elif name in missing:
            parts.append(f"<p class='warn'><b>{_e(name)}</b> not drawn: {_e(missing[name])}</p>")
    return "".join(parts)


def _results_section(results: list[dict]) -> str:
    body = "".join(
        f"<tr><td>{_e(r['quantity'])}</td><td class='num'>{_num(r['elastic']) if r['elastic'] is not None else '—'}"
        f"</td><td class='num'>{_num(r['thermal']) if r['thermal'] is not None else '—'}</td><td>{_e(r['unit'])}</td>"
        f"<td class='small'>{_e(r.get('note', ''))}</td></tr>" for r in results)
    return ("<h2 id='results'>Results</h2><table><tr><th>quantity</th><th>elastic</th><th>thermal</th><th>unit</th>"
            f"<th>note</th></tr>{body}</table>")


def _kind_counts_text(counts: dict) -> str:
    return (f"{counts['within']} within, {counts['outside']} outside, {counts['not computed']} not computed "
            f"of {counts['total']}")


def fe_versus_analytical(evaluation) -> dict | None:
    """Fig. 15 in numbers: the FE thermal drop 1 − kT/ke against the analytical one at the FE points [%], and
    the ratios FE/analytical of ke and kT (None without an FE result or thermal curves)."""
    import numpy as np

    fem, curves = evaluation.fem, evaluation.thermal_curves
    if fem is None or curves is None:
        return None
    gamma = np.asarray(fem["gamma"], float)
    fe_elastic, fe_thermal = np.asarray(fem["elastic"], float), np.asarray(fem["thermal"], float)
    path = np.asarray(curves.curve.gamma, float)
    elastic = np.interp(gamma, path, np.asarray(curves.curve.elastic_stiffness, float))
    thermal = np.interp(gamma, path, np.asarray(curves.curve.stiffness, float))
    fe_drop, drop = 100.0 * (1.0 - fe_thermal / fe_elastic), 100.0 * (1.0 - thermal / elastic)
    return {"fe_drop_percent": [float(fe_drop.min()), float(fe_drop.max())],
            "analytical_drop_percent": [float(drop.min()), float(drop.max())],
            "fe_over_analytical_elastic": [float((fe_elastic / elastic).min()), float((fe_elastic / elastic).max())],
            "fe_over_analytical_thermal": [float((fe_thermal / thermal).min()), float((fe_thermal / thermal).max())]}


def fe_versus_analytical_text(numbers: dict) -> str:
    """One paragraph stating the FE-versus-analytical difference of Fig. 15 as it is."""
    fe, an = numbers["fe_drop_percent"], numbers["analytical_drop_percent"]
    ke, kt = numbers["fe_over_analytical_elastic"], numbers["fe_over_analytical_thermal"]
    return (f"Fig. 15 in numbers: thermogear's FE puts the thermal pair stiffness {fe[0]:.0f}–{fe[1]:.0f} % below the "
            f"elastic one, the analytical model (Eqs. 13–23, X_te calibrated at C) {an[0]:.1f}–{an[1]:.1f} %. The FE "
            f"elastic stiffness is {ke[0]:.2f}–{ke[1]:.2f} × the analytical one, but the FE thermal stiffness is only "
            f"{kt[0]:.2f}–{kt[1]:.2f} × the analytical k_T: the FE confirms the direction of the paper's statement "
            "(k_T below k_e along the whole path), not its size.")


def _headline_section(evaluation, verdicts, pngs: dict[str, bytes]) -> str:
    """The first screen: the case in one line, the headline comparison and the key figures."""
    from thermogear.luo2020.report.table import known_gaps, known_gaps_text, table_counts

    case = evaluation.case
    pair, op = case.gear_pair, case.operating_point
    facts = (f"<b>{_e(case.name)}</b>: z1/z2 {pair.pinion.teeth}/{pair.wheel.teeth}, m {pair.module * 1e3:g} mm, "
             f"b {pair.face_width * 1e3:g} mm, {op.power / 1e3:.4g} kW at {op.speed_rpm:g} rpm, "
             f"ε {pair.contact_ratio:.3f}, load {case.normal_load / pair.face_width / 1e3:.4g} N/mm")
    parts = [f"<section id='headline'><p class='case-line'>{facts}</p>"]
    if verdicts:
        counts = table_counts(verdicts)
        prediction, statement = counts["prediction"], counts["qualitative"]
        gaps = known_gaps(verdicts)
        parts.append(
            f"<p class='headline' id='headline-numbers'><span class='big'>{prediction['within']} of "
            f"{prediction['total']}</span> "
            f"predictions of the paper's numbers within their argued tolerance · "
            f"<span class='big'>{_e(known_gaps_text(verdicts))}</span> · "
            f"{statement['within']} of {statement['total']} qualitative statements reproduced.</p>"
            f"<p class='small'>Not counted above: {counts['input']['total']} input rows (Table 1 and rig data "
            f"transcribed: {_kind_counts_text(counts['input'])}) and {counts['calibration']['total']} calibration "
            f"(X_te set so that the drop at C matches: {_kind_counts_text(counts['calibration'])}).</p>")
        by_cause: dict[str, list[str]] = {}
        for verdict in gaps:
            by_cause.setdefault(verdict.row.gap or verdict.reason or "no documented cause",
                                []).append(verdict.row.key)
        items = "".join(f"<li><b>{_e(', '.join(keys))}</b><details><summary class='small'>cause</summary>"
                        f"<span class='small'>{_e(cause)}</span></details></li>" for cause, keys in by_cause.items())
        parts.append(f"<p><b>Known gaps, by cause</b> (details in the table below):</p><ul class='gaps'>{items}</ul>")
    else:
        parts.append(f"<p class='headline' id='headline-numbers'>{_e(_headline_numbers(evaluation))}</p>")
    keys = [name for name in ("fig4", "fig9", "fig12") if name in pngs]
    if keys:
        thumbs = "".join(f"<a href='#{name}'><img alt='{_e(FIGURES[name])}' title='{_e(FIGURES[name])}' "
                         f"src='data:image/png;base64,{base64.b64encode(pngs[name]).decode('ascii')}'></a>"
                         for name in keys)
        parts.append(f"<div class='key-figures'>{thumbs}</div>")
    parts.append("</section>")
    return "".join(parts)


def _headline_numbers(evaluation) -> str:
    """The headline of a case without the paper table: per model the drivetrain's Kv where the case has a drivetrain
    (the structure it describes; the 1-DOF pair's beside it, labelled), else the pair's, with f_n."""
    metrics = {model: response.metrics for model, response in evaluation.responses.items()}
    drivetrain = evaluation.drivetrain.models if evaluation.drivetrain is not None else {}
    shown = []
    for model, m in metrics.items():
        if "kv" not in m:
            continue
        pair = f"Kv {m['kv']:.3f}" if m["kv"] is not None else "Kv not found"
        if model in drivetrain:
            kv = drivetrain[model].kv
            shown.append(f"{model}: drivetrain Kv {'not found' if kv is None else f'{kv:.3f}'} (1-DOF pair on rigid "
                         f"supports: {pair}, f_n {m['natural_frequency_hz']:.0f} Hz)")
        else:
            shown.append(f"{model}: {pair}, f_n {m['natural_frequency_hz']:.0f} Hz")
    return " · ".join(shown) or "no dynamic response computed"


def _paper_section(verdicts) -> str:
    from thermogear.luo2020.report.table import KIND_MEANING

    head = ("<h2 id='paper'>Every number of the paper beside thermogear's</h2>"
            "<p class='small'>Deviation = (thermogear − paper)/|paper|, or 'inside the range' where the paper gives "
            "only a range or an order of magnitude. Each tolerance is argued (open 'why'). Kinds: "
            + "; ".join(f"<i>{_e(kind)}</i> — {_e(text)}" for kind, text in KIND_MEANING.items())
            + ". Sections holding only inputs are closed.</p>")
    groups: dict[str, list] = {}
    for verdict in verdicts:
        groups.setdefault(verdict.row.section, []).append(verdict)
    blocks = []
    for section, items in groups.items():
        counts = {s: sum(1 for v in items if v.status == s) for s in ("within", "outside", "not computed")}
        evidence = any(v.row.kind in ("prediction", "qualitative") for v in items)
        rows = []
        for v in items:
            row = v.row
            css = v.status.replace(" ", "")
            value = _num(v.value) if v.computed else f"<span class='small'>not computed: {_e(v.reason)}</span>"
            value_class = "num" if v.computed else "nc"
            note = " ".join(text for text in (row.note, f"Known gap: {row.gap}" if row.gap else "",
                                              v.reason if v.computed else "") if text)
            rows.append(
                f"<tr class='{css}' id='row-{_e(row.key)}'><td>{_e(row.quantity)}<br><span class='small'>"
                f"<code>{_e(row.key)}</code></span></td><td>{_e(row.kind)}</td>"
                f"<td class='num'>{_e(row.paper_text)}</td><td class='{value_class}'>{value}</td><td>{_e(row.unit)}"
                f"</td><td class='num'>{_e(v.deviation_text)}</td><td>{_e(row.tolerance_text)}<details><summary "
                f"class='small'>why</summary><span class='small'>{_e(row.argument)}</span></details></td>"
                f"<td class='status'>{_e(v.status)}</td><td class='small'>{_e(note)}</td></tr>")
        summary = (f"{_e(section)} — {len(items)} rows: {counts['within']} within, {counts['outside']} outside"
                   + (f", {counts['not computed']} not computed" if counts["not computed"] else ""))
        blocks.append(f"<details class='section'{' open' if evidence else ''}><summary>{summary}</summary><table>"
                      "<tr><th>quantity</th><th>kind</th><th>paper</th><th>thermogear</th><th>unit</th>"
                      "<th>deviation</th><th>tolerance</th><th>status</th><th>note</th></tr>" + "".join(rows)
                      + "</table></details>")
    return head + "".join(blocks)


def render_report(evaluation, *, version: str, toml_text: str, pngs: dict[str, bytes], missing_figures: dict,
                  results: list[dict], verdicts: list, messages: list[str], citations: list) -> str:
    """The HTML text of the report."""
    case = evaluation.case
    generated = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    title = (f"thermogear reproduces Luo & Li (2020)" if verdicts else f"thermogear report: {case.title or case.name}")
    parts = [f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>{_e(title)}</title>"
             f"<meta name='viewport' content='width=device-width, initial-scale=1'><style>{_CSS}</style></head><body>",
             f"<h1>{_e(title)}</h1><p class='meta'>case <b>{_e(case.name)}</b> · thermogear {_e(version)} · "
             f"{_e(generated)} · method {_e(evaluation.method)}</p>"]
    for message in messages:
        # a model check (a result the user should weigh) is a note; contact loss or instability an alert
        kind = "warn" if ": check — " in message else "alert"
        parts.append(f"<div class='{kind}'>{_e(message)}</div>")
    if evaluation.warnings:  # near the top as well as at the end (issue 36)
        parts.append(f"<details class='warn'><summary>{len(evaluation.warnings)} warning(s) raised during the run "
                     "(also listed at the end)</summary>"
                     + "".join(f"<p class='small'>{_e(w)}</p>" for w in evaluation.warnings) + "</details>")
    nav = ["<a href='#case'>case</a>", "<a href='#figures'>figures</a>", "<a href='#results'>results</a>"]
    if evaluation.case.drivetrain is not None:
        nav.append("<a href='#drivetrain'>drivetrain</a>")
    if evaluation.warnings:
        nav.append("<a href='#warnings'>warnings</a>")
    if verdicts:
        nav += ["<a href='#paper'>paper vs thermogear</a>"]
    if "drivetrain_layout" in pngs:  # a [drivetrain] case: its pictures among the figures
        nav.insert(2, "<a href='#drivetrain_layout'>drivetrain pictures</a>")
    nav.append("<a href='#references'>references</a>")
    parts.insert(2, _headline_section(evaluation, verdicts, pngs))
    if verdicts:
        parts.append("<p>Luo B., Li W., <i>Investigation on the influence of heat on the dynamic characteristics of a "
                     "gear transmission system</i>, Engineering Failure Analysis (2020), "
                     "doi:10.1016/j.engfailanal.2020.104724. Every figure and every number the paper reports is "
                     "recomputed below from its Table 1 and the assumptions listed with the case.</p>")
    parts.append("<p class='small'>" + " · ".join(nav) + "</p>")
    parts.append(_case_section(evaluation, toml_text))
    fe_numbers = fe_versus_analytical(evaluation)
    parts.append(_figures_section(pngs, missing_figures,
                                  {"fig15": fe_versus_analytical_text(fe_numbers)} if fe_numbers else {}))
    parts.append(_results_section(results))
    parts.append(thermoelastic_section(evaluation.thermoelastic))
    parts.append(helical_section(evaluation.thermoelastic_summary))
    parts.append(drivetrain_section(evaluation.drivetrain, evaluation.problems.get("drivetrain")))
    if verdicts:
        parts.append(_paper_section(verdicts))
    if evaluation.problems:
        parts.append("<h2>Stages not computed</h2><ul>" + "".join(
            f"<li><b>{_e(k)}</b>: {_e(v)}</li>" for k, v in evaluation.problems.items()) + "</ul>")
    if evaluation.warnings:
        parts.append("<h2 id='warnings'>Warnings raised during the run</h2>" + "".join(
            f"<div class='warn'>{_e(w)}</div>" for w in evaluation.warnings))
    timing = ", ".join(f"{k} {v:.2f} s" for k, v in evaluation.timings.items())
    parts.append(f"<p class='small'>Run times: {_e(timing)}.</p>")
    refs = "".join(f"<li id='ref-{_e(ref.key)}'>{_e(ref.formatted())}"
                   f"{' <span class=small>— ' + _e(ref.used_for) + '</span>' if ref.used_for else ''}</li>"
                   for ref in citations)
    parts.append(f"<h2 id='references'>References</h2><ol>{refs}</ol>")
    parts.append("<p class='small'>Files beside this page: <code>figures/*.png</code>, <code>figures/*.svg</code>, "
                 "<code>results.nc</code> (xarray/netCDF: every curve, the case file and the version), "
                 "<code>summary.json</code> (the tables).</p></body></html>")
    return "".join(parts)
