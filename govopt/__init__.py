"""govopt: design optimisation of governor springs (Hamabe's shaft governor and relatives).

The names below are imported when first used (module ``__getattr__``, PEP 562): ``import
govopt`` and ``govopt --help`` load neither scipy, pint nor cvxpy.
"""

from __future__ import annotations

import importlib

__version__ = "0.1.0"

#: public name -> module that defines it
_EXPORTS = {
    "Check": ".result", "Result": ".result",
    "DesignError": ".errors", "GovoptError": ".errors", "InfeasibleError": ".errors",
    "Spec": ".spec", "SpecError": ".spec", "load_spec": ".spec", "parse_spec": ".spec",
    "design": ".optimize.search", "evaluate": ".evaluator", "transient": ".analysis.transient",
    "evaluate_many": ".bulk", "Study": ".study", "load_study": ".study", "run_study": ".study",
}

__all__ = [*_EXPORTS, "__version__"]


def __getattr__(name: str):
    if name in _EXPORTS:
        value = getattr(importlib.import_module(_EXPORTS[name], __name__), name)
        globals()[name] = value  # later look-ups skip this function
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
