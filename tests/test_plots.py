"""Plots: every plot of every governor type is drawn from the Result, the files
exist and are not blank, the CLI writes them through the no-clobber policy, and the numbers a
plot shows are the Result's (the diagram's curves checked against their defining equations)."""

import math
import subprocess
import sys
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from clirun import invoke

import govopt
import govopt.examples
from govopt.analysis import vyshnegradsky as vy
from govopt.evaluator import evaluate
from govopt.governors import REGISTRY
from govopt.report import plot_files, plots
from govopt.spec import load_spec

SPECS = govopt.examples.SPECS
CLI = [sys.executable, "-m", "govopt.cli"]


def _result(name: str):
    return evaluate(load_spec(SPECS / f"{name}.toml"))


def _graded(tmp_path: Path, name: str = "hamabe-a", extra: str = "") -> Path:
    """A copy of a bundled shaft spec with a wire grade (the spring report's fatigue)."""
    text = (SPECS / f"{name}.toml").read_text(encoding="utf-8")
    path = tmp_path / f"{name}-graded.toml"
    path.write_text(text.replace("[material]\n", f'[material]\ngrade = "EN10270-1 DH"\n{extra}',
                                 1), encoding="utf-8")
    return path


def _check_png(path: Path) -> None:
    import matplotlib.image as mpimg

    img = mpimg.imread(path)
    assert img.shape[:2] == (round(plots.SIZE[1] * plots.DPI), round(plots.SIZE[0] * plots.DPI))
    grey = img[..., :3].mean(axis=2)
    assert grey.std() > 0.05, f"{path.name} is blank"  # white page with lines and text
    assert (grey < 0.5).mean() > 0.005, f"{path.name} has hardly any ink"


def _check_svg(path: Path) -> None:
    root = ET.parse(path).getroot()
    assert root.tag.endswith("svg")
    assert len(list(root.iter("{http://www.w3.org/2000/svg}path"))) > 20, path.name


# ---------------------------------------------------------------------------- files


@pytest.mark.parametrize("name, expected", [
    ("hamabe-a-graded", ["characteristic", "linkage", "k2", "load-change-1", "vyshnegradsky",
                         "vibration-spectrum", "vibration-trace", "fatigue"]),
    ("porter-engine", ["characteristic", "linkage", "controlling-force", "k2", "load-change-1",
                       "vyshnegradsky"]),
])
def test_write_plots_png_and_svg_not_blank(tmp_path, name, expected):
    """Every plot of a shaft governor (hamabe-a, given a wire grade: the spring report's fatigue
    diagram last) and of a Porter with an engine, written as PNG and SVG under the spec file's
    name; none is blank. hamabe-a without a grade has every plot but the fatigue diagram."""
    if name == "hamabe-a-graded":
        assert plots.kinds(_result("hamabe-a")) == expected[:-1]
        res = evaluate(load_spec(_graded(tmp_path)))
        tmp_path = tmp_path / "out"  # the plots alone in their folder
        tmp_path.mkdir()
    else:
        res = _result(name)
    assert plots.kinds(res) == expected
    written = plot_files.write_plots(res, tmp_path)
    assert [p.name for p in written] == [f"{name}-{k}.{f}" for k in expected
                                         for f in plots.FORMATS]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in written)
    for p in written:
        (_check_png if p.suffix == ".png" else _check_svg)(p)


def test_files_are_reproducible_and_never_clobbered(tmp_path):
    """The same result gives the same bytes (no date in the SVG, fixed ids); an existing plot is
    replaced only with overwrite (the CLI's --force)."""
    res = _result("textbook-ex1-porter")
    first = plot_files.write_plots(res, tmp_path, formats=("svg",))
    assert sorted(tmp_path.iterdir()) == sorted(first) and len(first) == 4
    before = {p: p.read_bytes() for p in first}
    inode = {p: p.stat().st_ino for p in first}
    with pytest.raises(govopt.errors.GovoptError, match="already exists"):
        plot_files.write_plots(res, tmp_path, overwrite=False, formats=("svg",))
    assert {p: p.read_bytes() for p in first} == before  # refused: nothing written
    again = plot_files.write_plots(res, tmp_path, overwrite=True, formats=("svg",))
    assert again == first and sorted(tmp_path.iterdir()) == sorted(first)
    for p in first:  # drawn and written anew (a new file renamed over it): the same bytes
        assert p.stat().st_ino != inode[p] and p.read_bytes() == before[p], p.name


# ---------------------------------------------------------------------------- every type


