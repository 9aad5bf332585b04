"""The commands an engineer waits for, this tree against a baseline revision, in the same run.

Each command runs as ``python -m govopt.cli ARGS`` in a process of its own, once with govopt
from this checkout and once with govopt from ``--base`` (its files taken with ``git archive``
into a temporary folder and put first on ``PYTHONPATH``: the same interpreter and libraries),
the two alternating, ``--repeats`` times each; printed: the median CPU (user + system, from
``os.wait4``) of each, the ratio, the wall time and the peak resident memory. Both trees read
and write their bytecode in one private cache (``PYTHONPYCACHEPREFIX``), warmed first, so
neither pays for compiling the libraries (an installed environment has their bytecode).

The libraries' floor is the CPU of importing numpy, pint, typer, pydantic, rich and
scipy.interpolate in a process of its own, measured the same way.

The commands (the specs from ``specs/``; the variants written to a temporary folder):

* ``design hartnell-tolerances.toml`` (a yield of its samples), and with ``min_yield = 0.99``;
* ``design hamabe-design-fatigue.toml`` beside ``design hamabe-design.toml``;
* ``evaluate --plots`` of the ``min_yield`` design (written by each tree's own ``design -o``);
* Porter infeasible diagnoses: ``porter-design`` with a band the geometry cannot hold
  (190-200 rpm, no central load helps) and one whose k^2 margin fails (200-235.8 rpm);
* a design-mode study of ``porter-design`` over 17 upper speeds, and a ``--dask local`` study
  of 4 Porter points (2 workers, wall time matters there);
* evaluate-mode studies of ``hamabe-a``: ``--points`` points statics-only
  (``--skip dynamics,vibration,classic``) and ``--points-default`` points with the default
  outputs, both on ``--workers`` processes: points per wall second and per CPU second, peak
  memory.

Run:  python benchmarks/bench_commands.py --base REV [--repeats 3] [--out FILE]
Not a test: it takes minutes (the baseline's default-output study alone is about a minute).
"""

from __future__ import annotations

import argparse
import io
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"
FLOOR = "import numpy, pint, typer, pydantic, rich, scipy.interpolate"


def baseline_tree(ref: str, folder: Path) -> Path:
    """The files of ``ref`` (a commit of this repository) in ``folder`` (``git archive``)."""
    tar = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "govopt"], check=True,
                         capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(tar)) as archive:
        archive.extractall(folder, filter="data")
    return folder


def run(args: list[str], tree: Path, cwd: Path, cache: Path) -> dict:
    """``python -m govopt.cli ARGS`` (or ``python -c CODE`` where ``args[0] == "-c"``) with
    govopt from ``tree``: CPU and wall seconds, peak memory (MB), exit code."""
    env = {**os.environ, "PYTHONPATH": str(tree), "PYTHONPYCACHEPREFIX": str(cache),
           "OPENBLAS_NUM_THREADS": "1"}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    argv = [sys.executable, *args] if args[0] == "-c" else [sys.executable, "-m", "govopt.cli",
                                                            *args]
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    return {"cpu": usage.ru_utime + usage.ru_stime, "wall": time.perf_counter() - t0,
            "rss": usage.ru_maxrss / 1024.0, "exit": os.waitstatus_to_exitcode(status)}


def variants(folder: Path) -> dict[str, Path]:
    """The specs the commands read, written into ``folder``."""
    porter = (SPECS / "porter-design.toml").read_text(encoding="utf-8")
    hartnell = (SPECS / "hartnell-tolerances.toml").read_text(encoding="utf-8")
    out = {
        "hartnell": hartnell,
        "hartnell-099": hartnell.replace('objective = "moving_mass"',
                                         'objective = "moving_mass"\nmin_yield = 0.99'),
        "porter-narrow": porter.replace('outer = "224 rpm"', 'outer = "200 rpm"'),
        "porter-k2": porter.replace('inner = "190 rpm"', 'inner = "200 rpm"').replace(
            'outer = "224 rpm"', 'outer = "235.8 rpm"'),
        "porter": porter,
    }
    paths = {}
    for name, text in out.items():
        paths[name] = folder / f"{name}.toml"
        paths[name].write_text(text, encoding="utf-8")
    return paths


