"""`govopt evaluate SPEC --json` for every bundled spec, saved and compared.

    python benchmarks/evaluate_json.py save DIR
    python benchmarks/evaluate_json.py compare DIR_A DIR_B [--rtol 1e-14]

``save`` runs each spec in a fresh interpreter and writes ``DIR/NAME.json`` (stdout), ``.err``
(stderr) and ``.rc`` (exit code): run it in two working trees (or before and after a change)
to compare their answers. ``compare`` walks two folders' JSON side by side: every
number within ``rtol`` (relative to its magnitude, 1e-300 absolute at zero), every other value
equal, the same exit codes and stderr; it prints the differences and exits 1 if there are any.
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

SPECS = Path(__file__).resolve().parents[1] / "specs"

RUN = """
import sys
from govopt.cli import main
sys.argv = ["govopt", "evaluate", {spec!r}, "--json"]
main()
"""


def save(folder: Path) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    for spec in sorted(SPECS.glob("*.toml")):
        p = subprocess.run([sys.executable, "-c", RUN.format(spec=str(spec))],
                           capture_output=True, text=True, cwd=folder)
        (folder / f"{spec.stem}.json").write_text(p.stdout)
        (folder / f"{spec.stem}.err").write_text(p.stderr)
        (folder / f"{spec.stem}.rc").write_text(f"{p.returncode}\n")
        print(spec.stem, p.returncode)


def differences(a, b, rtol: float, where: str = ""):
    """Where ``a`` and ``b`` differ: numbers by more than ``rtol`` relative, anything else."""
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            yield f"{where}: keys {sorted(a.keys() ^ b.keys())}"
        for k in a.keys() & b.keys():
            yield from differences(a[k], b[k], rtol, f"{where}.{k}")
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            yield f"{where}: lengths {len(a)} and {len(b)}"
        for i, (x, y) in enumerate(zip(a, b, strict=False)):
            yield from differences(x, y, rtol, f"{where}[{i}]")
    elif (isinstance(a, int | float) and isinstance(b, int | float)
          and not isinstance(a, bool) and not isinstance(b, bool)):
        if not (a == b or abs(a - b) <= rtol * max(abs(a), abs(b), 1e-300)
                or (math.isnan(a) and math.isnan(b))):
            yield f"{where}: {a!r} and {b!r}"
    elif a != b:
        yield f"{where}: {a!r} and {b!r}"


def compare(first: Path, second: Path, rtol: float) -> int:
    bad = 0
    for fa in sorted(first.glob("*.json")):
        fb = second / fa.name
        found = []
        for ext in (".rc", ".err"):
            if fa.with_suffix(ext).read_text() != fb.with_suffix(ext).read_text():
                found.append(f"{ext[1:]} differs")
        ta, tb = fa.read_text(), fb.read_text()
        if ta.strip() or tb.strip():
            found += list(differences(json.loads(ta), json.loads(tb), rtol))
        print(f"{fa.stem}: {'same' if not found else f'{len(found)} differences'}")
        for line in found[:20]:
            print("   ", line)
        bad += bool(found)
    return 1 if bad else 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("save")
    s.add_argument("folder", type=Path)
    c = sub.add_parser("compare")
    c.add_argument("first", type=Path)
    c.add_argument("second", type=Path)
    c.add_argument("--rtol", type=float, default=1e-14)
    args = ap.parse_args()
    if args.cmd == "save":
        save(args.folder.resolve())
        return 0
    return compare(args.first, args.second, args.rtol)


if __name__ == "__main__":
    sys.exit(main())
