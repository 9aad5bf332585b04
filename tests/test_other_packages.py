"""govopt uses other packages through their public API only: no module of govopt makes a module
object (a placeholder), assigns into ``sys.modules`` or into another package's namespace (an
attribute of its module or of its class, ``setattr`` included), or subclasses another package's
class that the package does not document for subclassing (:data:`DOCUMENTED_BASES`). Read from
the source with :mod:`ast`, imports inside functions included."""

import ast
from pathlib import Path

import pytest

import govopt

PACKAGE = Path(govopt.__file__).resolve().parent

#: Other packages' classes that govopt subclasses, each with where its package documents that
#: it is there to be subclassed. A builtin (``Exception``, ``dict``) is no other package's.
DOCUMENTED_BASES = {
    "abc.ABC": "docs.python.org/3/library/abc.html: 'A helper class that has ABCMeta as its "
               "metaclass ... an abstract base class can be created by simply deriving from ABC'",
    "collections.abc.Sequence": "docs.python.org/3/library/collections.abc.html: the ABCs "
                                "'can be used ... as mixins', with Sequence's mixin methods",
    "typing.NamedTuple": "docs.python.org/3/library/typing.html#typing.NamedTuple: 'Typed "
                         "version of collections.namedtuple()', written as a subclass",
}


def foreign_names(tree: ast.AST) -> dict[str, str]:
    """Local name -> the dotted name it stands for, for every name a module binds by importing
    another package (``import numpy as np``: np -> numpy; ``from typer.core import
    TyperGroup``: TyperGroup -> typer.core.TyperGroup)."""
    names = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if not alias.name.startswith("govopt"):
                    if alias.asname:
                        names[alias.asname] = alias.name
                    else:
                        root = alias.name.split(".")[0]
                        names[root] = root
        elif isinstance(node, ast.ImportFrom) and not node.level and not (
                node.module or "").startswith("govopt"):
            for alias in node.names:
                names[alias.asname or alias.name] = f"{node.module}.{alias.name}"
    return names


def dotted(node: ast.AST, names: dict[str, str]) -> str | None:
    """The dotted name of ``a.b.c`` when ``a`` is another package's (else None); a module
    taken from ``sys.modules`` is ``sys.modules[]``."""
    if isinstance(node, ast.Subscript) and dotted(node.value, names) == "sys.modules":
        return "sys.modules[]"
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name) and node.id in names:
        return ".".join([names[node.id], *reversed(parts)])
    return None


def trespasses(source: str) -> list[str]:
    """What a module's ``source`` does to other packages that it may not (one line each)."""
    tree = ast.parse(source)
    names = foreign_names(tree)
    found = []

    def where(node, what):
        found.append(f"line {node.lineno}: {what}: {ast.unparse(node).splitlines()[0][:80]}")

    for node in ast.walk(tree):
        targets = (node.targets if isinstance(node, ast.Assign | ast.Delete) else
                   [node.target] if isinstance(node, ast.AugAssign | ast.AnnAssign) else [])
        for target in targets:
            if isinstance(target, ast.Attribute) and dotted(target.value, names):
                where(node, "assigns into another package's namespace")
            elif isinstance(target, ast.Subscript) and dotted(target.value,
                                                              names) == "sys.modules":
                where(node, "assigns into sys.modules")
        if isinstance(node, ast.Call):
            func = dotted(node.func, names) or getattr(node.func, "id", None)
            receiver = (dotted(node.func.value, names)
                        if isinstance(node.func, ast.Attribute) else None)
            if func in ("setattr", "delattr") and node.args and dotted(node.args[0], names):
                where(node, "sets another package's attribute")
            elif receiver == "sys.modules" and node.func.attr not in ("get", "keys", "items",
                                                                       "values", "copy"):
                where(node, "changes sys.modules")
            elif func == "types.ModuleType":
                where(node, "makes a module object")
        if isinstance(node, ast.ClassDef):
            for base in node.bases:
                name = dotted(base, names)
                if name and name not in DOCUMENTED_BASES:
                    where(node, f"subclasses {name}, not documented for subclassing")
    return found


def test_govopt_uses_other_packages_through_their_public_api_only():
    found = [f"{path.relative_to(PACKAGE.parent)}: {line}"
             for path in sorted(PACKAGE.rglob("*.py"))
             for line in trespasses(path.read_text(encoding="utf-8"))]
    assert found == []


@pytest.mark.parametrize("source", [
    "import sys\nsys.modules['dask'] = None",
    "import sys\ndel sys.modules['scipy.stats']",
    "import sys\nsys.modules.update(x=1)",
    "import numpy\nnumpy.__all__ = []",
    "import numpy as np\ndef f():\n    np.__dir__ = list",
    "import scipy._lib\nsetattr(scipy._lib, 'array_api_compat', None)",
    "import sys\ndelattr(sys.modules['scipy'], 'stats')",
    "import types\nm = types.ModuleType('scipy.stats')",
    "from typer.core import TyperGroup\nclass Root(TyperGroup):\n    pass",
    "import typer.core\nclass Root(typer.core.TyperCommand):\n    pass",
    "from typer.core import TyperOption\nTyperOption.process_value = print",
], ids=["sys.modules-set", "sys.modules-del", "sys.modules-update", "numpy-all",
        "in-a-function", "setattr", "delattr-module", "placeholder", "subclass",
        "subclass-dotted", "patch"])
def test_each_trespass_is_found(source):
    assert len(trespasses(source)) == 1, trespasses(source)


def test_ordinary_use_is_not_a_trespass():
    """Reading another package, its documented base classes, a builtin's subclass, data in a
    mapping it hands out (``os.environ``) and govopt's own attributes pass."""
    source = ("import os, sys\nfrom abc import ABC\nimport numpy as np\n"
              "class Governor(ABC):\n    pass\nclass Failed(Exception):\n    pass\n"
              "os.environ.setdefault('OPENBLAS_NUM_THREADS', '1')\nos.environ['X'] = '1'\n"
              "x = np.zeros(3)\nx[np.argmax(x)] = 1.0\nloaded = sys.modules.get('cvxpy')\n"
              "class State:\n    debug = False\nState.debug = True\n")
    assert trespasses(source) == []