def _one_spec_per_type() -> dict[str, Path]:
    """A bundled spec with a [design] per type, else its design problem (run by `design`)."""
    out = {}
    for path in sorted(SPECS.glob("*.toml"), key=lambda p: "[design]" not in p.read_text()):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        if "study" not in data and ("design" in data or "requirements" in data):
            out.setdefault(data["governor"]["type"], path)
    return out


PER_TYPE = _one_spec_per_type()


def _evaluated_or_designed(path: Path):
    spec = load_spec(path)
    if spec.design is not None:
        return evaluate(spec)
    from govopt.optimize.design import design

    return design(spec)


def test_every_registered_type_has_a_bundled_spec_to_plot():
    assert sorted(PER_TYPE) == sorted(REGISTRY)


@pytest.mark.parametrize("type_name", sorted(PER_TYPE))
def test_every_plot_of_every_type_draws_the_results_numbers(type_name):
    """Each plot of one spec per type draws; the characteristic's curve is the Result's speed in
    rpm; ball governors get the controlling-force diagram, whose constant-speed lines through the
    origin have the slope m omega^2 of F = m omega^2 r at the inner and outer radii."""
    res = _evaluated_or_designed(PER_TYPE[type_name])
    gov = res.spec.governor
    names = plots.kinds(res)
    assert names[0] == "characteristic" and "k2" in names
    assert ("controlling-force" in names) == (gov.coordinate == "length")
    for name in names:
        ax = plots.draw(res, name)
        assert ax.get_title().startswith(res.spec.name) and ax.get_xlabel() and ax.get_ylabel()
        assert "(" in ax.get_xlabel() and "(" in ax.get_ylabel(), "axis labels carry units"
    ax = plots.draw(res, "characteristic")
    curve = ax.lines[0]
    np.testing.assert_allclose(curve.get_ydata(), res.statics.omega * 30.0 / math.pi, rtol=1e-12)
    np.testing.assert_allclose(curve.get_xdata(), gov.shown(res.statics.alpha)[0], rtol=1e-12)
    if gov.coordinate == "length":
        ax = plots.draw(res, "controlling-force")
        rays = [ln for ln in ax.lines if len(ln.get_xdata()) == 2 and ln.get_xdata()[0] == 0.0]
        assert len(rays) == 3
        for ray, i in zip(rays[::2], (0, -1), strict=True):
            (x0, x1), (y0, y1) = ray.get_xdata(), ray.get_ydata()
            slope = (y1 - y0) / ((x1 - x0) * 1e-3)  # N per m (the axis is in mm)
            assert slope == pytest.approx(res.spring.m * res.statics.omega[i] ** 2, rel=1e-12)


# ---------------------------------------------------------------------------- the numbers


def test_vyshnegradsky_boundaries_satisfy_their_equations():
    """The discriminant curve has a double root (discriminant 0) and separates aperiodic from
    the rest; 2A^3 - 9AB + 27 = 0 separates monotonic (above) from oscillatory (below); AB = 1."""
    c = vy.boundaries(12.0)
    A, B = c["aperiodic"]
    disc = 18 * A * B - 4 * A**3 + A**2 * B**2 - 4 * B**3 - 27
    assert np.max(np.abs(disc) / np.maximum(A, B) ** 4) < 1e-12
    for a, b in zip(A[::50], B[::50], strict=True):
        roots = np.roots([1.0, a, b, 1.0])
        gaps = np.abs(roots[:, None] - roots[None, :])[np.triu_indices(3, 1)]
        assert np.min(gaps) < 1e-4  # a double root (numerically split by ~sqrt(eps))
    A, B = c["monotonic"]
    assert np.max(np.abs(2 * A**3 - 9 * A * B + 27) / (9 * A * B)) < 1e-12
    inner = (A > 0.2) & (A < 2.9)
    assert all(vy.region(a, 1.01 * b) == "monotonic" and vy.region(a, 0.99 * b) == "oscillatory"
               for a, b in zip(A[inner], B[inner], strict=True))
    A, B = c["stability"]
    np.testing.assert_allclose(A * B, 1.0, rtol=1e-14)


def test_vyshnegradsky_point_and_region_are_the_load_changes():
    res = _result("porter-engine")
    ax = plots.draw(res, "vyshnegradsky")
    lc = res.dynamics["load_changes"][0]["vyshnegradsky"]
    (pt,) = [ln for ln in ax.lines if len(ln.get_xdata()) == 1]
    assert (pt.get_xdata()[0], pt.get_ydata()[0]) == (lc["A"], lc["B"])
    assert lc["region"] in pt.get_label() and lc["region"] == "monotonic"


