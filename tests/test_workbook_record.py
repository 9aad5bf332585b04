"""The workbook as a record of the governor it describes, for every bundled spec and for
`govopt spring`: LibreOffice converts each workbook to PDF; page 1 holds the verdict and the
chosen design; no text prints under 8 pt (the cells' fonts at their sheet's scale, and the
words of the PDF); each type's Method sheet states its own method and sources (no Hamabe
equation, valve gear or half length where the type has none), and its Sources name the type's
own source and the standards its checks cite."""

from __future__ import annotations

import re
import shutil
import subprocess
import tomllib
from pathlib import Path

import openpyxl
import pytest
from test_excel import SOFFICE, _recalculate

import govopt
from govopt.references import REFERENCES, found_in
from govopt.report import excel

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"
ALL = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(SPECS.glob("*.toml"))}
PDFTOTEXT = shutil.which("pdftotext")
#: The height of a line of text in the PDF per point of font size: LibreOffice draws with
#: DejaVu Sans where Calibri is missing, whose line box (ascent + descent) is 1.164 em (read off
#: its PDF: 11 pt at 80 % gives words 10.25 pt tall).
LINE_EM = 1.16
#: The citations of the shaft governor's paper a non-shaft type may show, each with the check
#: of the analysis it sources: the resonance ceiling the ball and bell-crank governors keep,
#: and the friction strokes of a load change against a friction band (Hamabe's solution,
#: which govopt applies on the seam to every type).
SHARED_HAMABE = {"Hamabe Part II, case 2": "k^2 < omega0^2 (no resonance)",
                 "Hamabe eqs. 42-46": "friction: "}
#: Each type's own source in its Method sheet: (bibliography key, a place the type cites).
OWN = {"shaft": ("hamabe", "Hamabe eq. 12"), "watt": ("textbook-ch3", "textbook 3.4(a)"),
       "porter": ("textbook-ch3", "textbook 3.4(b)"), "proell": ("textbook-ch3", "textbook 3.4(c)"),
       "hartnell": ("textbook-ch3", "textbook 3.5(a)"),
       "spring_loaded": ("textbook-ch3", "textbook 3.5(b)"),
       "spring_gravity": ("textbook-ch3", "textbook 3.5(c)"),
       "traction_coil": ("traction-article", "article eq. 1"),
       "traction_leaf": ("traction-article", "article eqs. 5-6"),
       "force_line": ("textbook-ch3", "textbook 3.3")}

pytestmark = [pytest.mark.libreoffice,
              pytest.mark.skipif(SOFFICE is None or PDFTOTEXT is None,
                                 reason="LibreOffice (soffice) or pdftotext not on PATH")]


@pytest.fixture(scope="module")
def records(tmp_path_factory):
    """name -> (result, workbook path, PDF pages' text, PDF words' boxes) for every bundled
    spec (evaluated where it gives a design, designed where it does not), all converted by
    one LibreOffice call."""
    folder = tmp_path_factory.mktemp("records")
    results, books = {}, {}
    for name, data in ALL.items():
        spec = govopt.load_spec(SPECS / f"{name}.toml")
        results[name] = govopt.evaluate(spec) if "design" in data else govopt.design(spec)
        books[name] = excel.write_workbook(results[name], folder / f"{name}.xlsx")
    pdfs = _recalculate(list(books.values()), folder / "pdf", folder / "profile", pdf=True)
    return {name: (results[name], books[name], *_read_pdf(pdfs[books[name]]))
            for name in ALL}


def _read_pdf(pdf: Path) -> tuple[list[str], list[tuple[float, float, str]]]:
    """The PDF's pages as text, and its words as (width, height, word) in pt."""
    text = subprocess.run([PDFTOTEXT, "-layout", str(pdf), "-"], check=True,
                          capture_output=True, text=True).stdout
    boxes = subprocess.run([PDFTOTEXT, "-bbox", str(pdf), "-"], check=True,
                           capture_output=True, text=True).stdout
    words = [(float(m[2]) - float(m[0]), float(m[3]) - float(m[1]), m[4]) for m in re.findall(
        r'xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">([^<]*)</word>',
        boxes)]
    return text.split("\f"), words


