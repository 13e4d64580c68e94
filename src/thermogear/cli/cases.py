"""`thermogear cases` and `thermogear schema`: the built-in parameter sets and the case-file schema."""

from __future__ import annotations

import json
import tomllib
from importlib import resources

import typer

from thermogear.cli.app import app, console, print_json


def parameter_set_headers() -> list[dict]:
    """Name, title, citation and assumptions of every built-in parameter set, read from the ``[case]`` table of
    its file without building the case (``thermogear cases`` must not import NumPy and pydantic to list them; the
    sets themselves are validated by their own tests, and this list is checked equal to ``load_case``'s)."""
    folder = resources.files("thermogear.parameter_sets")
    rows = []
    for path in sorted((p for p in folder.iterdir() if p.name.endswith(".toml")), key=lambda p: p.name):
        header = tomllib.loads(path.read_text(encoding="utf-8")).get("case", {})
        rows.append({"name": path.name[:-5], "title": header.get("title", ""),
                     "citation": header.get("citation", ""), "assumptions": list(header.get("assumptions", []))})
    return rows


@app.command()
def cases(as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout")) -> None:
    """List the built-in parameter sets with their sources."""
    rows = parameter_set_headers()
    if as_json:
        print_json({"cases": rows})
        return
    from rich.table import Table  # noqa: PLC0415

    table = Table(title="Built-in parameter sets", show_lines=True)
    table.add_column("name", style="bold")
    table.add_column("title")
    table.add_column("source")
    for row in rows:
        table.add_row(row["name"], row["title"], row["citation"])
    console.print(table)
    console.print("Load one with load_case(name) or any command: thermogear stiffness luo2019")


@app.command()
def schema(
    section: str = typer.Argument(None, metavar="[SECTION]", help="only this section and the tables under it, e.g. "
                                                                  "gears or gears.pinion"),
    as_json: bool = typer.Option(False, "--json", help="the JSON schema of case files (for editors and tools)"),
) -> None:
    """Print every case-file key with its unit, type, allowed range, default and meaning (one table per section).

    ``--json`` prints the JSON schema instead (pydantic's, the one a case file is validated against).
    """
    if as_json:
        from thermogear.schema import CaseFile  # noqa: PLC0415

        print(json.dumps(CaseFile.model_json_schema(), indent=2))
        return
    from rich import box  # noqa: PLC0415
    from rich.table import Table  # noqa: PLC0415
    from rich.text import Text  # noqa: PLC0415

    from thermogear.cli.app import first_sentence  # noqa: PLC0415
    from thermogear.schema.reference import case_file_sections  # noqa: PLC0415

    sections = case_file_sections()
    if section is not None:
        chosen = [item for item in sections if item.name == section or item.name.startswith(f"{section}.")]
        if not chosen:
            from thermogear.errors import CaseError, closest_key  # noqa: PLC0415

            names = [item.name for item in sections]
            suggestion = closest_key(section, names)
            raise CaseError("section", section, ", ".join(names),
                            "no such case-file section" + (f" (did you mean '{suggestion}'?)" if suggestion else ""))
        sections = chosen
    for item in sections:
        console.print(Text(f"[{item.name}]" + (" (required)" if item.required else "") + ": "
                           + first_sentence(item.description), style="bold"))
        table = Table(box=box.SIMPLE_HEAD, pad_edge=False)
        table.add_column("key", no_wrap=True)
        table.add_column("unit", no_wrap=True)
        table.add_column("type", max_width=26)
        table.add_column("allowed", no_wrap=True)
        table.add_column("default", max_width=16)
        table.add_column("meaning", min_width=30)
        for key in item.keys:
            table.add_row(key.key, key.unit, key.kind, key.allowed, key.default_text, key.meaning)
        console.print(table)
    console.print("Units: – is a dimensionless number. The whole schema as JSON: thermogear schema --json")
