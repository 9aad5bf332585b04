"""The made governors' record (:mod:`govopt.made`, ``Result.made``) in figures and words: the
yield and the worst-case speeds declared once as reported figures (:func:`figures`, read
through :meth:`govopt.result.Result.figures`), and the yield's sentence every report gives
(:func:`yield_words`). Imports nothing of govopt but :mod:`govopt.verdict`, so the result reads
it without importing the evaluator back."""

from __future__ import annotations

import math

from .verdict import Figure


def percent(p: float, unit: bool = True) -> str:
    """A probability as a percentage, one decimal (two where it is within 1 % of 0 or 1, so
    99.62 % is not shown as 100 %).

    >>> percent(0.828), percent(0.9962), percent(1.0), percent(0.7923, False)
    ('82.8 %', '99.62 %', '100 %', '79.2')
    """
    v = 100.0 * p
    digits = 2 if 0 < p < 1 and min(v, 100 - v) < 1 else 1
    text = f"{v:.{digits}f}".rstrip("0").rstrip(".") if v in (0.0, 100.0) else f"{v:.{digits}f}"
    return text + (" %" if unit else "")


def yield_words(made: dict, name=str) -> str:
    """The yield in words, as every report gives it: ``"82.8 % of made governors pass (95 %:
    79.2-86.0 %); most often failing: lowest speed >= speed.inner"`` (``name``: a check's name
    as the report shows it)."""
    y = made["yield"]
    if y["probability"] is None:
        return "yield not sampled: " + y["note"]
    if y.get("certified"):
        text = "100 % of made governors pass (certified: every requirement holds over the " \
               "whole tolerance box)"
    else:
        lo, hi = y["ci95"]
        text = (f"{percent(y['probability'])} of made governors pass (95 %: "
                f"{percent(lo, False)}-{percent(hi)})")
        if y["most_failing"]:
            text += f"; most often failing: {name(y['most_failing'])}"
    if y.get("required") is not None:
        text += (f"; required >= {percent(y['required'])}: "
                 + ("met" if y["meets_required"] else "NOT MET"))
    return text


def meets(made: dict | None) -> bool | None:
    """Whether the made governors meet the required yield (the 95 % Wilson lower bound at
    least ``min_yield``): None where no yield is required or none was sampled."""
    if not made or made["yield"].get("required") is None:
        return None
    return made["yield"].get("meets_required")


def sampled_words(made: dict) -> str:
    """How the yield was found: ``"500 samples (Latin hypercube, seed 0)"``, or the worst
    case."""
    y = made["yield"]
    return (f"{y['samples']} samples (Latin hypercube, seed {y['seed']})" if y["samples"]
            else "worst case over the tolerance box")


def figures(made: dict) -> list:
    """The made governors' reported figures (group ``"made"``), declared here once and read
    through :meth:`govopt.result.Result.figures` by every writer: the yield (the share of made
    governors meeting every requirement, with its interval and how it was sampled) and the
    worst-case speeds over the tolerance box as made, the lowest closing and the highest opening
    speed (exact: :func:`govopt.analysis.tolerance.speed_band`), beside the required band."""
    y, band = made["yield"], made["speed_band"]
    req = band.get("required_rad_s")
    p = y["probability"]
    most = y.get("most_failing")
    out = [Figure("made governors passing", "not sampled" if p is None else p, "", "made",
                  symbol="yield", json="yield_probability",
                  note=(y.get("note") or "") if p is None else "; ".join(x for x in (
                      None if y.get("certified") else
                      f"95 %: {percent(y['ci95'][0], False)}-{percent(y['ci95'][1])}",
                      sampled_words(made),
                      most and f"most often failing: {most} ({y['failing'][most]})",
                      None if y.get("required") is None else
                      f"required >= {percent(y['required'])}") if x),
                  source="interval: Wilson 1927")]
    for i, (what, side) in enumerate((("lowest closing speed", "inner"),
                                      ("highest opening speed", "outer"))):
        out.append(Figure(f"worst-case {what}", band["band_rad_s"][i], "rad/s", "made",
                          note="" if req is None else
                          f"required {'>=' if i == 0 else '<='} {req[i] * 30.0 / math.pi:.4g} "
                          f"rpm (speed.{side})",
                          source="over the tolerance box as made, exact at its corners"))
    return out


__all__ = ["figures", "percent", "sampled_words", "yield_words"]
