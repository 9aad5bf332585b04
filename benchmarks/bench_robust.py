"""Time a robust design against the nominal design of the same spec (at most 10x).

Usage: ``PYTHONPATH=. python benchmarks/bench_robust.py`` - CPU and wall time of ``design()``
on each bundled robust spec, with its robust keys and without them (the nominal design), warm
(best of 3 after one run), and the ratio.
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

import govopt
from govopt.optimize import design as dz
from govopt.optimize import robust as rb
from govopt.optimize import search

SPECS = sorted((Path(__file__).resolve().parent.parent / "specs").glob("*robust*.toml"))


def best_of(spec, runs: int = 3) -> tuple[float, float]:
    search.design(spec)  # warm: imports and caches
    out = []
    for _ in range(runs):
        c, w = time.process_time(), time.perf_counter()
        search.design(spec)
        out.append((time.process_time() - c, time.perf_counter() - w))
    return min(out)


def main() -> None:
    for path in SPECS:
        spec = govopt.load_spec(path)
        nominal = dataclasses.replace(
            spec, requirements=rb.nominal_requirements(dz.requirements(spec)))
        (cn, wn), (cr, wr) = best_of(nominal), best_of(spec)
        print(f"{path.name}: nominal {cn:.3f} s CPU ({wn:.3f} s wall), robust {cr:.3f} s CPU "
              f"({wr:.3f} s wall): x{cr / cn:.1f} CPU, x{wr / wn:.1f} wall")


if __name__ == "__main__":
    main()
