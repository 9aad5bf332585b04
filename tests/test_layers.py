"""Layers that hold: govopt's modules import one way, counting imports inside functions.

Every module's imports are read with :mod:`ast` (module level and inside functions; not the
annotation-only ``if TYPE_CHECKING:`` blocks, which never run), resolved to govopt modules and
checked: no import cycle, the physics (analysis, springs, governors) imports nothing of the
parser, the evaluator, the optimiser, the studies, the writers or the CLI, and each module
imports only its own layer or those below it (docs/decisions.md, layers: ground floor ->
springs -> the governor seam -> generic analyses -> governor types -> parser -> evaluator ->
optimiser -> studies -> writers -> CLI).
"""

import ast
from pathlib import Path

import pytest

import govopt

PACKAGE = Path(govopt.__file__).resolve().parent

#: The layers, lowest first: (name, module prefixes). A module is in the layer of its longest
#: matching prefix; the seam's modules are named exactly (:data:`SEAM`).
LAYERS = (
    ("ground", ("govopt.units", "govopt.limits", "govopt.errors", "govopt.inputs",
                "govopt.stats", "govopt.jsonable", "govopt.examples", "govopt.verdict",
                "govopt.keys", "govopt.references")),
    ("springs", ("govopt.springs",)),
    ("seam", ()),
    ("analysis", ("govopt.analysis", "govopt.fidelity")),
    ("governor types", ("govopt.governors",)),
    ("parser", ("govopt.reader", "govopt.spec", "govopt.spec_keys", "govopt.spring_keys")),
    ("evaluator", ("govopt.result", "govopt.requirements", "govopt.evaluator", "govopt.bulk",
                   "govopt.made", "govopt.made_words", "govopt.questions")),
    ("optimize", ("govopt.optimize",)),
    ("study", ("govopt.study",)),
    ("report", ("govopt.report",)),
    ("bench", ("govopt.bench",)),
    ("cli", ("govopt.cli", "govopt.spring_command", "govopt")),
)

#: The seam every governor type plugs into (and the registry that finds a type by name, which
#: imports the types only when asked): the analyses are written on it; a type may use them.
SEAM = ("govopt.governors", "govopt.governors.base")

PHYSICS = ("govopt.analysis", "govopt.springs", "govopt.governors")
NOT_FOR_PHYSICS = ("govopt.reader", "govopt.spec", "govopt.evaluator", "govopt.bulk",
                   "govopt.optimize", "govopt.report", "govopt.cli", "govopt.study")

#: Imports that close a cycle: none (`Check` lives on the ground floor, govopt.verdict).
KNOWN_CYCLE_EDGES: set = set()

#: Imports that go up a layer today, each with the work that removes it (no cycle runs through
#: them).
KNOWN_UPWARD = KNOWN_CYCLE_EDGES | {
    # a graded wire's table and the spring maker's sheet on the governor seam
    # (Governor.spring_checks, spring_report; the helical stress and geometry are rows of the one
    # evaluator) until the spring is a plug of its own
    ("govopt.governors.base", "govopt.analysis.spring_engineering"),
    ("govopt.governors.base", "govopt.analysis.spring_record"),
    # Result.summary(), _repr_html_() and plot() render with the writers, imported when called
    # (conveniences for a notebook; no writer imports the result's module back)
    ("govopt.result", "govopt.report.plots"),
    ("govopt.result", "govopt.report.text"),
    # a study checks its database's name and writes its exports atomically with the writers'
    # helpers
    ("govopt.study.store", "govopt.report.files"),
    ("govopt.study.export", "govopt.report.files"),
}


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _runtime_nodes(tree):
    """Every node that runs: ``if TYPE_CHECKING:`` bodies are skipped (their else kept)."""
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, ast.If) and getattr(node.test, "id", getattr(node.test, "attr",
                                                                          "")) == "TYPE_CHECKING":
            for other in node.orelse:
                yield other
                yield from _runtime_nodes(other)
            continue
        yield node
        yield from _runtime_nodes(node)


