"""Imports on demand: a command loads what it uses when it uses it.

Each command runs in an interpreter of its own that starts as a fresh one (forked from one
that did only what a fresh interpreter running the command does before it) and reports its
``sys.modules``:
``govopt --help`` loads neither scipy, pint nor cvxpy; ``govopt evaluate`` no cvxpy (the GP
earns its place in ``design`` and ``spring``, for the certificate, duals and diagnosis) and of
scipy's numerics only what its governor's analyses use, where they use it (the shaft governor's
valve table is scipy's PCHIP, its swing's extremes scipy's ``brentq``; a Hartnell needs neither;
pint imports the bare ``scipy`` package, a few milliseconds), nor the writers' libraries it is
not asked for; ``govopt design`` imports cvxpy only for a design that needs its GP.
"""

import functools
import subprocess
import sys

import pytest

HEAVY = ("cvxpy", "scipy", "scipy.optimize", "pint", "numpy")


#: typer vendors its click, so the separate click package is never loaded; typer converts
#: options through pydantic, which the root's help does without (typer answers ``--help``
#: before it reads the other options) and a command's help and run do not (the root's
#: ``--install-completion`` is read first, through pydantic)
FRAMEWORKS = ("click", "pydantic")


#: Each command's interpreter: forked from one that ran what a fresh ``python -c`` running the
#: command runs before it (``import json, sys``, ``from govopt.cli import main``; nothing more
#: preloaded), so it starts in that state without paying Python's start-up and govopt.cli's
#: imports again (tests/forkcli.py); it runs ``main()`` and reports its ``sys.modules``.
_server: list = []  # started on first use


@pytest.fixture(scope="module", autouse=True)
def _stop_the_forking_interpreter():
    yield
    while _server:
        _server.pop().close()


@functools.cache
def modules_after(*args: str, cwd=None) -> frozenset[str]:
    """The modules loaded by ``govopt ARGS`` run through the console entry point, in an
    interpreter of its own that starts as a fresh one; each command once per test process (the
    same command, the same modules)."""
    from forkcli import Server

    if not _server:
        _server.append(Server(()))
    proc = _server[0].start(*args, cwd=cwd, modules=True)
    _, err = proc.communicate(timeout=120)
    assert "Traceback" not in err, err
    return proc.modules()


def test_help_loads_no_numerics():
    """The root's help lists the commands without importing one (govopt/cli.py: COMMANDS);
    typer draws it with rich."""
    loaded = modules_after("--help")
    assert "govopt.cli" in loaded and "typer" in loaded and "rich" in loaded
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))
    unwanted = {*FRAMEWORKS, "openpyxl", "matplotlib", "pandas"}
    assert not loaded & unwanted, sorted(loaded & unwanted)
    assert not {m for m in loaded if m.startswith("govopt.commands.")} - {
        "govopt.commands.common"}


@pytest.mark.parametrize("args", [("evaluate", "--help"), ("spring", "--help"),
                                  ("study", "run", "--help"), ("bench", "--help"),
                                  ("init", "--help")])
def test_command_help_loads_its_module_only(args):
    loaded = modules_after(*args)
    assert not loaded & {*HEAVY, "click"}, sorted(loaded & {*HEAVY, "click"})
    modules = {m for m in loaded if m.startswith("govopt.commands.")}
    assert len(modules - {"govopt.commands.common"}) == 1, sorted(modules)


def test_import_govopt_loads_no_numerics():
    p = subprocess.run([sys.executable, "-c", "import sys, govopt; print(sorted(sys.modules))"],
                       capture_output=True, text=True, check=True)
    loaded = set(eval(p.stdout))  # a printed list of module names
    assert not loaded & set(HEAVY)


def test_lazy_exports_are_the_modules_objects():
    import govopt
    from govopt.evaluator import evaluate
    from govopt.optimize.search import design

    assert govopt.evaluate is evaluate and govopt.design is design
    assert set(govopt.__all__) <= set(dir(govopt))
    with pytest.raises(AttributeError):
        govopt.no_such_name  # noqa: B018


def test_evaluate_loads_no_cvxpy():
    loaded = modules_after("evaluate", "--json")
    assert "govopt.evaluator" in loaded and "cvxpy" not in loaded


#: What `govopt evaluate` used to import and no longer may. Where dask is installed, pint
#: imports ``dask.base`` as it loads (its compat layer), never dask's arrays nor its scheduler.
NOT_ON_EVALUATE = ("scipy.interpolate", "scipy.optimize", "scipy.special", "scipy.linalg",
                   "scipy.integrate", "scipy.stats", "scipy.sparse", "cvxpy", "matplotlib",
                   "pandas", "openpyxl", "pyarrow", "dask.array", "dask.dataframe",
                   "distributed", "click")


@pytest.mark.parametrize("args", [("--json",), (), ("textbook-ex4-hartnell.toml", "--json")],
                         ids=["hamabe-json", "hamabe-text", "hartnell"])
