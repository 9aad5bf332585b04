"""``import cvxpy`` without the ``scipy`` and ``numpy`` modules it loads at start-up and govopt
never uses.

cvxpy (1.4-1.9) imports, when it is imported (CPU on the reference machine):

* ``scipy.stats`` for ``entropy``, used only by its quantum relative entropy atom: about 0.3 s;
* ``scipy.optimize``, only to ask whether its SCIPY solver is installed (``installed_solvers()``
  runs every solver's ``import_solver()``; SCIPY's is ``from scipy import optimize``): about
  0.12 s. govopt's GP is solved by Clarabel (:func:`govopt.optimize.spring_gp._default_solver`).

While cvxpy is imported, each of them that is not loaded yet stands in as a placeholder module:
``scipy.stats``'s holds an ``entropy`` that imports the real module when first called;
``scipy.optimize``'s is there only if scipy has that module (``importlib.util.find_spec``), so
the probe's answer, and ``cvxpy.installed_solvers()``, are the true ones. Afterwards the
placeholders are gone from ``sys.modules`` and ``import scipy.optimize`` works as usual (and a
name asked of a kept placeholder comes from the real module). A cvxpy that asks a placeholder
for anything while it loads is imported the ordinary way instead. :func:`installed_solvers`
asks cvxpy again the same way (its ``installed_solvers()`` probes every solver on each call).
Nothing else changes: the same cvxpy, the same solvers.

More that cvxpy loads and govopt's GP never uses, left out the same way (together a third
of ``govopt spring``'s CPU):

* ``scipy.special`` (about 0.04 s): cvxpy's atoms ``entr``, ``kl_div``, ``rel_entr``,
  ``log_sum_exp`` and ``von_neumann_entr`` import five of its functions to evaluate those atoms
  numerically. While cvxpy loads it is a placeholder whose five names import the real module
  when first called (a cvxpy asking it for another name is imported the ordinary way).
* ``scipy.linalg`` and ``scipy.sparse.linalg`` (about 0.085 s): cvxpy's ``utilities.linalg``
  and its matrix atoms bind them as modules for their PSD and eigenvalue functions, and the
  CVXOPT interface imports ``eigsh``; a GP never calls them. While cvxpy loads they are
  placeholders (``eigsh`` imports the real function when called); the module objects cvxpy
  keeps give the real modules' names afterwards.
* numpy's submodules ``testing`` (and with it ``unittest``), ``f2py``, ``ma``, ``ctypeslib``,
  ``polynomial``, ``char``, ``rec`` and ``strings`` (about 0.09 s): scipy 1.17's array-API
  layer, loaded with ``scipy.sparse``, copies every public name of numpy into its namespace
  (``scipy._lib.array_api_compat.numpy``), which imports each of numpy's lazily loaded
  submodules. While cvxpy loads, numpy's ``__all__`` and ``dir()`` leave out those of them not
  loaded yet; afterwards both are numpy's again, and the copy's namespace gives each of them
  from numpy on first use (a module ``__getattr__``), so nothing is missing, only later.
"""

from __future__ import annotations

import contextlib
import importlib
import importlib.util
import sys
import types


def _entropy(*args, **kwargs):
    from scipy import stats  # the real module, on first use

    return stats.entropy(*args, **kwargs)


def _stand_in(name: str, **attrs) -> types.ModuleType:
    """A placeholder for module ``name``: ``attrs``, nothing else while it is in ``sys.modules``
    (so that a ``from name import other`` fails and :func:`load` starts again), and the real
    module's names once it has left."""
    module = types.ModuleType(name, "govopt's placeholder while cvxpy loads")
    module.__dict__.update(attrs)

    def __getattr__(attr: str):
        if attr.startswith("__") or sys.modules.get(name) is module:
            raise AttributeError(f"module {name!r} has no attribute {attr!r}")
        return getattr(importlib.import_module(name), attr)

    module.__getattr__ = __getattr__
    return module


#: the names of ``scipy.special`` cvxpy imports as it loads (module docstring)
SPECIAL_NAMES = ("entr", "kl_div", "logsumexp", "rel_entr", "xlogy")
#: numpy's lazily loaded submodules that scipy's array-API copy of numpy would import
NUMPY_DEFERRED = ("testing", "f2py", "ma", "ctypeslib", "polynomial", "char", "rec", "strings",
                  "test")
