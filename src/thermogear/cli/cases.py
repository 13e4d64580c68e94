"""`thermogear cases` and `thermogear schema`: the built-in parameter sets and the case-file schema."""

from __future__ import annotations

import json

import typer
from rich.table import Table

from thermogear.case import load_case, parameter_set_names
from thermogear.cli.app import app, console, print_json
from thermogear.schema import CaseFile


@app.command()
def cases(as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout")) -> None:
    """List the built-in parameter sets with their sources."""
    rows = []
    for name in parameter_set_names():
        case = load_case(name)
        rows.append({"name": name, "title": case.title, "citation": case.citation,
                     "assumptions": list(case.assumptions)})
    if as_json:
        print_json({"cases": rows})
        return
    table = Table(title="Built-in parameter sets", show_lines=True)
    table.add_column("name", style="bold")
    table.add_column("title")
    table.add_column("source")
    for row in rows:
        table.add_row(row["name"], row["title"], row["citation"])
    console.print(table)
    console.print("Load one with [bold]load_case(name)[/] or any command: [bold]thermogear stiffness luo2019[/]")


@app.command()
def schema() -> None:
    """Print the JSON schema of case files (every key, its unit and range)."""
    print(json.dumps(CaseFile.model_json_schema(), indent=2))
