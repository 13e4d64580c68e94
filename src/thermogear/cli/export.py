"""`thermogear export SOURCE`: a sweep store or a report's results file as CSV (and the CSV of `run --csv`)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import typer

from thermogear.cli.app import app, error_console
from thermogear.errors import CaseError

#: Groups of a report's results.nc (the steady responses are the default: one row per time sample and model); a
#: drivetrain case adds ``drivetrain_elastic`` and ``drivetrain_thermal`` (its responses over one mesh period).
RESPONSE_GROUPS = ("elastic_steady", "thermal_steady", "elastic_transient", "thermal_transient",
                   "drivetrain_elastic", "drivetrain_thermal")
_FIRST_LINE = "# thermogear "


def check_csv_target(path: Path, force: bool, option: str = "--out") -> None:
    """Refuse an output that exists, unless ``force`` and it is a CSV thermogear wrote (its first line); checked
    before any work."""
    if path.is_dir():
        raise CaseError(option, str(path), "a file name", "a folder of that name exists")
    if not path.exists():
        if not path.parent.is_dir():
            raise CaseError(option, str(path), "a file in an existing folder", "the folder does not exist")
        return
    if not force:
        raise CaseError(option, str(path), "a file that does not exist yet, or --force",
                        "the file exists and is not overwritten silently")
    try:
        with path.open(encoding="utf-8") as stream:
            first = stream.readline()
    except (OSError, UnicodeDecodeError):
        first = ""
    if not first.startswith(_FIRST_LINE):
        raise CaseError(option, str(path), "a CSV file thermogear wrote", "thermogear replaces only its own files")


def _groups_in(path: Path) -> list[str]:
    """The groups a results.nc holds (empty where it cannot be read)."""
    try:
        import h5netcdf  # noqa: PLC0415

        with h5netcdf.File(str(path), "r") as handle:
            return sorted(handle.groups)
    except (OSError, ImportError, ValueError):
        return []


def _header(source: str, attrs: dict, what: str, left_out: list[str]) -> list[str]:
    from thermogear import __version__  # noqa: PLC0415

    lines = [f"thermogear {__version__} export of {source} ({what})"]
    case = attrs.get("case_name") or attrs.get("case")  # a linear store's / a branch store's attribute
    if case is None and "case_json" in attrs:
        try:
            case = json.loads(attrs["case_json"]).get("case", {}).get("name")
        except (ValueError, AttributeError):
            case = None
    if case:
        source_text = str(attrs.get("case_source") or "")
        lines.append(f"case: {case}" + (f" ({source_text})" if source_text and source_text != case else ""))
    if attrs.get("load"):  # which load the points hold (issue 24: every output names it)
        note = attrs.get("load_note")
        lines.append(f"load held: {attrs['load']}" + (f" ({note})" if note else ""))
    if attrs.get("thermogear_version"):
        lines.append(f"computed by thermogear {attrs['thermogear_version']}")
    if attrs.get("incomplete"):
        lines.append(f"INCOMPLETE: {attrs['incomplete']}")
    lines.append("units in brackets after each column name; nan: no value at that point (see the stable/valid "
                 "columns)")
    if left_out:
        lines.append("not in this table (other dimensions; --dimension chooses): " + ", ".join(left_out))
    return lines


def responses_csv(path: Path | None, responses: dict, *, case_name: str, case_source: str, load_held: str) -> int:
    """The steady responses of ``run`` (or any responses by model) as one CSV: a row per time sample and model,
    headed by the case's name, its source and the load the point holds (``OperatingPoint.load_held``)."""
    from thermogear.report.csv_table import dataset_rows, write_csv  # noqa: PLC0415

    blocks = [({"model": name}, dataset_rows(response.to_xarray(), ("time",))) for name, response in
              responses.items()]
    left_out = sorted({name for _, block in blocks for name in block.left_out})
    attributes = {"case_name": case_name, "case_source": case_source, "load": load_held}
    header = _header(f"thermogear run {case_name}", attributes,
                     "steady responses, one row per time sample and model", left_out)
    return write_csv(path if path is not None else sys.stdout, header, blocks)


def _is_zarr_store(path: Path) -> bool:
    return path.is_dir() and any((path / name).exists() for name in (".zgroup", ".zattrs", "zarr.json"))


