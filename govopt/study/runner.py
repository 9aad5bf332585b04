"""Running a study into its database: blocks of points on this process, a process pool or a
Dask cluster (:mod:`govopt.study.backends`), each block's rows committed as it finishes.

Only this process writes the database. A block is sent as the study's definition and its
points' numbers (a worker makes the points itself: :func:`govopt.study.rows.run_chunk`), so
nothing the size of the study is ever held or sent; blocks are handed out a few ahead of the
workers, never all at once.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .backends import check_dask_address, run_dask, run_pool
from .definition import Study
from .errors import StudyError
from .rows import run_chunk
from .store import Store, check_database, remove_database


@dataclass
class RunReport:
    """What a run did: the study's points (``total``), those already in the database
    (``skipped``), those computed now (``done``), the failed rows in the database
    (``failures``), whether Ctrl-C stopped it, and notes for the user (one line each)."""

    total: int
    skipped: int = 0
    done: int = 0
    failures: int = 0
    interrupted: bool = False
    notes: list[str] = field(default_factory=list)


def default_chunk(study: Study) -> int:
    """Points per block (and per database transaction): a vectorised batch for evaluate mode,
    one design at a time for design mode."""
    return 1024 if study.mode == "evaluate" else 1


def run_study(study: Study, db: str | Path, *, workers: int = 1, dask: str | None = None,
              resume: bool = False, fresh: bool = False, chunk: int | None = None,
              progress: Callable[[int, int, int], None] | None = None) -> RunReport:
    """Run ``study`` into the database ``db`` and return what was done.

    ``workers`` > 1: blocks on a process pool; ``dask``: ``"local"`` starts a
    ``dask.distributed.LocalCluster`` of ``workers`` processes, an address
    (``tcp://host:port``) uses a running scheduler. ``resume`` skips the points already in the
    database (which must hold this study); ``fresh`` starts afresh on a database that holds
    rows, another study, another format, or is damaged. ``progress(done, failures, total)``
    is called before the first block and after each. Ctrl-C stops after the blocks already
    finished, which are kept (``interrupted`` in the report).
    """
    check_dask_address(dask)
    db = check_database(db, inputs=[study.path])
    total = study.count()
    definition = json.loads(json.dumps(study.definition(), default=str))
    text = json.dumps(definition, sort_keys=True)
    size = chunk or default_chunk(study)
    for attempt in (0, 1):
        with _open(db, fresh) as store:
            try:
                notes = store.claim(definition, total, resume=resume, fresh=fresh,
                                    recompute=lambda points: run_chunk(text, points))
            except StudyError as exc:  # damaged past its header: with --force, afresh
                if attempt or not (fresh and exc.kind == "damaged"):
                    raise
            else:
                return _run(store, text, total, size, workers, dask, progress, notes)
        remove_database(db)
    raise AssertionError("unreachable")


def _open(db: Path, fresh: bool) -> Store:
    """The database opened for a run; a damaged one replaced when ``fresh``."""
    try:
        return Store(db)
    except StudyError as exc:
        if not (fresh and exc.kind == "damaged"):
            raise
    remove_database(db)
    return Store(db)


def _run(store: Store, text: str, total: int, size: int, workers: int, dask: str | None,
         progress, notes: list[str]) -> RunReport:
    store.start()
    before = store.count()
    report = RunReport(total, failures=store.failures(), notes=notes)

    def todo(lo: int, hi: int) -> np.ndarray:
        """The points of block ``[lo, hi)`` not yet in the database (an earlier run's,
        resumed, or another process's running the same study: they cooperate)."""
        done = store.done(lo, hi)
        report.skipped += len(done)
        return np.array([i for i in range(lo, hi) if i not in done], dtype=np.int64)

    def blocks():
        for lo in range(0, total, size):
            points = todo(lo, min(lo + size, total))
            if points.size:
                yield points

    def commit(rows) -> None:
        store.add(rows)
        report.done += len(rows)
        report.failures += rows.failures()
        if progress is not None:
            progress(max(before, report.skipped + report.done), report.failures, total)

    if progress is not None:
        progress(before, report.failures, total)
    try:
        if dask:
            run_dask(text, blocks(), commit, dask, workers)
        elif workers > 1 and total > size:
            run_pool(text, blocks(), commit, workers)
        else:
            for points in blocks():
                commit(run_chunk(text, points))
    except KeyboardInterrupt:
        report.interrupted = True
    return report
