"""Each governor type speaks of its own physics: the `govopt init --type T` template and every
record (the workbook's cells, the text report, the JSON) of a type other than the shaft
governor mention no valve gear, no example of Hamabe's paper and no shaft governor, and cite
Hamabe only for a criterion they borrow, saying so ("borrowed from Hamabe Part II, case 2").
The bibliography's full citations describe each source as a whole and are left out."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import pytest

import govopt
from govopt.governors import REGISTRY
from govopt.references import REFERENCES
from govopt.report import excel
from govopt.report.text import format_result
from govopt.spec_docs import template

SPECS = Path(__file__).resolve().parent.parent / "specs"
_ALL = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(SPECS.glob("*.toml"))}
#: every bundled spec of a type other than the shaft governor (evaluated where it gives a
#: design, designed where it does not)
OTHERS = [n for n, d in _ALL.items() if d["governor"]["type"] != "shaft"]
#: what a non-shaft text may not say: the shaft governor's valve gear, Hamabe's examples, the
#: shaft governor itself, and Hamabe cited without saying the criterion is borrowed
BANNED = {"valve gear": re.compile(r"valve[ -]gear", re.I),
          "Hamabe's example": re.compile(r"Hamabe('s)? Ex(ample|\.)"),
          "shaft governor": re.compile(r"shaft governor", re.I),
          "Hamabe, not borrowed": re.compile(r"(?<!borrowed from )Hamabe")}
CITATIONS = {r.citation for r in REFERENCES.values()}


def _offences(lines) -> list[tuple[str, str]]:
    return [(what, line) for line in lines if line not in CITATIONS
            for what, pattern in BANNED.items() if pattern.search(line)]


@pytest.mark.parametrize("type_name", [t for t in REGISTRY if t != "shaft"])
def test_template_speaks_of_its_own_type(type_name):
    """The template of a non-shaft type: no valve gear, Hamabe example or shaft governor; a key
    whose source is Hamabe's paper (the engine, the load change, the dash-pot) says it is
    borrowed; no stress or modulus placeholder where the key has a value of its own (E of a
    leaf 206 GPa, not the allowable stress's 400 MPa)."""
    text = template(type_name)
    comments = re.sub(r"\n# ?", " ", text)  # a comment's lines joined, as one reads them
    assert not _offences([comments]), re.findall(r".{60}Hamabe.{20}", comments)
    assert "borrowed from Hamabe Part III" in text  # [engine]'s keys
    assert '# elastic_modulus = "400 MPa"' not in text
    assert 'shear_modulus = "400 MPa"' not in text


def test_shaft_template_cites_its_own_paper():
    """The shaft governor's template cites Hamabe as its own source, not borrowed; the classic
    measures' setting, from the textbook, is borrowed there."""
    text = re.sub(r"\n# ?", " ", template("shaft"))
    assert "(Hamabe Part III)" in text and "borrowed from Hamabe" not in text
    assert "(borrowed from textbook 3.2)" in text


@pytest.fixture(scope="module")
def records():
    out = {}
    for name in OTHERS:
        spec = govopt.load_spec(SPECS / f"{name}.toml")
        out[name] = govopt.evaluate(spec) if "design" in _ALL[name] else govopt.design(spec)
    return out


def _record_lines(res) -> list[str]:
    """Every text a record holds: the workbook's text cells, the text report's lines and the
    JSON's strings."""
    wb = excel.build_workbook(res)
    lines = [c.value for ws in wb.worksheets for row in ws.iter_rows() for c in row
             if isinstance(c.value, str)]
    lines += format_result(res, colour=False).splitlines()

    def strings(x):
        if isinstance(x, str):
            yield x
        elif isinstance(x, dict):
            for v in x.values():
                yield from strings(v)
        elif isinstance(x, list | tuple):
            for v in x:
                yield from strings(v)

    return lines + list(strings(json.loads(json.dumps(res.to_dict(), default=str))))


def test_records_speak_of_their_own_type(records):
    """No record of a non-shaft type mentions valve gear, Hamabe's examples or the shaft
    governor; each Hamabe citation it has is a criterion it says it borrows (the resonance
    ceiling of the ball and bell-crank governors, the friction strokes of a load change)."""
    borrowed = 0
    for name, res in records.items():
        lines = _record_lines(res)
        assert not _offences(lines), (name, _offences(lines)[:3])
        borrowed += any("borrowed from Hamabe" in line for line in lines)
    assert borrowed, "no record borrows a criterion: nothing was tested"


def test_the_resonance_ceiling_is_said_where_it_is_kept(records):
    """A Hartnell keeps the ceiling k^2 < omega0^2 as a criterion borrowed from Hamabe Part II,
    case 2, and says so where it states it; a leaf governor keeps none and says why (nothing
    forces its flying masses), not that governors without forcing have no ceiling."""
    # Since the 'band' merge a textbook governor keeps the ceiling only where its spec asks for
    # Hamabe's band (requirements.k2_margin; tests/test_band.py): hartnell-design gives none and
    # keeps no ceiling, proell-design gives one and must say where it borrows the ceiling from.
    hartnell = records["hartnell-design"]
    assert not any(c.name.startswith("k^2 < omega0^2") for c in hartnell.checks)
    proell = "\n".join(_record_lines(records["proell-design"]))
    assert "borrowed from Hamabe Part II, case 2" in proell
    leaf = records["traction-leaf-design"]
    assert leaf.method.named("resonance") is None
    assert not any(c.name.startswith("k^2 < omega0^2") for c in leaf.checks)
