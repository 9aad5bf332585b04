"""The bundled example specs: the repository's ``specs/`` folder, installed as the package
``govopt.specs`` (pyproject.toml maps it), so that any install, editable or not, has them.
``govopt examples`` lists them (the trade studies of ``specs/studies/`` and the spring specs of
``specs/springs/`` too) and ``govopt init NAME`` copies one to start from; the CLI's default
specs are two of them.

>>> "hamabe-a" in examples() and example("hamabe-a.toml").name
'hamabe-a.toml'
>>> example("hamabe-desing")  # doctest: +ELLIPSIS
Traceback (most recent call last):
govopt.errors.GovoptError: no bundled example 'hamabe-desing' (did you mean 'hamabe-design'...
"""

from __future__ import annotations

import difflib
import tomllib
from importlib.resources import files
from pathlib import Path

from .errors import GovoptError

#: The folder of the bundled specs (the package ``govopt.specs``: ``specs/`` of a checkout or
#: an editable install, ``govopt/specs/`` of a plain one).
SPECS = Path(str(files("govopt.specs")))


def examples() -> dict[str, Path]:
    """Name (the file's stem) -> path of every bundled spec, the studies'
    (``specs/studies/``) and the spring specs' (``specs/springs/``, `govopt spring`) too,
    sorted by name.

    >>> examples()["hamabe-study"].parent.name
    'studies'
    """
    paths = [*SPECS.glob("*.toml"), *SPECS.glob("studies/*.toml"),
             *SPECS.glob("springs/*.toml")]
    return {p.stem: p for p in sorted(paths, key=lambda p: p.stem)}


def example(name: str) -> Path:
    """The bundled spec ``name`` (with or without ``.toml``); a :class:`GovoptError` naming
    the closest names when there is none."""
    stem = name[:-5] if name.endswith(".toml") else name
    found = examples()
    if stem in found:
        return found[stem]
    close = difflib.get_close_matches(stem, list(found), n=3, cutoff=0.6)
    hint = f" (did you mean {' or '.join(map(repr, close))}?)" if close else ""
    raise GovoptError(f"no bundled example {name!r}{hint}; `govopt examples` lists them")


def description(path: Path) -> str:
    """The spec's ``description`` (its ``name`` if it has none; empty if unreadable)."""
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))
    except (OSError, ValueError):
        return ""
    text = data.get("description") or data.get("name") or ""
    return text if isinstance(text, str) else ""
