"""``report.html``: one self-contained page (figures embedded as base64 PNG, inline CSS, no script, no network)."""

from __future__ import annotations

import base64
import html
from datetime import datetime, timezone

from thermogear.report.figures import FIGURES
from thermogear.report.paper_table import format_value

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
        ("power", f"{op.power / 1e3:.4g} kW"), ("static normal load", f"{case.normal_load:.5g} N "
                                                                      f"({case.normal_load / pair.face_width / 1e3:.4g} N/mm)"),
        ("equivalent mass me", f"{case.equivalent_mass:.4g} kg"),
        ("mesh frequency", f"{pair.mesh_frequency(op.speed_rpm):.5g} Hz"),
        ("lubricant", f"{case.lubricant.name}; elastic model oil at {case.lubricant.reference_temperature_c:g} °C"),
        ("temperature input", case.temperature.model), ("damping rule", case.damping.rule),
        ("solution method", evaluation.method),
    ]
    rows = "".join(f"<tr><th>{_e(k)}</th><td>{_e(v)}</td></tr>" for k, v in facts)
    assumptions = "".join(f"<li>{_e(item)}</li>" for item in case.assumptions) or "<li>none stated</li>"
    return (f"<h2 id='case'>The case</h2><p><b>{_e(case.title or case.name)}</b><br>"
            f"<span class='small'>source: {_e(case.citation or case.source)}</span></p>"
            f"<table style='width:auto'>{rows}</table><h3>Assumptions (what the source leaves open)</h3>"
            f"<ul>{assumptions}</ul><details><summary>case file (TOML)</summary><pre>{_e(toml_text)}</pre></details>")


def _figures_section(pngs: dict[str, bytes], missing: dict[str, str]) -> str:
    parts = ["<h2 id='figures'>Figures</h2>"]
    for name, caption in FIGURES.items():
        if name in pngs:
            data = base64.b64encode(pngs[name]).decode("ascii")
            parts.append(f"<figure id='{name}'><img alt='{_e(caption)}' src='data:image/png;base64,{data}'>"
                         f"<figcaption>{_e(caption)} <span class='small'>(figures/{name}.png, .svg)</span>"
                         f"</figcaption></figure>")
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


def _paper_section(verdicts) -> str:
    counts = {s: sum(1 for v in verdicts if v.status == s) for s in ("within", "outside", "not computed")}
    head = ("<h2 id='paper'>Every number of the paper beside thermogear's</h2>"
            f"<p><span class='badge b-within'>{counts['within']} within</span>"
            f"<span class='badge b-outside'>{counts['outside']} outside</span>"
            f"<span class='badge b-nc'>{counts['not computed']} not computed</span> of {len(verdicts)} rows. "
            "Deviation = (thermogear − paper)/|paper|. Each tolerance is argued (open a row's argument); rows of kind "
            "<i>input</i> check that the case carries the paper's data, <i>measured</i> rows check thermogear's copy "
            "of the rig measurements, <i>calibration</i> rows were used to set a parameter.</p>")
    rows = []
    for v in verdicts:
        row = v.row
        css = v.status.replace(" ", "")
        value = _num(v.value) if v.computed else f"<span class='small'>not computed: {_e(v.reason)}</span>"
        value_class = "num" if v.computed else "nc"
        note = row.note
        if v.computed and v.reason:
            note = f"{note} {v.reason}".strip()
        rows.append(
            f"<tr class='{css}' id='row-{_e(row.key)}'><td>{_e(row.quantity)}<br><span class='small'>{_e(row.section)}"
            f" · {_e(row.kind)} · <code>{_e(row.key)}</code></span></td><td class='num'>{_e(row.paper_text)}</td>"
            f"<td class='{value_class}'>{value}</td><td>{_e(row.unit)}</td><td class='num'>{_e(v.deviation_text)}</td>"
            f"<td>{_e(row.tolerance_text)}<details><summary class='small'>why</summary><span class='small'>"
            f"{_e(row.argument)}</span></details></td><td class='status'>{_e(v.status)}</td>"
            f"<td class='small'>{_e(note)}</td></tr>")
    return (head + "<table><tr><th>quantity</th><th>paper</th><th>thermogear</th><th>unit</th><th>deviation</th>"
            "<th>tolerance</th><th>status</th><th>note</th></tr>" + "".join(rows) + "</table>")


def _differences_section(verdicts) -> str:
    items = [v for v in verdicts if v.status != "within" or (v.row.note and v.row.kind == "result")]
    if not items:
        return ""
    lines = []
    for v in items:
        if v.status == "within" and not v.row.note:
            continue
        what = {"within": "within its tolerance", "outside": "OUTSIDE its tolerance",
                "not computed": "not computed"}[v.status]
        cause = v.row.note or "no documented cause yet"
        if v.status == "not computed":
            cause = v.reason
        lines.append(f"<li><b>{_e(v.row.quantity)}</b> ({what}): {_e(cause)}</li>")
    return ("<h2 id='differences'>Where thermogear differs from the paper, and why</h2><ul>" + "".join(lines)
            + "</ul>")


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
    if verdicts:
        parts.append("<p>Luo B., Li W., <i>Investigation on the influence of heat on the dynamic characteristics of a "
                     "gear transmission system</i>, Engineering Failure Analysis (2020), "
                     "doi:10.1016/j.engfailanal.2020.104724. Every figure and every number the paper reports is "
                     "recomputed below from its Table 1 and the assumptions listed with the case.</p>")
    for message in messages:
        parts.append(f"<div class='alert'>{_e(message)}</div>")
    nav = ["<a href='#case'>case</a>", "<a href='#figures'>figures</a>", "<a href='#results'>results</a>"]
    if verdicts:
        nav += ["<a href='#paper'>paper vs thermogear</a>", "<a href='#differences'>differences</a>"]
    nav.append("<a href='#references'>references</a>")
    parts.append("<p class='small'>" + " · ".join(nav) + "</p>")
    parts.append(_case_section(evaluation, toml_text))
    parts.append(_figures_section(pngs, missing_figures))
    parts.append(_results_section(results))
    if verdicts:
        parts.append(_paper_section(verdicts))
        parts.append(_differences_section(verdicts))
    if evaluation.problems:
        parts.append("<h2>Stages not computed</h2><ul>" + "".join(
            f"<li><b>{_e(k)}</b>: {_e(v)}</li>" for k, v in evaluation.problems.items()) + "</ul>")
    if evaluation.warnings:
        parts.append("<h2>Warnings raised during the run</h2>" + "".join(
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