#: scipy's copy of numpy's namespace (module docstring)
_NUMPY_COPY = "scipy._lib.array_api_compat.numpy"


def _deferred(module: str, name: str):
    """A stand-in for the function ``module.name`` that imports the module when called."""
    def call(*args, **kwargs):
        return getattr(importlib.import_module(module), name)(*args, **kwargs)

    call.__name__ = call.__qualname__ = name
    call.__doc__ = f"{module}.{name}, imported on first call (govopt.optimize._cvxpy)"
    return call


@contextlib.contextmanager
def _numpy_trimmed():
    """numpy's ``__all__`` and ``dir()`` without :data:`NUMPY_DEFERRED` submodules not loaded
    yet, while the block runs (if scipy's copy of numpy is not made yet); afterwards numpy's
    own again, and the copy made meanwhile gives those names from numpy on first use."""
    import numpy

    hidden = {n for n in NUMPY_DEFERRED if f"numpy.{n}" not in sys.modules}
    own_dir, own_all = numpy.__dict__.get("__dir__"), numpy.__dict__.get("__all__")
    if _NUMPY_COPY in sys.modules or not hidden or own_dir is None or own_all is None:
        yield
        return
    numpy.__all__ = [n for n in own_all if n not in hidden]
    numpy.__dir__ = lambda: [n for n in own_dir() if n not in hidden]
    try:
        yield
    finally:
        numpy.__all__, numpy.__dir__ = own_all, own_dir
        copy = sys.modules.get(_NUMPY_COPY)
        if copy is not None and "__getattr__" not in copy.__dict__:
            def __getattr__(attr: str):
                if attr in hidden:
                    return getattr(numpy, attr)
                raise AttributeError(f"module {_NUMPY_COPY!r} has no attribute {attr!r}")

            copy.__getattr__ = __getattr__


@contextlib.contextmanager
def _placeholders(stats: bool = True):
    """``scipy.optimize`` and (``stats``: at cvxpy's import) ``scipy.stats``, ``scipy.special``,
    ``scipy.linalg`` and ``scipy.sparse.linalg`` as placeholders, those not loaded yet, while
    the block runs; yields the list of them."""
    stand_ins = [_stand_in("scipy.stats", entropy=_entropy),
                 _stand_in("scipy.special", **{n: _deferred("scipy.special", n)
                                               for n in SPECIAL_NAMES}),
                 _stand_in("scipy.linalg"),
                 _stand_in("scipy.sparse.linalg", eigsh=_deferred("scipy.sparse.linalg",
                                                                  "eigsh"))] if stats else []
    if importlib.util.find_spec("scipy.optimize") is not None:  # the SCIPY probe's true answer
        stand_ins.append(_stand_in("scipy.optimize"))
    stand_ins = [m for m in stand_ins if m.__name__ not in sys.modules]
    sys.modules.update((m.__name__, m) for m in stand_ins)
    try:
        yield stand_ins
    finally:
        _remove(stand_ins)


def _remove(stand_ins: list[types.ModuleType]) -> None:
    """Take the placeholders out of ``sys.modules`` and off the ``scipy`` package."""
    for m in stand_ins:
        parent, _, child = m.__name__.rpartition(".")
        if sys.modules.get(m.__name__) is m:
            del sys.modules[m.__name__]
        if getattr(sys.modules.get(parent), "__dict__", {}).get(child) is m:
            delattr(sys.modules[parent], child)


def load():
    """The ``cvxpy`` module, imported without ``scipy.stats``, ``scipy.optimize``,
    ``scipy.special``, ``scipy.linalg``, ``scipy.sparse.linalg`` and numpy's
    :data:`NUMPY_DEFERRED` submodules if they are not loaded yet (module docstring)."""
    if "cvxpy" in sys.modules:
        import cvxpy

        return cvxpy
    with _numpy_trimmed(), _placeholders() as stand_ins:
        try:
            import cvxpy
        except (ImportError, AttributeError):  # a cvxpy using more of them: again without them
            for name in [m for m in sys.modules if m == "cvxpy" or m.startswith("cvxpy.")]:
                del sys.modules[name]
            _remove(stand_ins)
            import cvxpy
    return cvxpy


def installed_solvers() -> list[str]:
    """``cvxpy.installed_solvers()``, whose SCIPY probe meets the placeholder (see above)."""
    with _placeholders(stats=False):
        return cvxpy.installed_solvers()


cvxpy = load()
