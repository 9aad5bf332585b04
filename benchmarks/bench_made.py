"""The made governor's cost against a baseline revision's, measured in the same run: the CPU
(user + system of the process) of ``govopt design X`` for every bundled design spec with a
spring and every ``govopt init --type T`` template of a spring type, at this checkout (the made
governor's design and verdict, its yield included) and at ``--base`` (the nominal design of the
revision before), each the least of ``--repeat`` runs, alternated; and a 2000-sample yield in
process (:func:`govopt.made.made_yield`) at this checkout.

The base revision is cloned and run with this interpreter (the same libraries) and the clone
first on ``PYTHONPATH`` (its bundled specs linked in as ``govopt.specs``), so the two sides
differ only in govopt's code.

    python benchmarks/bench_made.py --base REV [--repeat 3] [--only NAME ...]

Not a test: a few minutes. Its output at the last measurement: benchmarks/bench_made.txt.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CLI = "import sys; from govopt.cli import main; sys.argv[0] = 'govopt'; main()"
TYPES = ("hartnell", "spring_loaded", "spring_gravity", "traction_coil", "traction_leaf")


def cpu(args: list[str], env: dict, cwd: Path) -> tuple[float, int]:
    """The CPU seconds (user + system) of one run of ``python -c CLI ARGS`` and its exit
    code."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    rc = subprocess.run([sys.executable, "-c", CLI, *args], cwd=cwd, env=env,
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), rc


def base_tree(rev: str, work: Path) -> Path:
    """A clone of this repository at ``rev`` whose ``govopt.specs`` resolves from the
    source tree."""
    tree = work / "base"
    subprocess.run(["git", "clone", "-q", str(ROOT), str(tree)], check=True)
    subprocess.run(["git", "-C", str(tree), "checkout", "-q", rev], check=True)
    (tree / "govopt" / "specs").symlink_to(tree / "specs")
    return tree


def cases(work: Path, env: dict) -> dict[str, Path]:
    """The specs designed: the bundled design specs with a spring and the spring types'
    templates (as this checkout writes them)."""
    import govopt
    from govopt.examples import SPECS

    out = {}
    for path in sorted(SPECS.glob("*design*.toml")):
        if govopt.load_spec(path).governor.spring is not None:
            out[path.stem] = path
    for t in TYPES:
        path = work / f"template-{t}.toml"
        subprocess.run([sys.executable, "-c", CLI, "init", "--type", t, "-o", str(path)],
                       env=env, check=True, stdout=subprocess.DEVNULL)
        out[path.stem] = path
    return out


def yield_seconds(repeat: int) -> tuple[float, float]:
    """The least CPU seconds of a 2000-sample yield in process (the bundled Hartnell's design,
    made to grade 2 and set by the fitter) and its probability."""
    import govopt
    from govopt import made
    from govopt.analysis import tolerance as tm
    from govopt.examples import SPECS

    res = govopt.design(govopt.load_spec(SPECS / "hartnell-tolerances.toml"))
    cols = made.resolved_columns(res.spec, res)
    req = made.made_requirements(res.spec)
    bx = tm.stated(res.spec, cols, req).known()
    best, p = float("inf"), None
    for _ in range(repeat + 1):  # the first warms the caches
        t = time.process_time()
        y = made.made_yield(res.spec, cols, bx, 2000, 0, made.fitter_of(req))
        best = min(best, time.process_time() - t)
        p = y["probability"]
    return best, p


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", required=True, help="the baseline revision (a commit or a tag)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", action="append", help="a case's name (repeatable)")
    args = ap.parse_args(argv)
    work = Path(tempfile.mkdtemp(prefix="bench-made-"))
    try:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        base_env = {**env, "PYTHONPATH": str(base_tree(args.base, work))}
        found = cases(work, env)
        if args.only:
            found = {k: v for k, v in found.items() if k in args.only}
        print(f"base {args.base[:12]} (nominal design) against HEAD (designed as made, "
              f"the yield included); CPU s, least of {args.repeat}")
        print(f"{'spec':32s} {'base':>7s} {'head':>7s} {'ratio':>6s}  exit base/head")
        worst = 0.0
        for name, path in found.items():
            b = h = float("inf")
            for _ in range(args.repeat):
                tb, rb = cpu(["design", str(path)], base_env, work)
                th, rh = cpu(["design", str(path)], env, work)
                b, h = min(b, tb), min(h, th)
            worst = max(worst, h / b)
            print(f"{name:32s} {b:7.2f} {h:7.2f} {h / b:6.2f}  {rb}/{rh}")
        print(f"largest ratio {worst:.2f}")
        s, p = yield_seconds(args.repeat)
        print(f"2000-sample yield in process (hartnell-tolerances' design): {s * 1e3:.0f} ms "
              f"CPU, probability {p:.4f}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