@app.command()
def export(
    source: Path = typer.Argument(..., metavar="SOURCE", help="a sweep store (.zarr), a report folder (thermogear "
                                                              "run/reproduce --out) or its results.nc"),
    out: Path = typer.Option(None, "--out", help="the CSV file to write (default: standard output)"),
    group: str = typer.Option(None, "--group", help="results.nc: root (curves along the path and the mesh "
                                                    "cycle) or one response group: " + " | ".join(RESPONSE_GROUPS)
                                                    + " (default: both steady responses)"),
    dimension: str = typer.Option(None, "--dimension", help="the dimension the rows run along (default: every "
                                                            "swept parameter of a store, time of a response)"),
    force: bool = typer.Option(False, "--force", help="replace an existing --out file that thermogear wrote"),
) -> None:
    """Write a sweep store or a report's results file as CSV: one row per point or per time sample, the units in
    the column names, the case and the version in comment lines (# …) on top."""
    if out is not None:
        check_csv_target(out, force)
    import xarray as xr  # noqa: PLC0415

    from thermogear.report.csv_table import dataset_rows, write_csv  # noqa: PLC0415

    if source.is_dir() and (source / "results.nc").is_file():
        source = source / "results.nc"
    dimensions = None if dimension is None else (dimension,)
    if _is_zarr_store(source):
        if group is not None:
            raise CaseError("--group", group, "no --group for a sweep store", "a store has one table")
        from thermogear.sweep.task_store import store_is_complete  # noqa: PLC0415

        dataset = xr.open_dataset(source, engine="zarr")
        complete, missing = store_is_complete(dataset)
        dataset = dataset.drop_vars(["chunk_done", "task_done", "branch_state"], errors="ignore")
        if dimensions is None and dataset.attrs.get("row_dimensions"):  # a store that names its grid
            dimensions = tuple(str(dataset.attrs["row_dimensions"]).split(","))
        datasets = [({}, dataset, {**dataset.attrs, **({} if complete else {"incomplete": missing})})]
        what = "sweep store, one row per point"
        if not complete:
            from thermogear.cli.console import print_warning  # noqa: PLC0415

            print_warning(f"{source} is incomplete: {missing}", error_console)
    elif source.is_file() and source.suffix == ".nc":
        groups = [group] if group is not None else ["elastic_steady", "thermal_steady"]
        allowed = ("root", *RESPONSE_GROUPS)
        present = _groups_in(source)
        for name in groups:
            if name not in allowed:
                raise CaseError("--group", name, " | ".join(allowed), "no such group in a report's results.nc")
            if present and name != "root" and name not in present:
                raise CaseError("--group", name, " | ".join(["root", *present]),
                                "this results.nc does not hold that group (a drivetrain group comes with a case that "
                                "has a [drivetrain] section)")
        root = xr.open_dataset(source, engine="h5netcdf")
        datasets = []
        for name in groups:
            try:
                data = root if name == "root" else xr.open_dataset(source, engine="h5netcdf", group=name)
            except OSError as error:
                raise CaseError("--group", name, " | ".join(allowed), f"not in this file ({error})") from None
            datasets.append(({} if group is not None else {"model": name.split("_")[0]}, data, root.attrs))
            if dimensions is None and name.startswith("drivetrain_") and "time" in data.dims:
                dimensions = ("time",)  # one row per time sample; the per-bearing arrays are named as left out
        what = f"group {group}" if group is not None else "steady responses, one row per time sample and model"
    else:
        raise CaseError("SOURCE", str(source), "a sweep store (.zarr folder), a report folder or a results.nc file",
                        "not found or not a thermogear result")
    blocks = []
    for label, data, _ in datasets:
        for name in dimensions or ():
            if name not in data.dims:
                raise CaseError("--dimension", name, ", ".join(map(str, data.dims)), "no such dimension")
        blocks.append((label, dataset_rows(data, dimensions)))
    left_out = sorted({name for _, block in blocks for name in block.left_out})
    header = _header(str(source), dict(datasets[0][2]), what, left_out)
    rows = write_csv(out if out is not None else sys.stdout, header, blocks)
    if out is not None:
        error_console.print(f"wrote {rows} rows to {out}", highlight=False)
