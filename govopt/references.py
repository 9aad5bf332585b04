"""The bibliography: every source govopt's methods and checks cite, declared once by key.

A governor type's method (:class:`govopt.governors.base.Method`) cites these keys with the place
in the source (``cite("hamabe", "eq. 12")`` reads "Hamabe eq. 12"); the workbook's Method sheet,
the JSON's ``method.sources`` and the reference pages list the full citations from here. A check
names its source in free text (``"EN 13906-1:2013, 9.2"``): :func:`found_in` finds the keys a
text cites by each reference's ``marks``, so that the sources of a design's own checks are
listed beside its method's.

The seeds the project was built from are OCR scans without a title page: where a scan does not
name its title or author, the citation says what the scan holds and names the scan.

>>> cite("hamabe", "eq. 12"), cite("textbook-ch3", "3.4(b) eq. (i)")
('Hamabe eq. 12', 'textbook 3.4(b) eq. (i)')
>>> found_in("EN 13906-1:2013 (static stress); Shigley eq. (10-5)")
['en13906-1', 'shigley']
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["REFERENCES", "Reference", "cite", "found_in", "reference"]


@dataclass(frozen=True)
class Reference:
    """One source: its ``key``, how a citation in running text names it (``short``), the full
    ``citation``, what govopt takes from it (``use``) and the words that mark it in a check's
    free-text source (``marks``, matched as written). ``governor``: the source of a governor
    type's own model (:attr:`govopt.governors.base.Governor.source`); another type citing it
    borrows."""

    key: str
    short: str
    citation: str
    use: str = ""
    marks: tuple[str, ...] = ()
    governor: bool = False


REFERENCES: dict[str, Reference] = {r.key: r for r in (
    Reference(
        "hamabe", "Hamabe",
        "Genjiro Hamabe, Disturbing Actions of a Shaft Governor. Part I: statics and the design "
        "of the spring (eqs. 1-12, Example 1); Part II: the pendulum's forced vibration by the "
        "valve gear (eqs. 13-23); Part III: load changes of governor and engine (eqs. 24-32) "
        "and friction at the fulcrum (eqs. 42-46). OCR scan: seeds/000_b7bd06436315e116.txt",
        "the shaft governor: its statics, valve gear, vibration, load change and friction",
        ("Hamabe",), governor=True),
    Reference(
        "textbook-ch3", "textbook",
        "Textbook chapter 3, Governors: 3.1 function, 3.2 types, 3.3 centrifugal governors "
        "(controlling force), 3.4 gravity-loaded governors (Watt, Porter, Proell, friction at "
        "the sleeve), 3.5 spring-loaded governors (Hartnell, balls connected by springs, spring "
        "and gravity), Examples 1-8. OCR scan without a title page: "
        "seeds/001_dc27644daefca84c.txt",
        "the statics of the Watt, Porter, Proell and bell-crank governors, sleeve friction",
        ("textbook",), governor=True),
    Reference(
        "traction-article", "article",
        "Spring balance governors of traction engines: the coil-spring governor (Fig. 1, "
        "eqs. 1-4) and the flat-spring governor (Fig. 2, eqs. 5-9), magazine article by an "
        "engineer of Bremerton, Washington. OCR scan without a title line: "
        "seeds/003_f797dd2d64bc6e21.txt",
        "the traction-engine governors: toggle and leaf statics, the replacement spring",
        ("article",), governor=True),
    Reference(
        "wahl", "Wahl 1944",
        "A. M. Wahl, Mechanical Springs, Penton, Cleveland, 1944 (2nd ed. McGraw-Hill, 1963)",
        "the helical spring's rate, index, stress factor and surge frequency", ("Wahl",)),
    Reference(
        "en13906-1", "EN 13906-1",
        "EN 13906-1:2013, Cylindrical helical springs made from round wire and bar - "
        "Calculation and design - Part 1: Compression springs",
        "compression springs: stresses, solid and least working lengths, buckling, fatigue "
        "(Goodman diagrams), natural frequency", ("EN 13906-1", "EN 13906 ", "EN13906")),
    Reference(
        "en13906-2", "EN 13906-2",
        "EN 13906-2:2013, Cylindrical helical springs made from round wire and bar - "
        "Calculation and design - Part 2: Extension springs",
        "extension springs: static stress, initial tension", ("EN 13906-2", "DIN 2089")),
    Reference(
        "en15800", "EN 15800",
        "EN 15800:2008, Cylindrical helical springs made from round wire - Tolerances for "
        "cold coiled compression springs",
        "tolerances of the coil diameter, free length and forces (grades 1-3)",
        ("EN 15800", "DIN 2095")),
    Reference(
        "en10270-1", "EN 10270-1",
        "EN 10270-1:2011, Steel wire for mechanical springs - Part 1: Patented cold drawn "
        "unalloyed spring steel wire",
        "the wire grades' tensile strength and diameter tolerances", ("EN 10270-1", "EN10270-1")),
    Reference(
        "en10270-2", "EN 10270-2",
        "EN 10270-2:2011, Steel wire for mechanical springs - Part 2: Oil hardened and "
        "tempered spring steel wire",
        "the valve-spring grades' tensile strength and diameter tolerances",
        ("EN 10270-2", "EN10270-2")),
    Reference(
        "astm-a228", "ASTM A228",
        "ASTM A228/A228M, Standard Specification for Steel Wire, Music Spring Quality",
        "music wire's tensile strength", ("ASTM A228",)),
    Reference(
        "shigley", "Shigley",
        "R. G. Budynas, J. K. Nisbett, Shigley's Mechanical Engineering Design, 9th ed., "
        "McGraw-Hill, 2011, ch. 10 (mechanical springs)",
        "spring fatigue (Zimmerli's data, Goodman and Gerber lines), extension springs' hooks "
        "and initial tension, Bergstraesser's factor", ("Shigley",)),
    Reference(
        "roark", "Roark",
        "W. C. Young, R. G. Budynas, Roark's Formulas for Stress and Strain, 7th ed., "
        "McGraw-Hill, 2002, Table 8.1",
        "the leaf spring's stiffness and bending stress (centre-loaded beams)", ("Roark",)),
    Reference(
        "bisshopp-drucker", "Bisshopp & Drucker 1945",
        "K. E. Bisshopp, D. C. Drucker, Large deflection of cantilever beams, Quarterly of "
        "Applied Mathematics 3 (1945) 272-275",
        "the leaf spring's large deflection (the elastica)", ("Bisshopp", "elastica")),
    Reference(
        "rattan", "Rattan",
        "S. S. Rattan, Theory of Machines, Tata McGraw-Hill: the chapter on governors "
        "(sensitiveness, stability, isochronism, effort and power)",
        "the classic measures of a governor", ("Rattan",)),
    Reference(
        "vyshnegradsky", "Vyshnegradsky 1877",
        "I. A. Vyshnegradsky, Ueber direkt wirkende Regulatoren, Der Civilingenieur 23 (1877) "
        "95-132",
        "the third-order model of a governed engine and its diagram", ("Vyshnegradsky",)),
    Reference(
        "hurwitz", "Hurwitz 1895",
        "A. Hurwitz, Ueber die Bedingungen, unter welchen eine Gleichung nur Wurzeln mit "
        "negativen reellen Theilen besitzt, Mathematische Annalen 46 (1895) 273-284",
        "the stability of the load-change cubic", ("Hurwitz",)),
    Reference(
        "lagrange", "Lagrange",
        "J.-L. Lagrange, Mecanique analytique, Paris, 1788: the principle of virtual work and "
        "the equations of motion in generalised coordinates",
        "every governor's statics and restoring stiffness on one coordinate (the seam)",
        ("virtual work", "Lagrange")),
)}


def reference(key: str) -> Reference:
    """The reference ``key`` (:data:`REFERENCES`); a key nobody declared is a KeyError."""
    return REFERENCES[key]


def cite(key: str, where: str = "") -> str:
    """How running text cites ``key`` at ``where`` (an equation, a section, a clause)."""
    return f"{REFERENCES[key].short} {where}".strip()


def found_in(text: str) -> list[str]:
    """The keys whose marks occur in ``text`` (a check's free-text source), in the order of
    :data:`REFERENCES`."""
    return [r.key for r in REFERENCES.values() if any(m in text for m in r.marks)]
