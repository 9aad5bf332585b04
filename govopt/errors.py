"""Errors a user can cause; the CLI prints them on one line and exits with code 2."""


class GovoptError(ValueError):
    """Base class of every user-facing error (bad spec, infeasible requirements, bad design)."""


class DesignError(GovoptError):
    """A design that cannot be evaluated (e.g. no equilibrium speed in part of the range), or
    a search's chosen design that fails its final evaluation."""

    def to_dict(self) -> dict:
        """The error as JSON (``--json``): its status and the one line."""
        return {"status": "error", "error": str(self)}


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
    """Requirements that no design can meet, the reason as data: ``file`` (the spec), ``key``
    (the key at fault, where one is), ``reason`` (which requirements or bounds conflict),
    ``moves`` (each change of the spec that alone makes a design exist, in the spec's words;
    None where none was sought) and ``otherwise`` (what is said where none does); the one line
    is composed from them.

    >>> e = InfeasibleError("infeasible: a conflicts with b", file="s.toml", moves=["k2 -> 0.05"])
    >>> str(e)
    's.toml: infeasible: a conflicts with b; it becomes feasible if one of these moves: k2 -> 0.05'
    >>> e.moves
    ['k2 -> 0.05']
    >>> InfeasibleError("missing", file="s.toml", key="speed").key
    'speed'
    """

    #: what is said where no single move makes a design exist
    NO_MOVE = "no single requirement within a factor of 100 makes it feasible"

    def __init__(self, reason: str, *, file=None, key: str | None = None,
                 moves: list[str] | None = None, otherwise: str = NO_MOVE):
        self.reason, self.key, self.otherwise = reason, key, otherwise
        self.file = None if file is None else str(file)
        self.moves = None if moves is None else list(moves)
        super().__init__(self._line())

    def _line(self) -> str:
        line = ": ".join([*(p for p in (self.file, self.key) if p), self.reason])
        if self.moves is None:
            return line
        return line + ("; it becomes feasible if one of these moves: " + "; ".join(self.moves)
                       if self.moves else f"; {self.otherwise}")

    def __str__(self) -> str:
        return self._line()

    def to_dict(self) -> dict:
        """The diagnosis as JSON (``govopt design --json`` on an infeasible spec): status,
        spec, key, reason, moves, what is said where none, and the one line."""
        return {"status": "infeasible", "spec": self.file, "key": self.key,
                "reason": self.reason, "moves": self.moves, "otherwise": self.otherwise,
                "error": str(self)}
