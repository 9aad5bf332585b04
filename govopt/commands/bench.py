"""`govopt bench`: speed against error of every analysis and the speed targets beside what was
measured."""

from pathlib import Path
from typing import Annotated

import typer

from . import common
from .common import FORCE_HELP, echo, guarded

BENCH_HELP = ("Speed against error of every analysis (one point per method and setting, errors "
              "against high-precision references) and the speed targets beside what was "
              "measured.")
BENCH_SHORT = ("Speed against error of every analysis and the speed targets beside what was "
               "measured.")

app = typer.Typer(add_completion=False)


@app.command("bench", help=BENCH_HELP, short_help=BENCH_SHORT)
@guarded
def bench(quick: Annotated[bool, common.flag(
              "--quick/--no-quick",
              help="A smaller suite and fewer repeats (under a minute).")] = False,
          out: Annotated[Path | None, common.option(
              "--out", metavar="<path>", help="Folder for speed-vs-error.md, .csv and .png "
                                              "(made if only its parent exists).")] = None,
          force: Annotated[bool, common.flag("--force", help=FORCE_HELP)] = False,
          targets: Annotated[bool, common.flag(
              "--targets/--no-targets", help="Also measure the speed targets.")]
          = True) -> None:
    """Speed against error of every analysis (one point per method and setting, errors
    against high-precision references) and the speed targets beside what was measured."""
    from ..bench import report, suites
    from ..bench import targets as measured

    if out is not None:  # before the benchmark: fail in a second, not after it
        report.check_report(out, overwrite=force)

    def log(message: str) -> None:
        echo(f"  {message}", err=True)

    rows = measured.targets(quick, log=log) if targets else None
    points = suites.speed_vs_error(quick, log=log)
    echo(report.summary(points, rows))
    if out is not None:
        for path in report.write_report(points, out, rows, overwrite=force):
            echo(f"wrote {path}")