def test_every_bundled_spec_has_a_record(records):
    """The 32 bundled specs, each a workbook LibreOffice converts: the Summary first, page 1
    holding the verdict and the chosen design (the flying mass, the spring where the type has
    one, the dash-pot where the design has one), every page naming the design at its top and
    'page x of y' at its foot."""
    assert len(records) == 33
    long_summaries = []
    for name, (res, path, pages, _) in records.items():
        assert openpyxl.load_workbook(path, read_only=True).sheetnames[0] == "Summary"
        first = pages[0]
        # a spec with a made requirement reads "PASS as made: ..." (the made verdict, merged
        # with govopt.report.text's verdict line; tests/test_made.py), others "PASS: ..."
        assert re.search(r"^\s*(PASS|FAIL)( as made)?: ", first, re.M), name
        gov = res.spec.governor
        assert f"{gov.mass_name} weight (each)" in first, name
        if res.spring_report is not None:
            assert "wire diameter d" in first and "free length L0" in first, name
        elif gov.spring is not None:
            assert re.search(r"stiffness|leaf", first), name
        if res.design.dashpot is not None:
            assert "dash-pot f" in first, name
        assert "Checks to watch" in first, name
        pages = [p for p in pages if p.strip()]
        if sum("Summary, page" in p for p in pages) != 1:  # the Summary on one page
            long_summaries.append(name)
        for k, page in enumerate(pages, start=1):
            assert f"govopt {'design' if res.optimisation else 'evaluation'}: {res.spec.name}" \
                in page, (name, k)
            assert re.search(rf"page {k} of {len(pages)}", page), (name, k)
    # KNOWN, to mend: two records' made-verdict notes under the verdict (the tolerances made to,
    # the fitter's setting with its source) run their Summary onto a second page; no other may
    assert set(long_summaries) <= {"spring_loaded-design-robust", "traction-coil-design"}, \
        long_summaries


def test_no_text_under_8_pt(records):
    """No cell's font prints under 8 pt (its size times its sheet's print scale), and no word
    of the PDF is drawn smaller (its height over the font's line box; words of four letters or
    more set across the page: an axis title set upwards has its length as its height)."""
    for name, (res, _, _, words) in records.items():
        built = excel.build_workbook(res)
        for ws in built.worksheets:
            assert excel.printed_font(excel.layout(ws)) >= 8.0, (name, ws.title)
        across = [(h, w) for width, h, w in words if len(w) >= 4 and width >= h]
        smallest = min(across)
        assert smallest[0] / LINE_EM >= 8.0 - 1e-9, (name, smallest)


def _method_text(path: Path) -> tuple[str, str]:
    """The Method sheet's text: its equations and settings, and its sources (the
    bibliography's citations, which describe each source as a whole)."""
    wb = openpyxl.load_workbook(path, read_only=True)
    rows = ["\t".join(str(v) for v in row if v is not None)
            for row in wb["Method"].iter_rows(values_only=True)]
    cut = next(i for i, r in enumerate(rows) if r.startswith("Sources"))
    return "\n".join(rows[:cut]), "\n".join(rows[cut:])


def test_each_type_states_its_own_method(records):
    """The Method sheet of a type other than the shaft governor mentions no valve gear, no
    half length and no equation of the shaft governor's paper; it cites the paper only for an
    analysis the type uses (:data:`SHARED_HAMABE`), and then only where the result has that
    analysis's check. Each type's Method cites its own source, and its Sources list names it
    with the full citation, and the standards its spring's checks cite."""
    for name, (res, path, _, _) in records.items():
        text, sources = _method_text(path)
        kind = res.spec.governor_type
        key, place = OWN[kind]
        assert place in text, (name, place)
        assert REFERENCES[key].citation in sources, (name, key)
        for check in res.checks:
            for ref in found_in(check.source):
                assert REFERENCES[ref].citation in sources, (name, check.name, ref)
        if kind == "shaft":
            assert "valve gear" in text and "half length" in text
            continue
        for banned in ("valve gear", "valve-gear", "half length", "M_r0", "M_f", "M_z"):
            assert banned not in text, (name, banned)
        for citation in re.findall(r"Hamabe [^;()\n]*", text):
            shared = next((c for c in SHARED_HAMABE if citation.startswith(c)), None)
            assert shared is not None, (name, citation)
            assert any(c.name.startswith(SHARED_HAMABE[shared]) for c in res.checks), \
                (name, citation)


