"""Command-line interface: parses arguments, calls the API, prints. No physics here."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Annotated

import typer

from .errors import GovoptError

app = typer.Typer(add_completion=False, no_args_is_help=False,
                  help="Design and evaluate governor springs (Hamabe's shaft governor).")

SPECS = Path(__file__).resolve().parent.parent / "specs"
DEFAULT_EVALUATE = SPECS / "hamabe-a.toml"
DEFAULT_DESIGN = SPECS / "hamabe-design.toml"
REPORTS = Path(__file__).resolve().parent.parent / "reports"

SpecArg = Annotated[Path | None, typer.Argument(help="Spec file (TOML with units).",
                                               show_default=False)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print a JSON object in SI units.")]


@app.callback()
def _root() -> None:
    """govopt: design and evaluate governor springs."""


def _fail(message: str) -> None:
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)


def _load(spec: Path | None, default: Path, **analysis):
    from .spec import load_spec

    s = load_spec(spec or default)
    changes = {k: v for k, v in analysis.items() if v is not None}
    return s.with_analysis(**changes) if changes else s


@app.command()
def evaluate(
    spec: SpecArg = None,
    geometry: Annotated[str | None, typer.Option(
        help="Linkage geometry: 'exact' (default) or 'series' (the paper's eq. 3).")] = None,
    json_out: JsonOpt = False,
    xlsx: Annotated[Path | None, typer.Option("--xlsx", help="Write an Excel design sheet.")]
    = None,
) -> None:
    """Evaluate the spec's design (default: the bundled Hamabe case a)."""
    from .evaluation import evaluate as run
    from .report.text import format_result

    if geometry is not None and geometry not in ("exact", "series"):
        _fail(f"--geometry: expected 'exact' or 'series', got {geometry!r}")
    try:
        res = run(_load(spec, DEFAULT_EVALUATE, geometry=geometry))
        if xlsx is not None:
            from .report.excel import write_workbook

            write_workbook(res, xlsx)
    except GovoptError as exc:
        _fail(str(exc))
    typer.echo(json.dumps(res.to_dict(), indent=2) if json_out else format_result(res))
    if xlsx is not None and not json_out:
        typer.echo(f"\nwrote {xlsx}")


@app.command()
def design(
    spec: SpecArg = None,
    json_out: JsonOpt = False,
    output: Annotated[Path | None, typer.Option("-o", "--output",
                                                help="Write the design as a spec file.")] = None,
    xlsx: Annotated[Path | None, typer.Option("--xlsx", help="Write an Excel design sheet.")]
    = None,
) -> None:
    """Find the best design for the spec's requirements (default: bundled hamabe-design)."""
    from .optimize.design import design as run
    from .report.files import write_design_spec
    from .report.text import format_result

    if spec is None and xlsx is None:
        xlsx = REPORTS / "hamabe-design.xlsx"
    try:
        res = run(_load(spec, DEFAULT_DESIGN))
        if output is not None:
            write_design_spec(res, output)
        if xlsx is not None:
            from .report.excel import write_workbook

            write_workbook(res, xlsx)
    except GovoptError as exc:
        _fail(str(exc))
    typer.echo(json.dumps(res.to_dict(), indent=2) if json_out else format_result(res))
    if not json_out:
        for path in (output, xlsx):
            if path is not None:
                typer.echo(f"wrote {path}")


@app.command()
def bench(
    quick: Annotated[bool, typer.Option(help="Smaller problem sizes.")] = False,
) -> None:
    """Measure speed against a baseline timed in the same run (design, GP, transient)."""
    from .report import bench as b

    out = {"design": b.design_bench(DEFAULT_DESIGN), "gp_resolve": b.gp_bench(10 if quick else 30),
           "transient": b.transient_bench(10_000 if quick else 100_000, 20 if quick else 100)}
    typer.echo(json.dumps(out, indent=2, default=float))


def main() -> None:
    """Console-script entry point."""
    try:
        app()
    except KeyboardInterrupt:
        sys.exit(130)


if __name__ == "__main__":
    main()
