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
def schema() -> None:
    """Print the JSON schema of case files (every key, its unit and range)."""
    from thermogear.schema import CaseFile  # noqa: PLC0415

    print(json.dumps(CaseFile.model_json_schema(), indent=2))