def test_friction_shown_where_it_acts(records):
    """A type with friction shows the speeds it opens and closes at on the Design and
    Characteristic sheets (and a Porter's on its Summary), the speeds the band checks hold."""
    with_friction = [n for n, (res, *_) in records.items() if res.friction_speeds[0] is not None]
    assert {"porter-design", "hartnell-design", "textbook-ex5-hartnell"} <= set(with_friction)
    for name in with_friction:
        res, path, pages, _ = records[name]
        wb = openpyxl.load_workbook(path)
        rise, fall = res.friction_speeds
        design = {r[0]: r for r in wb["Design"].iter_rows(values_only=True) if r[0]}
        closing = design["lowest closing speed"]
        opening = design["highest opening speed"]
        assert closing[4] == pytest.approx(fall.min() * 30 / 3.141592653589793, rel=1e-12)
        assert opening[4] == pytest.approx(rise.max() * 30 / 3.141592653589793, rel=1e-12)
        head = [c.value for c in wb["Characteristic"][1]]
        assert "closing speed (falling against friction) (rpm)" in head, name
        assert re.search(r"lowest closing\s+speed", pages[0]), name
        for check, speed in (("lowest speed >= speed.inner", fall.min()),
                             ("highest speed <= speed.outer", rise.max())):
            band = [c for c in res.checks if c.name == check]
            if band:  # the check holds the band's end over the whole range: the speed shown
                assert band[0].value == pytest.approx(speed, rel=1e-12), (name, check)


def test_spring_page_only_with_a_spring(records):
    """A governor without a spring has no Spring sheet; one with a helical spring relates the
    model's free length, the maker's and the coils in words (the shaft's half length to the
    attachments' distance and the spring closed in its loops)."""
    for name, (res, path, _, _) in records.items():
        names = openpyxl.load_workbook(path, read_only=True).sheetnames
        assert ("Spring" in names) == (res.spec.governor.spring is not None), name
    res, path, _, _ = records["hamabe-design"]
    words = openpyxl.load_workbook(path)["Spring"]["A2"].value
    sd = res.spring
    assert f"l0 = {sd.l0 * 1e3:.2f} mm" in words and f"{2 * sd.l0 * 1e3:.2f} mm" in words
    assert "body coils n_b" in words and "half length" in words


def test_spring_workbook(tmp_path):
    """`govopt spring --xlsx`: a Summary with the command, govopt's version and the date, the
    objective and its certified bound to twelve digits and their gap; the force-length table
    without a repeated point; LibreOffice converts it, its first page holding the answer."""
    from clirun import invoke

    out = tmp_path / "s.xlsx"
    run = invoke(["spring", str(SPECS / "springs" / "spring-500n.toml"), "--xlsx", str(out)])
    assert run.exit_code == 0, run.output
    wb = openpyxl.load_workbook(out)
    assert wb.sheetnames[0] == "Summary"
    rows = {r[0].value: r for r in wb["Summary"].iter_rows() if r[0].value}
    assert "spring-500n.toml" in rows["command"][1].value
    assert rows["govopt version"][1].value == govopt.__version__
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT.*", rows["written (UTC)"][1].value)
    objective = next(v for k, v in rows.items() if str(k).startswith("objective"))
    bound = rows["certified lower bound"]
    assert objective[1].number_format == bound[1].number_format == "0.00000000000E+00"
    assert objective[1].value != bound[1].value  # the gap, 8e-10, shows in twelve digits
    assert rows["gap to the certified bound"][1].value == pytest.approx(
        (objective[1].value - bound[1].value) / bound[1].value, rel=1e-3)
    points = [(r[1].value, r[2].value) for r in wb["Force-length"].iter_rows(min_row=3)
              if isinstance(r[1].value, float)]
    assert len(points) == len(set(points)) >= 3
    pdf = _recalculate([out], tmp_path, tmp_path / "profile", pdf=True)[out]
    pages, _ = _read_pdf(pdf)
    assert "wire diameter d" in pages[0] and "page 1 of" in pages[0]
