"""The design's speed targets, beside what is measured in this run.

1. ``design()`` in process on the bundled spec: median CPU (target <= 0.1 s), its stages, and
   the pruned continuous bound checked against the bound solved at every mass;
2. whole-process times of ``govopt --help`` (<= 0.3 s), ``govopt evaluate`` (<= 0.5 s) and
   ``govopt design`` (<= 0.6 s), beside ``python -c pass`` timed in the same run;
3. peak RSS of a design over a 48 million-combination catalogue (< 1 GB), in a child process.

Run:  python benchmarks/bench_design.py [--quick]
(also part of ``govopt bench``). A benchmark, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import json

from govopt.bench import report, targets


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="fewer repeats")
    p.add_argument("--json", action="store_true", help="print the measurements as JSON")
    a = p.parse_args(argv)
    rows = targets.targets(a.quick, log=lambda m: print(f"  {m}"))
    stages = targets.design_in_process(3 if a.quick else 7)
    if a.json:
        print(json.dumps({"targets": rows, "design_in_process": stages}, indent=2,
                         default=float))
        return
    print(report.summary([], rows).split("\nspeed against error")[0])
    print("design() stages, CPU s per call:")
    for name, t in stages["stages_cpu_s"].items():
        print(f"  {name:32s} {t:.4f}")


if __name__ == "__main__":
    main()
