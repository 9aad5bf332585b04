"""The design search's entry point (``govopt.design``, ``govopt design``): the nominal optimum
of :mod:`govopt.optimize.design`, or, where the requirements ask for a tolerance box (a spring
grade, mass or dash-pot spreads, an adjusting nut), the robust search of
:mod:`govopt.optimize.robust`, which itself starts from the nominal optimum.

Imports run one way: this module -> robust -> design (robust, with the bulk evaluator and
pandas, only for a robust spec).
"""

from __future__ import annotations

from . import design as dz


def design(spec):
    """The best design for the spec's requirements (a :class:`govopt.result.Result`).

    Raises :class:`~govopt.errors.InfeasibleError` with a diagnosis when no design exists, and
    :class:`~govopt.errors.DesignError` naming the failed checks when the chosen design fails
    its final re-evaluation (never returns a design that fails a check).
    """
    from ..made import as_made

    spec = as_made(dz.validated(spec))  # a spring governor: designed as made and set
    req = spec.requirements
    if req.robust:
        from .robust import robust_design  # the bulk evaluator and pandas: only when asked

        return robust_design(spec)
    if req.adjusting_nut > 0 or req.dashpot_valve > 0:
        from .robust import fitter_supported

        fitter_supported(spec, req)
    return dz.design(spec)
