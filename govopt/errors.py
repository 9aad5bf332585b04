"""Errors a user can cause; the CLI prints them on one line and exits with code 2."""


class GovoptError(ValueError):
    """Base class of every user-facing error (bad spec, infeasible requirements, bad design)."""


class DesignError(GovoptError):
    """A design that cannot be evaluated (e.g. no equilibrium speed in part of the range)."""


class InfeasibleError(GovoptError):
    """Requirements that no design can meet; the message names the conflicting ones."""
