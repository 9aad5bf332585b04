"""``docs/validation.md``: how govopt's numbers agree with the sources and with high-precision
references, generated from runs so that every number on the page is what the code gives today.

The sources' values are declared here once (:data:`WORKED`, :data:`LITERATURE`), each with the
place it is printed and, where govopt differs, why; govopt's side is computed when the page is
written. The speed-against-error table is the shipped record of the last full ``govopt bench``
run (``govopt/data/speed-vs-error.csv``, the data ``[analysis] use_case`` reads): ``govopt bench
--out DIR`` measures it again.

``python tools/validation_docs.py docs/validation.md`` writes the page (stdout without a path);
a test fails when it is stale.
"""

from __future__ import annotations

import csv
import math
import sys
from dataclasses import dataclass
from pathlib import Path

RPM = math.pi / 30.0
KGF_CM = 9.80665 / 0.01


@dataclass(frozen=True)
class Worked:
    """A figure of a bundled worked example against the value its source prints."""

    spec: str
    figure: str  # a figure's name in the result (:meth:`govopt.result.Result.figures`)
    unit: str  # how the source states it: "rpm", "kgf/cm" or "" (a ratio)
    source_value: float
    where: str
    why: str = ""


WORKED = (
    Worked("textbook-ex1-porter", "speed at the inner end", "rpm", 178.5,
           "textbook 3.4(b) Example 1, N_2",
           "the book's own omega_2 = 18.6 rad/s is 177.6 rpm: a slip in converting"),
    Worked("textbook-ex1-porter", "speed at the outer end", "rpm", 202.0,
           "textbook 3.4(b) Example 1, N_1",
           "omega_1 = sqrt(7.660 x 981/16.58) = 21.29 rad/s is 203.3 rpm; the book rounds "
           "omega to 21.2"),
    Worked("hamabe-a", "spring stiffness", "kgf/cm", 64.2, "Hamabe Example 1, case a"),
    Worked("hamabe-b", "spring stiffness", "kgf/cm", 50.4, "Hamabe Example 1, case b"),
    Worked("hamabe-c", "spring stiffness", "kgf/cm", 38.9, "Hamabe Example 1, case c"),
    Worked("hamabe-d", "spring stiffness", "kgf/cm", 21.95, "Hamabe Example 1, case d"),
    Worked("hamabe-d-prime", "spring stiffness", "kgf/cm", 29.3, "Hamabe Example 1, case d'"),
    Worked("hamabe-a", "irregularity", "", 0.119, "Hamabe Example 1, case a",
           "the paper's closing check uses omega_a^2 = 700 where its own M_za gives 711, and "
           "rounds the spring arms (theory/shaft.md)"),
)


@dataclass(frozen=True)
class Literature:
    """An optimisation problem of the literature: its best known value and govopt's."""

    name: str
    best_known: float
    where: str
    why: str


LITERATURE = (
    Literature("Belegundu / Arora spring, printed constant 71785", 0.0126652,
               "Belegundu 1982, Arora: best known (N + 2) D d^2",
               "an exact GP with a certified bound (theory/springs.md)"),
    Literature("Belegundu / Arora spring, the data's constant 71875", 0.0126652,
               "the same problem with the constant its data give",
               "the printed 71785 is a slip for 71875 = 1.15e7 x 0.5 / 80; the best known value "
               "is the printed constant's"),
    Literature("Sandgren 1990 mixed-discrete spring", 2.65856,
               "Sandgren 1990 as restated by Deb and Goyal: best known pi^2 D d^2 (N + 2) / 4",
               "exact enumeration over the 42 wires and whole coils"),
)


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _worked_rows() -> list[str]:
    import govopt
    from govopt.examples import example

    results: dict = {}
    rows = ["| example | figure | source | govopt | difference | where | why |",
            "|---|---|---|---|---|---|---|"]
    for w in WORKED:
        if w.spec not in results:
            results[w.spec] = {f.name: f for f in
                               govopt.evaluate(govopt.load_spec(example(w.spec))).figures()}
        si = results[w.spec][w.figure].value
        value = si / RPM if w.unit == "rpm" else si / KGF_CM if w.unit == "kgf/cm" else si
        unit = f" {w.unit}" if w.unit else ""
        diff = (value - w.source_value) / w.source_value
        rows.append(f"| `{w.spec}` | {w.figure} | {_fmt(w.source_value)}{unit} | "
                    f"{_fmt(value)}{unit} | {diff:+.2%} | {w.where} | {w.why} |")
    return rows


