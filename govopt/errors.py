"""Errors a user can cause; the CLI prints them on one line and exits with code 2."""


class GovoptError(ValueError):
    """Base class of every user-facing error (bad spec, infeasible requirements, bad design)."""


class DesignError(GovoptError):
    """A design that cannot be evaluated (e.g. no equilibrium speed in part of the range)."""


def located(where, message: str) -> str:
    """``message`` of a lower layer with the file it concerns in front: the physics speaks of a
    design, not of a file; the layer that knows the file (the evaluator, the parser) adds it
    once, at the edge.

    >>> located("a.toml", "design: no equilibrium speed")
    'a.toml: design: no equilibrium speed'
    >>> located("a.toml", "a.toml: design: missing")
    'a.toml: design: missing'
    """
    where = str(where or "")
    return message if not where or message.startswith(f"{where}: ") else f"{where}: {message}"


class InfeasibleError(GovoptError):
    """Requirements that no design can meet; the message names the conflicting ones."""
