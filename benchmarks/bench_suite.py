"""The test suite's time against a baseline revision's, measured in the same run on the same
machine: each tree (this checkout's HEAD and ``--base``, cloned) is installed into a virtual
environment of its own (``uv``, the same releases for both where their ranges allow; with pip
and setuptools, as ``python -m venv`` gives the README's test command) and runs its whole suite
on one worker (``-n 0``: no time of one test includes another's), writing a JUnit report; the
reports are then compared.

Printed: each suite's total test time and its process CPU; the tests found in both (matched by
function name and parameters, whatever file they moved to) with their ratio, the same without
the tests named by ``--apart`` (a test whose inputs grew with the project, such as the hostile
corpus), the tests only one side has, and the largest changes.

    python benchmarks/bench_suite.py --base REV [--apart test_hostile_corpus] [--keep DIR]

Not a test: it takes twice the suite's serial time (about 15 minutes here).
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def install(tree: Path, venv: Path) -> Path:
    """A virtual environment at ``venv`` with ``tree`` installed editable with its test extras;
    its interpreter."""
    subprocess.run(["uv", "venv", "-q", "--seed", str(venv)], check=True)  # pip, setuptools
    python = venv / "bin" / "python"
    subprocess.run(["uv", "pip", "install", "-q", "--python", str(python), "-e",
                    f"{tree}[test]"], check=True)
    return python


def run_suite(tree: Path, python: Path, report: Path) -> float:
    """Run ``tree``'s suite on one worker; its process CPU (user + system, s)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([str(python), "-m", "pytest", "-q", "-n", "0", "-p", "no:cacheprovider",
                    f"--junitxml={report}"], cwd=tree, stdout=subprocess.DEVNULL,
                   env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"})
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def times(report: Path) -> dict[str, float]:
    """``{test name with its parameters: seconds}`` from a JUnit report (a name in two files
    counts once, the times added)."""
    out: dict[str, float] = {}
    for case in ET.parse(report).getroot().iter("testcase"):
        name = case.get("name", "")
        out[name] = out.get(name, 0.0) + float(case.get("time") or 0.0)
    return out


def compare(base: dict[str, float], head: dict[str, float], apart: tuple[str, ...]) -> str:
    both = sorted(set(base) & set(head))
    kept = [t for t in both if re.sub(r"\[.*", "", t) not in apart]
    lines = [f"base: {sum(base.values()):.1f} s of test time, {len(base)} tests; "
             f"head: {sum(head.values()):.1f} s, {len(head)} tests"]
    for label, names in (("in both", both), (f"in both, without {', '.join(apart)}", kept)):
        b, h = sum(base[t] for t in names), sum(head[t] for t in names)
        lines.append(f"{label} ({len(names)}): base {b:.1f} s, head {h:.1f} s, "
                     f"ratio {h / b if b else float('nan'):.3f}")
    for t in apart:
        b = sum(v for k, v in base.items() if re.sub(r"\[.*", "", k) == t)
        h = sum(v for k, v in head.items() if re.sub(r"\[.*", "", k) == t)
        lines.append(f"{t}: base {b:.1f} s, head {h:.1f} s")
    only = set(head) - set(base)
    lines.append(f"only in head ({len(only)}): {sum(head[t] for t in only):.1f} s; only in "
                 f"base ({len(set(base) - set(head))}): "
                 f"{sum(base[t] for t in set(base) - set(head)):.1f} s")
    lines.append("largest changes among the tests in both (base -> head, s):")
    for t in sorted(both, key=lambda t: head[t] - base[t])[-10:]:
        lines.append(f"  {base[t]:7.2f} -> {head[t]:7.2f}  {t}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", required=True, help="the baseline revision (a commit or a tag)")
    ap.add_argument("--apart", action="append", default=[],
                    help="a test function to report apart (repeatable)")
    ap.add_argument("--keep", type=Path, help="keep the trees, venvs and reports in DIR")
    args = ap.parse_args(argv)
    work = args.keep or Path(tempfile.mkdtemp(prefix="bench-suite-"))
    work.mkdir(parents=True, exist_ok=True)
    try:
        cpu, found = {}, {}
        for side, rev in (("base", args.base), ("head", "HEAD")):
            tree = work / side
            if not tree.exists():
                subprocess.run(["git", "clone", "-q", str(ROOT), str(tree)], check=True)
                subprocess.run(["git", "-C", str(tree), "checkout", "-q", rev], check=True)
            python = install(tree, work / f"venv-{side}")
            report = work / f"{side}.xml"
            cpu[side] = run_suite(tree, python, report)
            found[side] = times(report)
        print(f"process CPU: base {cpu['base']:.0f} s, head {cpu['head']:.0f} s, "
              f"ratio {cpu['head'] / cpu['base']:.2f}")
        print(compare(found["base"], found["head"], tuple(args.apart)))
    finally:
        if args.keep is None:
            shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
