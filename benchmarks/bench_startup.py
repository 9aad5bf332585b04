"""Start-up of the command line against ``python -c "import numpy"`` on the same machine:
``govopt --help`` within 3 x and ``govopt evaluate SPEC`` within 4.5 x of numpy's import; and
a plain ``govopt spring`` design (a force, a stiffness, an allowable stress and a modulus: one
GP) within 1.3 x of ``python -c "import cvxpy"``; in whole-process CPU (user + system) and wall
time.

    python benchmarks/bench_startup.py [--runs 21] [--json]

Every command runs ``--runs`` times in a fresh interpreter, interleaved (one run of each in
turn, so that a change of the machine's load falls on all alike); the medians are compared.
CPU is the measure that a busy machine disturbs least; wall time is printed beside it.
Not a test: timing assertions would fail on a loaded machine; this prints the ratios.

The children run with compiled bytecode, as an installed package does (pip writes the .pyc
files): they cache it under a temporary ``PYTHONPYCACHEPREFIX`` (numpy's as well as govopt's),
written by a warm-up run of each command, with ``PYTHONDONTWRITEBYTECODE`` dropped. Without a
cache every start compiles govopt's ~40 modules from source (~0.1 s of CPU).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "govopt" / "specs" / "hamabe-a.toml"

NUMPY, CVXPY = 'python -c "import numpy"', 'python -c "import cvxpy"'
#: name -> (command words after the interpreter, the limit as a multiple of its baseline's
#: time, the baseline: a command measured in the same run)
COMMANDS = {
    NUMPY: (["-c", "import numpy"], None, NUMPY),
    "govopt --help": (["-m", "govopt.cli", "--help"], 3.0, NUMPY),
    "govopt evaluate SPEC": (["-m", "govopt.cli", "evaluate", str(SPEC)], 4.5, NUMPY),
    CVXPY: (["-c", "import cvxpy"], None, CVXPY),
    "govopt spring (plain design)": (
        ["-m", "govopt.cli", "spring", "--force", "500 N", "--stiffness", "10 N/mm",
         "--allowable-stress", "600 MPa", "--shear-modulus", "81.5 GPa"], 1.3, CVXPY),
}


def run_once(words: list[str], env: dict) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one fresh interpreter running ``words``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, *words], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False, cwd=ROOT, env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def measure(runs: int) -> dict:
    """Median wall and CPU of every command, and each one's ratio to numpy's import."""
    samples = {name: ([], []) for name in COMMANDS}
    with tempfile.TemporaryDirectory() as cache:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env.update(PYTHONPATH=str(ROOT), PYTHONPYCACHEPREFIX=cache)
        for words, _, _ in COMMANDS.values():  # one warm-up each: the file cache, the .pyc
            run_once(words, env)
        for _ in range(runs):
            for name, (words, _, _) in COMMANDS.items():
                wall, cpu = run_once(words, env)
                samples[name][0].append(wall)
                samples[name][1].append(cpu)
    out = {}
    for name, (walls, cpus) in samples.items():
        wall, cpu = statistics.median(walls), statistics.median(cpus)
        base = COMMANDS[name][2]
        out[name] = {"runs": runs, "median_wall_s": wall, "median_cpu_s": cpu,
                     "baseline": base,
                     "cpu_ratio": cpu / statistics.median(samples[base][1]),
                     "wall_ratio": wall / statistics.median(samples[base][0]),
                     "limit_ratio": COMMANDS[name][1]}
    out["load_average"] = os.getloadavg()[0]
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=21)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    result = measure(args.runs)
    if args.json:
        print(json.dumps(result, indent=2))
        return
    print(f"{args.runs} runs each, interleaved; load average {result.pop('load_average'):.1f}")
    print(f"{'command':<30}{'CPU s':>8}{'x base':>8}{'wall s':>8}{'x base':>8}  base, limit")
    for name, r in result.items():
        met = r["limit_ratio"] is not None and r["cpu_ratio"] <= r["limit_ratio"]
        limit = "" if r["limit_ratio"] is None else (
            f", <= {r['limit_ratio']:g} x ({'met' if met else 'MISSED'} in CPU)")
        print(f"{name:<30}{r['median_cpu_s']:>8.3f}{r['cpu_ratio']:>8.2f}"
              f"{r['median_wall_s']:>8.3f}{r['wall_ratio']:>8.2f}  {r['baseline']}{limit}")


if __name__ == "__main__":
    main()
