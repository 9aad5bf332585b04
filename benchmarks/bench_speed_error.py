"""Speed against error of every analysis: one point per method and setting.

Writes ``speed-vs-error.md``, ``speed-vs-error.csv`` and ``speed-vs-error.png`` (log-log: CPU
time per evaluation against relative error, one panel per analysis, the Pareto front dotted and
govopt's defaults circled) into ``--out``. The suite, its hard cases and the high-precision
references are described in :mod:`govopt.bench.suites`. ``--quick`` runs in under a minute,
the full suite in under ten; the full run's CSV is what :mod:`govopt.fidelity` reads
(``govopt/data/speed-vs-error.csv``).

Run:  python benchmarks/bench_speed_error.py [--quick] --out DIR [--only transient ...]
"""

from __future__ import annotations

import argparse

from govopt.bench import report, suites, targets


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="smaller suite, fewer repeats")
    p.add_argument("--out", required=True, help="folder for the report files")
    p.add_argument("--only", nargs="*", choices=list(suites.SUITES), help="run only these")
    p.add_argument("--targets", action="store_true", help="also measure the speed targets")
    a = p.parse_args(argv)
    rows = targets.targets(a.quick, log=lambda m: print(f"  {m}")) if a.targets else None
    points = suites.speed_vs_error(a.quick, a.only, log=lambda m: print(f"  {m}"))
    print(report.summary(points, rows))
    for path in report.write_report(points, a.out, rows):
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