def test_load_change_plot_marks_equilibrium_band_and_over_regulation():
    """hamabe-d over-regulates: the dash-dot line sits at the largest swing past the new
    equilibrium, which is the response's own extreme (to the response table's resolution)."""
    res = _result("hamabe-d")
    lc = res.dynamics["load_changes"][0]
    ax = plots.draw(res, "load-change-1")
    to = res.spec.load_changes[0].alpha_to
    over = math.degrees(lc["over_regulation_rad"])
    assert over > 1.0
    line = next(ln for ln in ax.lines if ln.get_label().startswith("over-regulation"))
    assert line.get_ydata()[0] == pytest.approx(math.degrees(to) + over, rel=1e-12)
    peak = math.degrees(to + max(lc["response"]["xi_rad"]))
    assert peak == pytest.approx(math.degrees(to) + over, abs=2e-3)  # 200 samples: ~1e-3 deg
    band = next(p for p in ax.patches if p.get_label().startswith("settling band"))
    half = math.degrees(lc["settling_band"] * abs(lc["initial_state"]["xi_rad"]))
    ys = band.get_patch_transform().transform(band.get_path().vertices)[:, 1]  # y in data
    assert (ys.max() - ys.min()) / 2 == pytest.approx(half, rel=1e-9)
    assert (ys.max() + ys.min()) / 2 == pytest.approx(math.degrees(to), rel=1e-12)


def test_vibration_trace_is_the_sum_of_the_harmonics():
    """The trace over one revolution (Hamabe eq. 22) has the analysis's peak-to-peak (sampled
    every 2 deg: below it by at most the curvature over 1 deg) and its value at tau = 0 is the
    mean offset plus the sum of the cosine amplitudes."""
    res = _result("hamabe-a")
    vib = res.dynamics["vibration"]
    xi = np.asarray(vib["response"]["xi_rad"])
    assert len(xi) == 181 and vib["response"]["crank_angle_rad"][-1] == pytest.approx(2 * math.pi)
    p2p = vib["peak_to_peak_rad"]
    assert 0.0 <= p2p - (xi.max() - xi.min()) < 1e-3 * p2p
    assert xi[0] == pytest.approx(vib["mean_offset_rad"]
                                  + sum(h["cos_rad"] for h in vib["harmonics"]), rel=1e-12)
    ax = plots.draw(res, "vibration-spectrum")
    heights = [b.get_height() for b in ax.patches]
    np.testing.assert_allclose(heights, [math.degrees(h["amplitude_rad"])
                                         for h in vib["harmonics"]], rtol=1e-12)


@pytest.mark.parametrize("rules", ["EN13906", "Shigley"])
def test_fatigue_diagram_reads_the_checks_safety_factor(tmp_path, rules):
    """The body's fatigue safety factor of the Result's checks, read off the plotted diagram:
    EN 13906-1, the admissible stroke at the cycle's lower stress over the actual stroke;
    Shigley, the load line's meeting with the Goodman line over the amplitude."""
    res = evaluate(load_spec(_graded(tmp_path, "hamabe-d", f'rules = "{rules}"\n')))
    fat = res.spring_report.loads["fatigue"]
    dia = fat["diagram"]
    assert dia["method"] == rules
    want = res.check("body fatigue safety factor").value
    stresses = [f for f in (*fat.values(), *dia["locus"].values()) if hasattr(f, "unit")
                and "stress" in f.name]
    assert len(stresses) == 6 and {f.unit for f in stresses} == {"Pa"}  # units are fields
    value = {k: f.value for k, f in (*fat.items(), *dia["locus"].items()) if hasattr(f, "unit")}
    if rules == "EN13906":
        lo, hi = value["corrected stress min"], value["corrected stress max"]
        top = np.interp(lo, value["lower stress"], value["upper stress"])
        got = (top - lo) / (hi - lo)
    else:
        m = np.asarray(value["midrange stress"])
        a = np.asarray(value["amplitude stress"])
        r = value["alternating stress"] / value["mean stress"]
        # a - r m falls along the line: the meeting point by linear interpolation (exact)
        m_star = np.interp(0.0, (r * m - a), m)
        got = r * m_star / value["alternating stress"]
    assert got == pytest.approx(want, rel=1e-9)
    ax = plots.draw(res, "fatigue")
    assert any(f"{want:.3g}" in t.get_text() for t in ax.get_legend().get_texts())