def import_graph() -> dict[str, set[str]]:
    """govopt module -> the govopt modules it imports (module level and in functions)."""
    files = {module_name(p): p for p in PACKAGE.rglob("*.py")}
    graph = {}
    for name, path in files.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        targets = set()
        for node in _runtime_nodes(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                found = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[:len(package.split(".")) - (node.level - 1)]
                    module = ".".join(base + ([node.module] if node.module else []))
                else:
                    module = node.module or ""
                # `from pkg import mod` imports the module pkg.mod (and the package, which
                # counts only where a name is taken from it)
                mods = [f"{module}.{a.name}" for a in node.names if f"{module}.{a.name}" in files]
                found = mods + ([module] if len(mods) < len(node.names) else [])
            else:
                continue
            for target in found:
                while target not in files and "." in target:
                    target = target.rpartition(".")[0]
                if target in files and target not in (name, "govopt"):
                    targets.add(target)
        graph[name] = targets
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def layer(module: str) -> int:
    if module in SEAM:
        return [name for name, _ in LAYERS].index("seam")
    best = max(((len(p), i) for i, (_, prefixes) in enumerate(LAYERS) for p in prefixes
                if module == p or module.startswith(p + ".")), default=None)
    assert best is not None, f"{module} is in no layer: add it to LAYERS"
    return best[1]


@pytest.fixture(scope="module")
def graph():
    return import_graph()


def test_the_graph_sees_imports_inside_functions(graph):
    """The reader counts an import inside a function (statics imports errors at module level;
    the evaluate command imports the evaluator only when it runs)."""
    assert "govopt.errors" in graph["govopt.analysis.statics"]
    assert "govopt.evaluator" in graph["govopt.commands.evaluate"]
    assert "govopt.inputs" in graph["govopt.analysis.statics"]


def test_no_import_cycle(graph):
    assert KNOWN_CYCLE_EDGES <= {(m, t) for m, targets in graph.items() for t in targets}
    acyclic = {m: targets - {t for (a, t) in KNOWN_CYCLE_EDGES if a == m}
               for m, targets in graph.items()}
    assert cycles(acyclic) == []


def test_cycles_are_found():
    """The cycle finder finds a planted cycle (a -> b -> c -> a) and leaves a chain alone."""
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": {"c"}}) == []


def test_physics_imports_no_parser_evaluator_or_writer(graph):
    bad = sorted((m, t) for m, targets in graph.items() if m.startswith(PHYSICS)
                 for t in targets if t.startswith(NOT_FOR_PHYSICS))
    assert bad == []


def test_every_import_stays_in_its_layer_or_below(graph):
    upward = {(m, t) for m, targets in graph.items() for t in targets if layer(t) > layer(m)}
    assert sorted(upward - KNOWN_UPWARD) == []
    # an exception that no longer exists is taken off the list
    assert sorted(KNOWN_UPWARD - upward) == []


def test_no_private_name_imported_across_modules():
    """No ``from govopt.x import _name`` in govopt, its tests or benchmarks: a module's private
    names stay its own."""
    bad = []
    roots = (PACKAGE, PACKAGE.parent / "tests", PACKAGE.parent / "benchmarks")
    for path in (p for root in roots for p in root.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "")
                                                     .startswith("govopt")):
                bad += [f"{path.name}: {a.name}" for a in node.names
                        if a.name.startswith("_") and a.name != "__version__"]
    assert bad == []


#: the longest a govopt module may be: past it, a module is doing several jobs (split it along them)
MAX_MODULE_LINES = 1000


def test_no_module_over_a_thousand_lines():
    """Every govopt module fits in :data:`MAX_MODULE_LINES` lines."""
    sizes = {str(p.relative_to(PACKAGE)): len(p.read_text(encoding="utf-8").splitlines())
             for p in PACKAGE.rglob("*.py")}
    assert len(sizes) > 100  # the package's modules were all read
    assert {name: n for name, n in sizes.items() if n > MAX_MODULE_LINES} == {}


def test_no_spring_kind_branch_outside_the_spring_plug():
    """No ``== "leaf"`` (or ``!=``, ``in (..., "leaf")``) outside the springs and the leaf's
    governor: the spec parser, the limits and the searches read the kind's declarations
    (:mod:`govopt.springs.kinds`)."""
    import re

    branch = re.compile(r"""(==|!=)\s*["']leaf["']|["']leaf["']\s*(==|!=)|in \([^)]*["']leaf["']""")
    own = (PACKAGE / "springs", PACKAGE / "governors" / "traction_leaf.py")
    bad = [f"{p.relative_to(PACKAGE)}:{i}" for p in PACKAGE.rglob("*.py")
           if not any(p == o or o in p.parents for o in own)
           for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
           if branch.search(line)]
    assert bad == []
    assert branch.search('if governor.spring == "leaf":')  # the pattern finds what it forbids


def test_spring_kinds_declare_their_spec_keys():
    """Each governor spring kind is a plug; the parser reads a leaf's and a wire's section from
    its declaration, in the order it states (errors name the first missing key)."""
    from govopt.springs.kinds import KINDS

    assert set(KINDS) == {"compression", "tension", "leaf"}
    assert [k.name for k in KINDS["leaf"].section] == ["leaf_width", "leaf_thickness"]
    assert [k.name for k in KINDS["tension"].section] == ["wire_diameter", "coil_radius",
                                                          "active_turns"]
    assert KINDS["compression"].helical and not KINDS["leaf"].helical
    assert KINDS["leaf"].section_error({"leaf_width": 0.01, "leaf_thickness": 0.02})[0] \
        == "leaf_thickness"
    assert KINDS["tension"].section_error({"wire_diameter": 0.01, "coil_radius": 0.004}) \
        is not None
    assert KINDS["tension"].section_error({"wire_diameter": 0.002, "coil_radius": 0.01}) \
        is None


def test_no_private_name_read_across_modules():
    """No ``module._name`` in govopt where ``module`` is another govopt module imported by name:
    what one module uses of another is public (the import rule above, for attributes)."""
    bad = []
    for path in PACKAGE.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        modules = {a.asname or a.name for node in ast.walk(tree)
                   if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "")
                                                            .startswith("govopt"))
                   for a in node.names}
        modules |= {(a.asname or a.name).split(".")[0] for node in ast.walk(tree)
                    if isinstance(node, ast.Import) for a in node.names
                    if a.name.startswith("govopt")}
        bad += [f"{path.relative_to(PACKAGE)}:{node.lineno} {node.value.id}.{node.attr}"
                for node in ast.walk(tree)
                if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                and node.value.id in modules and node.attr.startswith("_")
                and not node.attr.startswith("__")]
    assert bad == []
