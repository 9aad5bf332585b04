"""The workbook as printed: LibreOffice turns several types' workbooks into PDF (one
soffice call), and every page is read back with ``pdftotext``: a page that carries a table's
rows carries that table's header line, and a table that runs onto another page leaves at least
three of its rows on each side of the break; the bundled design's workbook prints in about a
dozen pages."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
from openpyxl.utils import column_index_from_string
from test_excel import SOFFICE, _recalculate  # the suite's LibreOffice helpers

import govopt
from govopt.report import excel

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"
PDFTOTEXT = shutil.which("pdftotext")

#: Types whose workbooks print long tables: the shaft's Design and Spring sheets and its three
#: Dynamics pages, a Hartnell design (an optimiser's record on the Checks sheet, a coil
#: spring's sheet), a Porter with an engine (Dynamics), a textbook Hartnell (Characteristic),
#: the bundled (shaft) design (`govopt design`, the README's Quick start).
CASES = {"hamabe-a": govopt.evaluate, "hartnell-design": govopt.design,
         "porter-engine": govopt.evaluate, "textbook-ex4-hartnell": govopt.evaluate,
         "hamabe-design": govopt.design}
#: A table that runs onto another page keeps at least this many rows on each side.
ORPHANS = 3

pytestmark = [pytest.mark.libreoffice,
              pytest.mark.skipif(SOFFICE is None or PDFTOTEXT is None,
                                 reason="LibreOffice (soffice) or pdftotext not on PATH")]


@pytest.fixture(scope="module")
def printed(tmp_path_factory):
    """name -> (the workbook as built, its sheets' printed pages: sheet -> [page text], the
    PDF's bytes)."""
    folder = tmp_path_factory.mktemp("printed")
    built = {}
    for name, run in CASES.items():
        res = run(govopt.load_spec(SPECS / f"{name}.toml"))
        excel.write_workbook(res, folder / f"{name}.xlsx")
        built[name] = excel.build_workbook(res)  # the same layout, with its tables' rows
    # one soffice call, with a fresh LibreOffice profile: no lock shared with others
    pdfs = _recalculate([folder / f"{n}.xlsx" for n in CASES], folder, folder / "profile",
                        pdf=True)
    out = {}
    for name, wb in built.items():
        pdf = pdfs[folder / f"{name}.xlsx"]
        text = subprocess.run([PDFTOTEXT, "-layout", str(pdf), "-"],
                              check=True, capture_output=True, text=True).stdout
        pages: dict[str, list[str]] = {}
        for page in text.split("\f"):
            foot = re.search(r"(\w[\w-]*), page \d+ of \d+", page)
            if foot:
                pages.setdefault(foot.group(1), []).append(page)
        out[name] = (wb, pages, pdf.read_bytes())
    return out


def _words(ws, row: int) -> list[str]:
    """The words of a row's printed text cells (a header wraps in its cell, word by word)."""
    cols = column_index_from_string(re.search(r":\$?([A-Z]+)", ws.print_area).group(1))
    return [w for c in ws[row][:cols] if isinstance(c.value, str)
            for w in re.split(r"[\s-]+", c.value) if w]  # a wrap may break at a hyphen


@pytest.mark.parametrize("name", CASES)
def test_every_page_carries_its_tables_header(printed, name):
    """Each sheet prints on the pages its breaks make (LibreOffice adds none), each page
    starting with the row after the break; a page with a table's rows shows the table's header
    (a continued table's, repeated by the sheet's print titles), and a table split by a break
    keeps at least three rows on each side."""
    wb, pages, _ = printed[name]
    assert set(pages) == set(wb.sheetnames)
    spanning = 0
    for ws in wb.worksheets:
        breaks = [b.id for b in ws.row_breaks.brk]
        assert len(pages[ws.title]) == len(breaks) + 1, ws.title
        last_row = int(re.search(r"(\d+)$", ws.print_area).group(1))
        bounds = [0, *breaks, last_row]
        for k, page in enumerate(pages[ws.title]):
            lo, hi = bounds[k] + 1, bounds[k + 1]
            first = ws.cell(lo, 1).value
            if k and isinstance(first, str) and first.strip():
                assert first.split()[0] in page, (ws.title, k + 1, first)
            for t in excel.tables(ws):
                rows = range(max(t.title, t.header) + 1, t.last + 1)
                on_page = [r for r in rows if lo <= r <= hi]
                if not on_page:
                    continue
                missing = [w for w in _words(ws, t.header) if w not in page]
                assert not missing, (ws.title, f"page {k + 1}", t, missing)
                if len(on_page) < len(rows):  # split: no orphans on either side
                    spanning += 1
                    assert len(on_page) >= ORPHANS, (ws.title, f"page {k + 1}", t, on_page)
    assert spanning, "no table of these workbooks runs onto a second page: nothing was tested"


def test_bundled_design_workbook_prints_in_thirty_pages(printed):
    """The bundled design's workbook, converted to PDF by LibreOffice, prints in at most 30
    pages, the Summary on one (51 before any print setup; 12 when each sheet was fitted to the
    page's width, its text printed at about 6 pt; now no text prints under 8 pt, so the same
    tables take more pages). The pages were looked at (docs/how-to/read-the-workbook.md)."""
    pages = len(re.findall(rb"/Type\s*/Page\b", printed["hamabe-design"][2]))
    print(f"hamabe-design.xlsx prints in {pages} pages")
    # Summary 1, Design 3, Checks 3, Characteristic 2, Spring 3, Dynamics 6, Spec 3, Method 4,
    # Model 2 when this was written
    assert len(excel.SHEETS) <= pages <= 30
