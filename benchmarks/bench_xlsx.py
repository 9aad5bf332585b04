"""``govopt evaluate SPEC --xlsx FILE`` against the same command of another checkout (the
baseline), and against ``govopt evaluate SPEC`` alone: what the workbook costs.

    python benchmarks/bench_xlsx.py --baseline /path/to/other/venv/bin/python [--runs 9]
                                    [--spec hamabe-a] [--json]

Each command runs ``--runs`` times in a fresh interpreter, interleaved (one run of each in turn,
so a change of the machine's load falls on all alike); the medians of whole-process CPU (user +
system) are compared, wall time printed beside it. ``--baseline``: the interpreter of the
checkout to compare with (its own ``govopt`` is the one it imports); without it only this
checkout's two commands run. The children cache their bytecode under a temporary
``PYTHONPYCACHEPREFIX``, written by a warm-up run of each command (as an installed package has
its .pyc files). Not a test: timing assertions would fail on a loaded machine; this prints the
ratios (the target: this checkout's workbook command within 1.2 x of the baseline's).
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


def run_once(python: str, words: list[str], env: dict, cwd: Path) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one fresh interpreter running ``words``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([python, *words], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=False, cwd=cwd, env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--baseline", help="the interpreter of the checkout to compare with")
    ap.add_argument("--runs", type=int, default=9)
    ap.add_argument("--spec", default="hamabe-a", help="a bundled spec with a [design]")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    spec = str(ROOT / "specs" / f"{args.spec}.toml")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = str(tmp / "pycache")
        book = str(tmp / "out.xlsx")
        commands = {"evaluate": (sys.executable, ["-m", "govopt.cli", "evaluate", spec]),
                    "evaluate --xlsx": (sys.executable, ["-m", "govopt.cli", "evaluate", spec,
                                                         "--xlsx", book, "--force"])}
        if args.baseline:
            commands["baseline evaluate --xlsx"] = (args.baseline, [
                "-m", "govopt.cli", "evaluate", spec, "--xlsx", book, "--force"])
        times: dict[str, list[tuple[float, float]]] = {k: [] for k in commands}
        for python, words in commands.values():  # warm-up: the bytecode caches
            run_once(python, words, env, tmp)
        for _ in range(args.runs):
            for name, (python, words) in commands.items():
                times[name].append(run_once(python, words, env, tmp))
    median = {k: (statistics.median(w for w, _ in v), statistics.median(c for _, c in v))
              for k, v in times.items()}
    ratios = {"workbook / evaluate (CPU)": median["evaluate --xlsx"][1] / median["evaluate"][1]}
    if args.baseline:
        ratios["this / baseline, evaluate --xlsx (CPU)"] = (
            median["evaluate --xlsx"][1] / median["baseline evaluate --xlsx"][1])
        ratios["this / baseline, evaluate --xlsx (wall)"] = (
            median["evaluate --xlsx"][0] / median["baseline evaluate --xlsx"][0])
    if args.json:
        print(json.dumps({"runs": args.runs, "median_wall_cpu_s": median, "ratios": ratios},
                         indent=2))
        return
    for name, (wall, cpu) in median.items():
        print(f"{name:28s} CPU {cpu:6.3f} s   wall {wall:6.3f} s   (median of {args.runs})")
    for name, value in ratios.items():
        print(f"{name:40s} {value:.3f}")


if __name__ == "__main__":
    main()