def test_fatigue_diagram_draws_the_hooks_at_their_checks_safety_factors(tmp_path):
    """An extension spring's hooks (the binding hook A was only in the legend): the
    inset's load lines meet the Goodman line (x + y = 1 in the hooks' normalised coordinates)
    at each hook check's safety factor times its cycle, and the governing hook is red."""
    res = evaluate(load_spec(_graded(tmp_path, "hamabe-d")))
    hooks = res.spring_report.loads["fatigue"]["hooks"]
    assert hooks["criterion"] == "goodman"
    ax = plots.draw(res, "fatigue")
    (inset,) = ax.child_axes
    marks = {tuple(np.round(line.get_xydata()[0], 12)): line.get_color()
             for line in inset.get_lines() if line.get_marker() == "x"}
    assert len(marks) == 2
    checks = {p: res.check(f"hook {p} fatigue safety factor") for p in "AB"}
    governs = min(checks.values(), key=lambda c: c.margin)
    for point, check in checks.items():
        h = hooks[point]
        x = h["midrange"].value / h["ultimate"].value
        y = h["amplitude"].value / h["endurance"].value
        assert check.value * (x + y) == pytest.approx(1.0, rel=1e-9)  # on the Goodman line
        mark = (round(check.value * x, 12), round(check.value * y, 12))
        assert mark in marks, (point, marks)
        assert (marks[mark] == "tab:red") == (check is governs)


# ---------------------------------------------------------------------------- API and CLI


def test_result_plot_api():
    from matplotlib.figure import Figure

    res = _result("porter-engine")
    fig = Figure()
    ax = fig.add_subplot()
    assert res.plot("k2", ax=ax) is ax and ax.lines
    overview = res.plot()
    assert isinstance(overview, Figure)
    assert sum(1 for a in overview.axes if a.get_title()) == len(plots.kinds(res))
    with pytest.raises(ValueError, match="it has: characteristic, linkage, controlling-force"):
        res.plot("vibration-trace")
    with pytest.raises(ValueError, match="name a kind"):
        res.plot(ax=ax)


def test_help_does_not_import_matplotlib():
    code = ("import sys; sys.argv = ['govopt', '--help']\n"
            "import govopt.cli as c\n"
            "try:\n    c.main()\nexcept SystemExit:\n    pass\n"
            "print('MPL', 'matplotlib' in sys.modules)")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "MPL False" in p.stdout and "--plots" not in p.stdout  # a command's option
    p = subprocess.run(CLI + ["evaluate", "--help"], capture_output=True, text=True, check=True)
    assert "--plots" in p.stdout


def test_cli_plots_written_refused_and_forced(tmp_path):
    # the book's answer (3.572 kgf/cm) spans 0.002 % more than its 240-256.8 rpm band, which
    # evaluate requires: a passing copy with the band's top at 257 rpm
    text = (SPECS / "textbook-ex4-hartnell.toml").read_text()
    assert 'outer = "256.8 rpm"' in text
    (tmp_path / "spec").mkdir()
    spec = tmp_path / "spec" / "textbook-ex4-hartnell.toml"
    spec.write_text(text.replace('outer = "256.8 rpm"', 'outer = "257 rpm"'))
    out = tmp_path / "plots"  # made by the run (its parent exists)
    run = invoke(["evaluate", spec, "--plots", out], cwd=tmp_path)
    assert run.exit_code == 0, run.output
    names = [f"textbook-ex4-hartnell-{k}.{f}" for k in ("characteristic", "linkage",
                                                         "controlling-force", "k2")
             for f in ("png", "svg")]
    assert sorted(p.name for p in out.iterdir()) == sorted(names)
    assert [ln for ln in run.stdout.splitlines() if ln.startswith("wrote")] == \
        [f"wrote {out / n}" for n in names]
    for n in names:
        (_check_png if n.endswith(".png") else _check_svg)(out / n)
    before = {n: (out / n).stat().st_mtime_ns for n in names}
    again = invoke(["evaluate", spec, "--plots", out], cwd=tmp_path)
    assert again.exit_code == 2 and "already exists; use --force" in again.stderr
    assert "Characteristic" not in again.stdout  # refused before the run
    assert {n: (out / n).stat().st_mtime_ns for n in names} == before
    forced = invoke(["evaluate", spec, "--plots", out, "--force"], cwd=tmp_path)
    assert forced.exit_code == 0, forced.output
    assert all((out / n).stat().st_mtime_ns > before[n] for n in names)
    bad = invoke(["evaluate", spec, "--plots", out / names[0]], cwd=tmp_path)
    assert bad.exit_code == 2 and "not a folder" in bad.stderr


