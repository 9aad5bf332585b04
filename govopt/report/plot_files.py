"""The plots of a result as files: ``<folder>/<stem>-<kind>.png|svg`` (``govopt evaluate --plots``).

The drawing is :mod:`govopt.report.plots`'s; this module checks the folder before a run and writes
each plot through :func:`govopt.report.files.atomic_write` and its no-clobber policy. Kept apart
from the drawing so that :meth:`govopt.result.Result.plot` imports no file writer (and, through
it, nothing that imports the result back).
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from ..errors import GovoptError
from .files import atomic_write, check_output, output_folder
from .plots import FORMATS, KINDS, STYLE, draw, kinds

__all__ = ["check_plot_dir", "save_figure", "write_plots"]


def _stem(res) -> str:
    path = getattr(res.spec, "path", None)
    return Path(path).stem if path else re.sub(r"[^\w.-]+", "-", res.spec.name)


def _pattern(stem: str):
    names = "|".join(re.escape(k) for k in KINDS if k != "load-change")
    exts = "|".join(FORMATS)
    return re.compile(rf"{re.escape(stem)}-(?:{names}|load-change-\d+)\.(?:{exts})")


def check_plot_dir(directory: str | Path, stem: str, *, overwrite: bool = False,
                   inputs=(), others=()) -> Path:
    """Before a run (the CLI's ``--plots DIR``): the folder exists (it is made if only its parent
    does), can be written, and holds no plot ``<stem>-<kind>.png|svg`` unless ``overwrite``
    (only regular files are ever replaced); no other output of the run (``others``) has a plot's
    name in it. Raises :class:`GovoptError` with one line."""
    directory = Path(directory)
    pattern = _pattern(stem)
    for other in map(Path, others):
        if os.path.realpath(other) == os.path.realpath(directory):
            raise GovoptError(f"{other}: cannot write it: it is the plots folder of this run")
        if pattern.fullmatch(other.name) and os.path.realpath(other.parent) == os.path.realpath(
                directory):
            raise GovoptError(f"{other}: cannot write it: it is also a plot of this run")
    directory = output_folder(directory, "plots")
    check_output(directory / f"{stem}-characteristic.png", overwrite=overwrite, inputs=inputs,
                 what="plot")
    for entry in sorted(directory.iterdir()):
        if pattern.fullmatch(entry.name):
            check_output(entry, overwrite=overwrite, inputs=inputs, what="plot")
    return directory


def write_plots(res, directory: str | Path, *, stem: str | None = None,
                overwrite: bool | None = None, formats=FORMATS) -> list[Path]:
    """Write every plot of ``res`` as ``<directory>/<stem>-<kind>.<format>`` (stem: the spec
    file's name) through :func:`atomic_write` (``overwrite``: its policy); return the paths."""

    stem = stem or _stem(res)
    written = []
    for name in kinds(res):
        written += save_figure(draw(res, name).figure, Path(directory) / f"{stem}-{name}",
                               overwrite, formats)
    return written


def save_figure(fig, base: Path, overwrite: bool | None = None, formats=FORMATS) -> list[Path]:
    """``fig`` as ``<base>.<format>`` for each format, in the plots' style, each through
    :func:`atomic_write` (``overwrite``: its policy); an SVG carries no date, so the same
    figure gives the same file."""
    import matplotlib as mpl

    written = []
    for fmt in formats:
        def save(tmp, fmt=fmt):
            with mpl.rc_context(STYLE):
                fig.savefig(tmp, format=fmt, metadata={"Date": None} if fmt == "svg" else {})

        written.append(atomic_write(Path(f"{base}.{fmt}"), save, overwrite=overwrite,
                                    what="plot"))
    return written