def test_evaluate_loads_no_scipy_numerics_nor_unasked_writers(args):
    from govopt.examples import SPECS

    args = tuple(str(SPECS / a) if a.endswith(".toml") else a for a in args)
    loaded = modules_after("evaluate", *args)
    assert "govopt.evaluator" in loaded  # it ran (the classic travel needs no root finder now)
    # the shaft governor's valve table and swing: scipy's interpolants and root finder, and
    # what scipy.interpolate imports itself (linalg, sparse, special); never integrate or stats
    shaft = {"scipy.interpolate", "scipy.optimize", "scipy.linalg", "scipy.sparse",
             "scipy.special"} if "hartnell" not in str(args) else set()
    assert not loaded & (set(NOT_ON_EVALUATE) - shaft), sorted(loaded & set(NOT_ON_EVALUATE))
    if "--json" in args:  # the JSON needs no table (the text report's tables are rich's)
        assert "rich" not in loaded


def test_evaluate_xlsx_loads_openpyxl_only_then(tmp_path):
    loaded = modules_after("evaluate", "--xlsx", str(tmp_path / "a.xlsx"))
    assert "openpyxl" in loaded and "matplotlib" not in loaded and "pandas" not in loaded


def test_design_certified_by_the_energy_bound_loads_no_cvxpy(tmp_path):
    """The bundled design's continuous bound is the energy bound, attained by a spring that
    meets every row of the GP (optimize/gp_table.energy_optimum): no solve, no cvxpy."""
    loaded = modules_after("design", "--json", cwd=tmp_path)
    assert "govopt.optimize.design" in loaded
    # pandas: the made verdict's worst case over the tolerance box keeps its probed points'
    # rows as a frame (optimize/robust.worst_case); the yield's samples need none
    assert not loaded & {"cvxpy", "govopt.optimize.spring_gp", "scipy.stats", "matplotlib",
                         "openpyxl", "click"}


def test_design_that_needs_the_gp_loads_cvxpy(tmp_path):
    """With Wahl's factor (K > 1) the energy bound is not attained: the GP decides, in cvxpy,
    imported where the GP is solved."""
    from govopt.examples import SPECS

    text = (SPECS / "hamabe-design.toml").read_text()
    assert "[material]\n" in text
    spec = tmp_path / "wahl.toml"
    spec.write_text(text.replace("[material]\n", '[material]\nstress_correction = "wahl"\n', 1))
    loaded = modules_after("design", str(spec), "--json", cwd=tmp_path)
    assert "cvxpy" in loaded and "govopt.optimize.spring_gp" in loaded
    assert not loaded & {"matplotlib", "openpyxl", "click"}  # pandas: the worst case's rows


@pytest.mark.parametrize("preset, expect", [(None, "1"), ("2", "2")])
def test_cli_runs_one_blas_thread_unless_told(preset, expect):
    """OpenBLAS's idle threads spin: a third of `govopt evaluate`'s CPU
    (benchmarks/bench_startup.py measures it)."""
    import os

    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    if preset:
        env["OPENBLAS_NUM_THREADS"] = preset
    code = ("import os, sys\nfrom govopt.cli import main\nsys.argv = ['govopt', '--version']\n"
            "try:\n    main()\nexcept SystemExit:\n    pass\n"
            "print(os.environ['OPENBLAS_NUM_THREADS'])\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                       env=env)
    assert p.stdout.strip().splitlines()[-1] == expect


def _guarded(tree) -> set:
    """The import nodes inside a ``try`` that catches ImportError (an optional library, named
    in its own error or skipped)."""
    import ast

    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Try) and any(
                isinstance(h.type, ast.Name) and h.type.id in ("ImportError",
                                                               "ModuleNotFoundError")
                for h in node.handlers):
            out |= {id(n) for stmt in node.body for n in ast.walk(stmt)}
    return out


def test_every_library_govopt_imports_is_a_main_dependency():
    """A plain install (``pip install govopt``, no extra) runs every command: each third-party
    module the package imports is one of pyproject's ``dependencies``, unless imported inside a
    ``try`` that catches ImportError (an optional library: python-control beside the bench's
    other methods, dask for ``--dask``, which names ``govopt[dask]`` when absent)."""
    import ast
    import re
    import tomllib
    from importlib.metadata import packages_distributions
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    project = tomllib.loads((root / "pyproject.toml").read_text())["project"]
    main = {re.split(r"[\s<>=!~\[;]", d, maxsplit=1)[0].lower() for d in project["dependencies"]}
    dists = packages_distributions()
    missing = set()
    for path in (root / "govopt").rglob("*.py"):
        tree = ast.parse(path.read_text())
        optional = _guarded(tree)
        for node in ast.walk(tree):
            if id(node) in optional:
                continue
            names = ([a.name for a in node.names] if isinstance(node, ast.Import) else
                     [node.module] if isinstance(node, ast.ImportFrom) and node.level == 0
                     and node.module else [])
            for name in names:
                top = name.split(".")[0]
                if top in sys.stdlib_module_names or top == "govopt":
                    continue
                if not {d.lower() for d in dists.get(top, [top])} & main:
                    missing.add(f"{top} ({path.relative_to(root)})")
    assert not missing, f"imported but not a main dependency: {sorted(missing)}"
