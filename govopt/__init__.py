"""govopt: design optimisation of governor springs (Hamabe's shaft governor and relatives)."""

from .analysis.transient import transient
from .errors import DesignError, GovoptError, InfeasibleError
from .evaluation import evaluate
from .optimize.design import design
from .result import Check, Result
from .spec import Spec, SpecError, load_spec, parse_spec

__version__ = "0.1.0"

__all__ = ["Check", "DesignError", "GovoptError", "InfeasibleError", "Result", "Spec",
           "SpecError", "design", "evaluate", "transient", "load_spec", "parse_spec", "__version__"]