# ---------------------------------------------------------------- plots not misread


def test_k2_axis_is_the_datas_where_the_ceiling_is_far():
    """A Porter has no forcing modelled: its k^2 plot has no ceiling. Asked for Hamabe's band
    (``k2_margin``), its k^2 (24-31 1/s^2) against omega0^2 = 396: the axis is scaled to k^2
    (not a 0-396 band with the curve squashed at its foot), the ceiling named with its spare; a
    textbook governor's band is not called Hamabe's case; the shaft's still shows omega0^2."""
    from dataclasses import replace

    from matplotlib.colors import to_rgba

    from govopt.inputs import Requirements

    res = _result("porter-engine")
    labels = [t.get_text() for t in plots.draw(res, "k2").get_legend().get_texts()]
    assert any("no ceiling" in t for t in labels) and not any("spare" in t for t in labels)
    spec = load_spec(SPECS / "porter-engine.toml")
    res = evaluate(replace(spec, requirements=Requirements(k2_margin=0.0)))
    ax = plots.draw(res, "k2")
    w0sq = res.omega_reference ** 2
    lo, hi = ax.get_ylim()
    assert hi < 0.25 * w0sq and hi > float(np.max(res.k2))
    span = float(np.ptp(res.k2)) / (hi - lo)
    assert span > 0.1  # the curve spans a visible share of the axis (was 2 %)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("above the axis" in t and "spare" in t for t in labels), labels
    assert not any("Hamabe" in t for t in labels)
    shaft = plots.draw(_result("hamabe-a"), "k2")
    assert shaft.get_ylim()[1] > _result("hamabe-a").omega_reference ** 2
    assert any("Hamabe Part II, case 1" in t.get_text() for t in shaft.get_legend().get_texts())
    # the Vyshnegradsky point is not the red of the unstable region
    vy_ax = plots.draw(res, "vyshnegradsky")
    (pt,) = [ln for ln in vy_ax.lines if len(ln.get_xdata()) == 1]
    assert to_rgba(pt.get_markerfacecolor()) != to_rgba("tab:red")


def test_k2_required_margin_is_drawn():
    """A spec that requires a k^2 margin: its line at the check's limit."""
    from govopt.optimize.design import design

    res = design(load_spec(SPECS / "hamabe-design.toml"))
    limit = res.check("k^2 > 0 (stability)").limit
    assert limit > 0
    ax = plots.draw(res, "k2")
    assert any(np.allclose(ln.get_ydata(), limit) for ln in ax.lines
               if len(ln.get_ydata()) == 2)


def test_characteristic_legend_with_friction_is_outside_the_curves():
    """With friction (three curves across the axes) the legend sits below the axes."""
    ax = plots.draw(_result("textbook-ex5-hartnell"), "characteristic")
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "opening against friction" in labels
    fig = ax.figure
    fig.canvas.draw()
    legend = ax.get_legend().get_window_extent()
    assert legend.y1 <= ax.get_window_extent().y0  # below the axes


def test_bench_plot_draws_an_exact_error_on_its_own_line_and_joins_near_labels(tmp_path):
    """`govopt bench`'s plot: an error of 0 sits a decade below the least nonzero error (not at
    1e-17, twelve decades down), on a line that says it is exact; two settings at the same
    point share one label ("grids x2, x4") instead of printing over each other."""
    from matplotlib.figure import Figure

    from govopt.bench import report as bench

    assert bench.zero_floor([0.0, 5e-3, 0.17]) == pytest.approx(1e-4)
    assert bench.zero_floor([0.0]) == 1e-3
    ax = Figure().add_subplot()
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(0.03, 0.06)
    bench.label_points(ax, [(0.0410, 5e-3, "grids x2"), (0.0385, 5e-3, "grids x4"),
                            (0.0552, 1e-4, "full catalogue")])
    texts = sorted(t.get_text() for t in ax.texts)
    assert texts == ["full catalogue", "grids x2, x4"]
    # a label at the right edge is written to the left of its point, inside the axes
    align = {t.get_text(): t.get_horizontalalignment() for t in ax.texts}
    assert align == {"full catalogue": "right", "grids x2, x4": "left"}
    points = [bench.Point("optimiser", "exhaustive", s, t, e) for s, t, e in (
        ("full", 0.055, 0.0), ("grids x2", 0.041, 5e-3), ("grids x4", 0.0385, 5e-3))]
    bench.plot(points, tmp_path / "p.png")
    assert (tmp_path / "p.png").stat().st_size > 1000
