"""Atomic file output and the design-as-spec writer (formats only, no physics)."""

from __future__ import annotations

import contextlib
import os
import re
import tempfile
from collections.abc import Callable
from pathlib import Path

from ..errors import GovoptError
from ..result import Result


def atomic_write(path: str | Path, write: Callable[[Path], None]) -> Path:
    """Call ``write(tmp)`` on a temporary file beside ``path``, then rename it into place.

    On any error the temporary file is removed and ``path`` is left as it was: nothing
    half-written is ever left on disk.
    """
    path = Path(path)
    if not path.parent.exists():
        raise GovoptError(f"{path}: cannot write: folder {path.parent} does not exist")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        write(Path(tmp))
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    return path


def design_toml(res: Result) -> str:
    """The spec file of ``res`` with its ``[design]`` table replaced by the chosen design, in SI
    with full precision, so that `govopt evaluate` reproduces the design exactly."""
    text = Path(res.spec.path).read_text(encoding="utf-8")
    text = re.sub(r"(?ms)^\[design\][^\[]*", "", text).rstrip() + "\n"
    d, sd = res.design, res.spring
    lines = ["", "[design]  # written by govopt design", f'pendulum_mass = "{sd.m!r} kg"',
             f'wire_diameter = "{sd.d!r} m"', f'coil_radius = "{sd.r!r} m"',
             f"active_turns = {sd.n!r}", f'free_half_length = "{sd.l0!r} m"']
    if d.pendulum_inertia is not None:
        lines.append(f'pendulum_inertia = "{d.pendulum_inertia!r} kg*m^2"')
    if d.dashpot is not None:
        lines.append(f'dashpot_f = "{d.dashpot!r} N*m*s/rad"')
    if d.friction_moment is not None:
        lines.append(f'friction_moment = "{d.friction_moment!r} N*m"')
    return text + "\n".join(lines) + "\n"


def write_design_spec(res: Result, path: str | Path) -> Path:
    text = design_toml(res)
    return atomic_write(path, lambda tmp: tmp.write_text(text, encoding="utf-8"))