def commands(specs: dict[str, Path], points: int, points_default: int,
             workers: int) -> dict[str, tuple[list[list[str]], str]]:
    """name -> (the argument lists run in turn, the last one measured; what it is)."""
    a = str(SPECS / "hamabe-a.toml")
    study = ["study", "run", a, "--force", "--workers", str(workers)]
    return {
        "libraries' floor": ([["-c", FLOOR]], FLOOR),
        "design hartnell-tolerances": ([["design", str(specs["hartnell"])]], "yield of 500"),
        "design hartnell min_yield 0.99": ([["design", str(specs["hartnell-099"])]], ""),
        "design hamabe-design": ([["design", str(SPECS / "hamabe-design.toml")]],
                                 "the plain design"),
        "design hamabe-design-fatigue": ([["design", str(SPECS / "hamabe-design-fatigue.toml")]],
                                         ""),
        "evaluate --plots (min_yield design)": (
            [["design", str(specs["hartnell-099"]), "-o", "made.toml", "--force"],
             ["evaluate", "made.toml", "--plots", "plots", "--force"]], "the design first"),
        "Porter diagnosis: no central load helps": (
            [["design", str(specs["porter-narrow"])]], "190-200 rpm"),
        "Porter diagnosis: k^2 margin": ([["design", str(specs["porter-k2"])]],
                                         "200-235.8 rpm"),
        "design-mode Porter study, 17 points": (
            [["study", "run", str(specs["porter"]), "--mode", "design", "--force", "--db",
              "pd.db", "--sweep", "speed.outer=212 rpm:236 rpm:17"]], ""),
        "--dask local, 4 Porter points": (
            [["study", "run", str(specs["porter"]), "--mode", "design", "--force", "--db",
              "dk.db", "--dask", "local", "--workers", "2", "--sweep",
              "speed.outer=212 rpm:236 rpm:4"]], "wall matters"),
        f"hamabe-a study, {points} points statics-only": (
            [[*study, "--db", "s.db", "--skip", "dynamics,vibration,classic", "--sweep",
              f"design.pendulum_weight=10 kgf:14 kgf:{points}"]], f"{workers} workers"),
        f"hamabe-a study, {points_default} points default outputs": (
            [[*study, "--db", "d.db", "--sweep",
              f"design.pendulum_weight=10 kgf:14 kgf:{points_default}"]], f"{workers} workers"),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", required=True, help="the baseline revision (a commit)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--points", type=int, default=200_000)
    ap.add_argument("--points-default", type=int, default=50_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--only", help="run only the commands whose name holds this text")
    ap.add_argument("--out", type=Path, help="also write the table to this file")
    args = ap.parse_args(argv)
    lines = []

    def say(text: str = "") -> None:
        print(text, flush=True)
        lines.append(text)

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        trees = {"base": baseline_tree(args.base, tmp / "base"), "head": ROOT}
        cache = tmp / "pycache"
        specs = variants(tmp)
        work = {side: tmp / f"work-{side}" for side in trees}
        for w in work.values():
            w.mkdir()
        load = os.getloadavg()[0]
        say(f"base {args.base[:12]}, head {_head()}; {os.cpu_count()} cores, load average "
            f"{load:.1f} at the start; CPU = user + system of the command's process tree, "
            f"median of {args.repeats} (studies: 1)")
        for side, tree in trees.items():  # warm the bytecode cache
            run(["evaluate", str(SPECS / "hamabe-a.toml")], tree, work[side], cache)
        say(f"{'command':44} {'base CPU':>9} {'head CPU':>9} {'ratio':>6} {'base wall':>9} "
            f"{'head wall':>9} {'head MB':>8}  note")
        table = commands(specs, args.points, args.points_default, args.workers)
        for name, (steps, note) in table.items():
            if args.only and args.only not in name:
                continue
            repeats = 1 if "study" in name else args.repeats
            got = {side: [] for side in trees}
            for _ in range(repeats):
                for side, tree in trees.items():
                    for step in steps[:-1]:
                        run(step, tree, work[side], cache)
                    got[side].append(run(steps[-1], tree, work[side], cache))
            med = {side: {k: statistics.median(r[k] for r in rs) for k in ("cpu", "wall", "rss")}
                   for side, rs in got.items()}
            codes = {side: {r["exit"] for r in rs} for side, rs in got.items()}
            ratio = med["head"]["cpu"] / med["base"]["cpu"]
            extra = "" if codes["base"] == codes["head"] else f" exit {codes}"
            say(f"{name:44} {med['base']['cpu']:9.2f} {med['head']['cpu']:9.2f} {ratio:6.2f} "
                f"{med['base']['wall']:9.2f} {med['head']['wall']:9.2f} "
                f"{med['head']['rss']:8.0f}  {note}{extra}")
            if "study" in name and "hamabe-a" in name:
                n = args.points if "statics" in name else args.points_default
                say(f"{'':44} points/s: base {n / med['base']['wall']:,.0f} wall "
                    f"{n / med['base']['cpu']:,.0f} CPU; head {n / med['head']['wall']:,.0f} "
                    f"wall {n / med['head']['cpu']:,.0f} CPU")
        say(f"load average {os.getloadavg()[0]:.1f} at the end")
    if args.out:
        args.out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return 0


def _head() -> str:
    rev = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short=12", "HEAD"],
                         capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "govopt"],
                           capture_output=True, text=True).stdout.strip()
    return rev + (" (+ uncommitted changes)" if dirty else "")


if __name__ == "__main__":
    sys.exit(main())
