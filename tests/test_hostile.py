"""Hostile inputs: a corpus of more than a thousand mutated specs,
hostile files and options (:mod:`hostile`), for every governor type and every command
(evaluate, design, spring, study run), degenerate geometries of every type, study databases
(another study's, damaged, empty, foreign) and the outputs of study, init and bench (issue
21), run in-process through the CLI with a time limit each, and a sample through the real
command line. Every one is answered with a result, or with one line naming the file and the
key (exit 2): no traceback, no hang, no silent result, no warning noise. The terminal summary
shows "N hostile inputs: 0 tracebacks, 0 hangs, 0 silent results"."""

import resource

import hostile
import pytest

from govopt.governors import REGISTRY
from govopt.limits import MAX_ROBUST_SEARCH_SECONDS

#: cases and estimated seconds of the in-process corpus (at least a case for every governor
#: type, command and mutation kind, and for every type, command and key)
BUDGET, SECONDS = 2000, 40
#: a case running longer than this is a hang: past govopt's own limit of work for one search
#: (govopt.limits.MAX_ROBUST_SEARCH_SECONDS of estimated evaluations, which a made-governor
#: design of a traction coil, a friction run a sample, uses nearly whole) with as much again for
#: reading, the nominal design and the report on a loaded machine
LIMIT = 2.0 * MAX_ROBUST_SEARCH_SECONDS
#: the sample run through the real command line, one process each
SAMPLE = (
    "file/not UTF-8/evaluate", "file/deep arrays/evaluate", "file/larger than 1 MiB/design",
    "file/a FIFO", "file//dev/zero", "output//proc",
    "hamabe-a/governor.a/huge_int", "hamabe-a/governor.a/long_sum",
    "hamabe-a/governor.a/power_tower", "hamabe-a/design.wire_diameter/tiny",
    "hamabe-design/analysis.points/size_limit", "hamabe-design/analysis.harmonics/size_limit#2",
    "hamabe-design/catalogue.turn_step/size_limit", "hamabe-a/load_change/size_limit",
    "hamabe-design/engine.flywheel_inertia/huge", "spring/--force/power_tower",
    "hamabe-study/option/sweep of 1e8 points", "hamabe-study/option/sweep of 9**9**9",
    "traction-leaf-assembly/material/missing", "textbook-ex1-porter/name/text_control",
    "spring/--force/not_utf8", "output/-o into the package, --force",
    "option/--speed-change 1e-300/evaluate",
)
#: run in a new interpreter too (a design: the optimiser is imported on demand)
FRESH = ("hamabe-design/analysis.points/size_limit",)


def _report(outcomes, what: str) -> str:
    counts = hostile.summary(outcomes)
    line = hostile.summary_line(outcomes)
    hostile.SUMMARY.append(f"{line} ({what}; {counts['ok']} results, {counts['error']} "
                           f"one-line errors, {counts['unclear']} unclear)")
    bad = [o.line() for o in outcomes if o.klass not in ("ok", "error")]
    return line + "\n" + "\n".join(bad[:40])


@pytest.mark.slow  # ~25-30 s: first, so that the other worker runs the rest beside it
def test_hostile_corpus(tmp_path):
    cases = hostile.corpus(BUDGET, SECONDS)
    assert len(cases) >= 1000
    assert {c.gtype for c in cases} >= set(REGISTRY)
    assert {c.command for c in cases} == {"evaluate", "design", "spring", "study", "init",
                                          "bench"}
    assert {c.kind for c in cases} >= {"degenerate_long", "degenerate_near", "degenerate_wire",
                                       "degenerate_turns", "angle_in_unit", "incomplete",
                                       "unbalanced", "divide_by_zero", "not_utf8",
                                       "band_spring", "band_narrow", "impossible_spring"}
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    outcomes = [hostile.run(c, tmp_path, LIMIT, json_out=i % 2 == 1)
                for i, c in enumerate(cases)]
    grown = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - rss) / 1024  # MB (Linux)
    text = _report(outcomes, f"in-process, peak memory +{grown:.0f} MB")
    assert all(o.klass in ("ok", "error") for o in outcomes), text
    assert grown < 1024, f"the corpus grew the peak memory by {grown:.0f} MB"
    # no warning noise: none after an error line, none after a result either
    noisy = [f"{o.case.id}: {o.warnings[:2]}" for o in outcomes if o.warnings]
    assert not noisy, "\n".join(noisy[:20])


def test_hostile_sample_through_the_real_cli(tmp_path):
    """Each case of :data:`SAMPLE` in a process of its own, forked from a server that has
    imported govopt (:mod:`forkcli`); and :data:`FRESH` in a new interpreter as well, with
    the imports on demand of ``python -m govopt.cli`` (the same answer both ways)."""
    cases = {c.id: c for c in hostile.corpus()}
    # one after the other: a forked process takes ~0.05 s here
    outcomes = [hostile.run_cli(cases[i], tmp_path, 60.0) for i in SAMPLE]
    fresh = [hostile.run_cli(cases[i], tmp_path, 60.0, fresh=True) for i in FRESH]
    text = _report(outcomes + fresh, "through the real command line")
    assert all(o.klass in ("ok", "error") for o in outcomes + fresh), text
    assert sum(o.klass == "error" for o in outcomes) >= len(SAMPLE) - 2
    forked = {o.case.id: o for o in outcomes}
    for o in fresh:
        assert (o.code, o.stdout, o.stderr) == (forked[o.case.id].code,
                                                forked[o.case.id].stdout,
                                                forked[o.case.id].stderr), o.case.id