def _literature_rows() -> list[str]:
    from govopt.optimize.spring_literature import constants, solve_belegundu, solve_sandgren

    printed, data = solve_belegundu(), solve_belegundu(constants()["c1"])
    sandgren = solve_sandgren()
    ours = [(printed.objective, f"certified bound {printed.lower_bound:.8g}"),
            (data.objective, f"certified bound {data.lower_bound:.8g}"),
            (sandgren.objective, f"N {sandgren.N}, d {sandgren.d} in, D {sandgren.D:.6g} in; "
                                 f"{sandgren.checked} pairs enumerated")]
    rows = ["| problem | best known | govopt | difference | govopt's certificate | where | "
            "why |", "|---|---|---|---|---|---|---|"]
    for lit, (value, cert) in zip(LITERATURE, ours, strict=True):
        rows.append(f"| {lit.name} | {lit.best_known:.8g} | {value:.8g} | "
                    f"{(value - lit.best_known) / lit.best_known:+.2e} | {cert} | {lit.where} | "
                    f"{lit.why} |")
    return rows


def _bench_rows() -> list[str]:
    from importlib.resources import files

    text = files("govopt").joinpath("data/speed-vs-error.csv").read_text(encoding="utf-8")
    rows = ["| analysis | method | setting | time (s) | error | worst case | |",
            "|---|---|---|---|---|---|---|"]
    for r in csv.DictReader(text.splitlines()):
        marks = " ".join(m for m, key in (("P", "pareto"), ("D", "default"))
                         if r[key] == "True")
        error = r["error"] if r["error"] in ("", "nan", "inf") else f"{float(r['error']):.2g}"
        rows.append(f"| {r['analysis']} | {r['method']} | {r['setting']} | "
                    f"{float(r['time_s']):.2g} | {error} | {r['worst_case']} | {marks} |")
    return rows


def page() -> str:
    """The whole of ``docs/validation.md``."""
    out = ["# Validation: agreement with the sources and with high-precision references", "",
           "Generated by `python tools/validation_docs.py docs/validation.md` from runs of the "
           "code: do not edit by hand (a test fails when it is stale). Where govopt and a "
           "source differ, the last column says which is right and why; the tests hold each "
           "figure to its tolerance with the same reason beside it.", "",
           "## Worked examples of the sources", "",
           "The bundled specs of the sources' worked examples (`govopt init NAME` copies one), "
           "govopt's figure against the one the source prints. A difference of a few tenths "
           "of a per cent is the source's rounding.", ""]
    out += _worked_rows()
    out += ["", "## Problems of the optimisation literature", "",
            "The spring problems the optimisation literature uses as benchmarks, solved "
            "exactly (`govopt.optimize.spring_literature`; `govopt init belegundu-arora` and "
            "`govopt init sandgren-1990` state them as spring specs).", ""]
    out += _literature_rows()
    out += ["", "## High-precision references and speed against error", "",
            "Every analysis's methods and settings on a suite with the hard cases (repeated "
            "roots, the Hurwitz boundary, stiff spreads, resonance), each error against a "
            "high-precision reference (mpmath, a dense harmonic sum, the nonlinear equations at "
            "tight tolerance), from the last full `govopt bench` run "
            "(`govopt/data/speed-vs-error.csv`; `govopt bench --out DIR` measures it again on "
            "your machine, `--quick` in under a minute). Time: CPU seconds per evaluation; "
            "error: relative, worst over the suite; P: on the analysis's Pareto front of time "
            "and error; D: govopt's default.", ""]
    out += _bench_rows()
    return "\n".join(out) + "\n"


def main(argv: list[str] | None = None) -> None:
    argv = sys.argv[1:] if argv is None else argv
    text = page()
    if argv:
        Path(argv[0]).write_text(text, encoding="utf-8")
        print(f"wrote {argv[0]}")
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
