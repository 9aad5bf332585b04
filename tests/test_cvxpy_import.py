"""govopt's ``import cvxpy`` (govopt/optimize/_cvxpy.py) leaves out ``scipy.stats`` and
``scipy.optimize`` (issue 14, target 2) and changes nothing else: the same installed solvers
as a plain import, the real modules afterwards, and an ordinary import for a cvxpy that uses
them as it loads. The placeholder's ``entropy`` and a cvxpy wanting more of ``scipy.stats``:
tests/test_imports.py.
"""

import pytest
from test_imports import DEFERRED, run_python


def test_solvers_are_a_plain_imports_and_scipy_optimize_loads_later():
    """The SCIPY solver's probe meets a placeholder (at import and in govopt's
    ``installed_solvers``): the same installed solvers as a plain ``import cvxpy`` and as cvxpy's
    own probe, and the real scipy.optimize solves with SCIPY afterwards."""
    ours = run_python(
        "import sys\n"
        "from govopt.optimize._cvxpy import cvxpy as cp, installed_solvers\n"
        "ours = installed_solvers()\n"
        f"assert not {{'scipy.optimize', 'scipy.stats'}} & set(sys.modules) or not {DEFERRED}\n"
        "assert ours == cp.installed_solvers()\n"
        "print(ours)\n"
        "x = cp.Variable(2)\n"
        "p = cp.Problem(cp.Minimize(x[0] + 2 * x[1]), [x >= 1, x[0] + x[1] >= 3])\n"
        "print(round(p.solve(solver='SCIPY'), 9), sys.modules['scipy.optimize'].linprog.__name__)")
    plain = run_python("import cvxpy\nprint(cvxpy.installed_solvers())")
    solvers, solved = ours.splitlines()
    assert solvers == plain and "'CLARABEL'" in solvers
    assert solved == "4.0 linprog"  # x = (2, 1): min x0 + 2 x1 on x >= 1, x0 + x1 >= 3


def fake_cvxpy(tmp_path, body: str) -> str:
    """A folder holding a stand-in ``cvxpy`` package whose ``__init__`` is ``body``."""
    (tmp_path / "cvxpy").mkdir()
    (tmp_path / "cvxpy" / "__init__.py").write_text(body)
    return str(tmp_path)


@pytest.mark.parametrize("module, body, probe, expected", [
    ("scipy.optimize", "from scipy.optimize import linprog\n", "cvxpy.linprog.__module__",
     "scipy.optimize._linprog"),
    ("scipy.optimize", "import scipy.optimize as opt\nlinprog = opt.linprog\n",
     "cvxpy.linprog.__module__", "scipy.optimize._linprog"),
    ("scipy.special", "from scipy.special import gamma\n", "cvxpy.gamma(5.0)", "24.0"),
], ids=["optimize-from-import", "optimize-attribute", "special-more-names"])
def test_cvxpy_using_a_left_out_module_as_it_loads_is_imported_as_usual(tmp_path, module, body,
                                                                         probe, expected):
    """A (future) cvxpy using scipy.optimize (or more of scipy.special than its five functions)
    while it loads: the placeholders step aside and it gets the real module."""
    out = run_python("import sys\n"
                     "from govopt.optimize._cvxpy import cvxpy\n"
                     f"print({probe}, 'placeholder' in (sys.modules[{module!r}].__doc__ or ''))",
                     PYTHONPATH=fake_cvxpy(tmp_path, body))
    assert out == f"{expected} False"


def test_a_kept_placeholder_gives_the_real_modules_names(tmp_path):
    """A (future) cvxpy keeping ``scipy.optimize`` for later gets the real module's names."""
    out = run_python("import sys\n"
                     "from govopt.optimize._cvxpy import cvxpy\n"
                     "print('scipy.optimize' in sys.modules,\n"
                     "      cvxpy.OPT.brentq(lambda x: x - 2, 0, 3))",
                     PYTHONPATH=fake_cvxpy(tmp_path, "import scipy.optimize as OPT\n"))
    assert out == "False 2.0"


@pytest.mark.skipif(not DEFERRED, reason="older cvxpy and scipy load these modules themselves "
                    "(and scipy 1.11 has no copy of numpy's namespace): nothing is deferred")
def test_scipy_special_and_numpys_test_modules_load_only_when_used():
    """cvxpy loads without scipy.special, scipy.linalg, scipy.sparse.linalg and numpy's
    testing/f2py/ma (issue 22, CPU of `govopt spring`); numpy's ``__all__`` and ``dir()`` are its
    own afterwards, scipy's copy of numpy gives the deferred submodules on first use, and
    cvxpy's code that uses those modules gets the real functions when it calls them."""
    out = run_python(
        "import sys, numpy\n"
        "own = (list(numpy.__all__), sorted(dir(numpy)))\n"
        "from govopt.optimize._cvxpy import cvxpy as cp\n"
        "late = {'scipy.special', 'numpy.testing', 'numpy.f2py', 'numpy.ma', 'unittest',\n"
        "        'scipy.linalg', 'scipy.sparse.linalg'}\n"
        "print(sorted(late & set(sys.modules)), own == (numpy.__all__, sorted(dir(numpy))))\n"
        "import scipy._lib.array_api_compat.numpy as copy\n"
        "print(copy.testing is numpy.testing, copy.ma is numpy.ma)\n"
        "import scipy.special as sp\n"
        "x = numpy.array([0.5, 2.0])\n"
        "print(numpy.array_equal(cp.entr(x).value, sp.entr(x)),\n"
        "      numpy.array_equal(cp.kl_div(x, x[::-1]).value, sp.kl_div(x, x[::-1])),\n"
        "      cp.log_sum_exp(x).value == sp.logsumexp(x))\n"
        "import scipy.linalg, scipy.sparse, scipy.sparse.linalg\n"
        "from cvxpy.utilities import linalg as L\n"
        "from cvxpy.reductions.solvers.conic_solvers import cvxopt_conif as C\n"
        "A = scipy.sparse.csc_array(numpy.diag([1.0, 2.0, 3.0]))\n"
        "print(L.la.eigh is scipy.linalg.eigh, L.sparla.svds is scipy.sparse.linalg.svds,\n"
        "      round(float(C.eigsh(A, k=1)[0][0]), 9))")
    assert out.splitlines() == ["[] True", "True True", "True True True", "True True 3.0"]
