"""Start-up of the command line against baselines measured in the same run, on the same machine:
``govopt design`` and ``govopt evaluate SPEC`` within 3 x ``python -c "import numpy"``,
``govopt spring SPEC`` within 1.3 x ``python -c "import cvxpy"`` (what cvxpy's import costs is
cvxpy's), and, given a checkout of main (``--main``), ``govopt --help`` as fast as main's
(within 1.05 x: the medians of two runs of one command differ by a few per cent here); with
``--main`` every govopt command is also run from main, for comparison. In whole-process CPU
(user + system), wall time beside it.

Each command is also measured against its libraries' floor, the import of the packages it
needs (numpy, pint, typer with the pydantic it converts options with, rich's tables; the shaft
governor's scipy.interpolate, for its valve table's PCHIP and the swing's root; cvxpy for a
spring), within 1.3 x: what a floor costs is the libraries' (scipy.interpolate alone takes the
shaft governor past 3 x numpy, and govopt does not copy a library's algorithm to save its
import); what lies above it is govopt's.
Measure on a plain install (``pip install -e .``): where dask is installed, pint imports
``dask.base`` as it loads (pint 0.25), which every quantity-reading command then pays.

    python benchmarks/bench_startup.py [--runs 21] [--json]
        [--main ../main --main-python ../venvs/main/bin/python]

Every command runs ``--runs`` times in a fresh interpreter, interleaved (one run of each in
turn, so that a change of the machine's load falls on all alike); the medians are compared.
CPU is the measure that a busy machine disturbs least. Not a test: timing assertions would fail
on a loaded machine; this prints the ratios.

The children run with compiled bytecode, as an installed package does (pip writes the .pyc
files): they cache it under a temporary ``PYTHONPYCACHEPREFIX`` (numpy's as well as govopt's),
written by a warm-up run of each command, with ``PYTHONDONTWRITEBYTECODE`` dropped. Without a
cache every start compiles govopt's modules from source (~0.1 s of CPU).
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
SPECS = ROOT / "specs"
NUMPY = 'python -c "import numpy"'
CVXPY = 'python -c "import cvxpy"'
#: the libraries every command loads (units, the CLI and its option conversion, typer 0.29's
#: through pydantic, the terminal's tables): govopt's floor
LIBRARIES = "numpy, pint, typer, pydantic, rich.console, rich.table"
FLOOR = f'python -c "import {LIBRARIES}"'
#: the shaft governor's evaluation adds scipy's PCHIP (its valve table) and brentq
FLOOR_SHAFT = f'python -c "import {LIBRARIES}, scipy.interpolate"'
FLOOR_SPRING = f'python -c "import {LIBRARIES}, cvxpy"'
MAIN = "main's "
MAIN_HELP = MAIN + "govopt --help"

#: name -> (command words after the interpreter, the limits: (baseline's name, the limit as a
#: multiple of it), ...; none for a baseline). The issue's budgets are against numpy and cvxpy;
#: the floors show what is govopt's own (what the libraries cost is theirs to lower upstream).
COMMANDS = {
    NUMPY: (["-c", "import numpy"], ()),
    CVXPY: (["-c", "import cvxpy"], ()),
    FLOOR: (["-c", f"import {LIBRARIES}"], ()),
    FLOOR_SHAFT: (["-c", f"import {LIBRARIES}, scipy.interpolate"], ()),
    FLOOR_SPRING: (["-c", f"import {LIBRARIES}, cvxpy"], ()),
    "govopt --help": (["-m", "govopt.cli", "--help"], ((MAIN_HELP, 1.05),)),
    "govopt evaluate porter-engine.toml": (
        ["-m", "govopt.cli", "evaluate", str(SPECS / "porter-engine.toml")],
        ((NUMPY, 3.0), (FLOOR, 1.3))),
    "govopt evaluate hamabe-a.toml": (
        ["-m", "govopt.cli", "evaluate", str(SPECS / "hamabe-a.toml")],
        ((NUMPY, 3.0), (FLOOR_SHAFT, 1.3))),
    "govopt design": (["-m", "govopt.cli", "design"], ((NUMPY, 3.0), (FLOOR_SHAFT, 1.3))),
    "govopt spring spring-500n.toml": (
        ["-m", "govopt.cli", "spring", str(SPECS / "springs" / "spring-500n.toml")],
        ((CVXPY, 1.3), (FLOOR_SPRING, 1.3))),
}


def run_once(python: str, words: list[str], env: dict) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one fresh interpreter running ``words``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([python, *words], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=False, cwd=env["PYTHONPATH"], env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def measure(runs: int, main: Path | None = None, main_python: str | None = None) -> dict:
    """Median wall and CPU of every command, and each one's ratio to its baseline (main's
    ``govopt --help`` from the checkout ``main`` run by ``main_python``, if given)."""
    with tempfile.TemporaryDirectory() as cache:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env.update(PYTHONPYCACHEPREFIX=cache)
        todo = {name: (sys.executable, words, {**env, "PYTHONPATH": str(ROOT)})
                for name, (words, _) in COMMANDS.items()}
        if main is not None:
            todo.update({MAIN + name: (main_python or sys.executable, words,
                                       {**env, "PYTHONPATH": str(main)})
                         for name, (words, _) in COMMANDS.items() if name.startswith("govopt")})
        samples = {name: ([], []) for name in todo}
        for python, words, child_env in todo.values():  # warm-up: the file cache, the .pyc
            run_once(python, words, child_env)
        for _ in range(runs):
            for name, (python, words, child_env) in todo.items():
                wall, cpu = run_once(python, words, child_env)
                samples[name][0].append(wall)
                samples[name][1].append(cpu)
    medians = {name: (statistics.median(walls), statistics.median(cpus))
               for name, (walls, cpus) in samples.items()}
    out = {}
    for name, (wall, cpu) in medians.items():
        limits = COMMANDS.get(name.removeprefix(MAIN), (None, ()))[1]
        if name.startswith(MAIN):  # main's own, beside: its ratios to the same baselines
            limits = tuple((base, None) for base, _ in limits if base != MAIN_HELP)
        row = {"runs": runs, "median_wall_s": wall, "median_cpu_s": cpu, "ratios": [
            {"baseline": base, "limit_ratio": limit, "cpu_ratio": cpu / medians[base][1],
             "wall_ratio": wall / medians[base][0]}
            for base, limit in limits if base in medians]}
        out[name] = row
    out["load_average"] = os.getloadavg()[0]
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=21)
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--main", type=Path, help="a checkout of main, to run its govopt beside")
    ap.add_argument("--main-python", help="the interpreter for --main (default: this one)")
    args = ap.parse_args()
    result = measure(args.runs, args.main, args.main_python)
    if args.json:
        print(json.dumps(result, indent=2))
        return
    print(f"{args.runs} runs each, interleaved; load average {result.pop('load_average'):.1f}")
    print(f"{'command':<39}{'CPU s':>7}{'wall s':>8}  {'CPU ratio':>9}  to (limit)")
    for name, r in result.items():
        print(f"{name:<39}{r['median_cpu_s']:>7.3f}{r['median_wall_s']:>8.3f}")
        for q in r["ratios"]:
            line = f"{'':<39}{'':>15}  {q['cpu_ratio']:>9.2f}  {q['baseline']}"
            if q["limit_ratio"]:
                met = "met" if q["cpu_ratio"] <= q["limit_ratio"] else "MISSED"
                line += f" (<= {q['limit_ratio']:g}: {met})"
            print(line)

if __name__ == "__main__":
    main()
