"""Where a study's blocks of points run: a process pool or a Dask cluster.

Each backend takes the study's definition (JSON text), an iterator of blocks (arrays of point
numbers) and ``commit(rows)``, called in this process as each block's rows come back. At most
:data:`AHEAD` blocks per worker are in flight: the blocks are made as they are sent, so a
million-point study never holds its blocks.
"""

from __future__ import annotations

import itertools
import re

from .. import limits
from .errors import StudyError
from .rows import run_chunk

#: blocks in flight per worker
AHEAD = 2

#: a Dask scheduler's address: ``[protocol://]host:port`` (or an in-process cluster's)
_DASK_ADDRESS = re.compile(r"(?:(?:tcp|tls|ws|wss|ucx)://)?(?:\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+)"
                           r":(\d{1,5})|inproc://[\w.:/-]+")


def check_dask_address(address: str | None) -> None:
    """``--dask``: ``"local"`` or a scheduler's ``[tcp://]HOST:PORT`` (one line if not)."""
    if address is None or address == "local":
        return
    m = _DASK_ADDRESS.fullmatch(str(address))
    if m is None or (m[1] is not None and not 0 < int(m[1]) < 65536):
        raise StudyError(f"expected 'local' or a scheduler address HOST:PORT or "
                         f"tcp://HOST:PORT, got {limits.shorten(address)}", where="--dask")


def _ignore_sigint():
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C


def run_pool(text: str, blocks, commit, workers: int) -> None:
    """Blocks on a pool of ``workers`` processes; rows committed by this process as they
    finish. An error or Ctrl-C stops the work in flight at once (the pool terminated)."""
    import multiprocessing
    import queue

    done: queue.Queue = queue.Queue()
    pool = multiprocessing.Pool(workers, initializer=_ignore_sigint)
    try:
        def send(block) -> None:
            pool.apply_async(run_chunk, (text, block), callback=done.put,
                             error_callback=done.put)

        pending = 0
        for block in itertools.islice(blocks, AHEAD * workers):
            send(block)
            pending += 1
        while pending:
            rows = done.get()
            pending -= 1
            if isinstance(rows, BaseException):
                raise rows
            commit(rows)
            nxt = next(blocks, None)
            if nxt is not None:
                send(nxt)
                pending += 1
    except BaseException:
        pool.terminate()
        raise
    finally:
        pool.close()
        pool.join()


def run_dask(text: str, blocks, commit, address: str, workers: int) -> None:
    """Blocks on a Dask cluster: ``"local"`` starts a ``LocalCluster`` (``workers``
    processes, one thread each), an address uses a running scheduler."""
    try:
        from dask.distributed import Client, LocalCluster, as_completed
    except ImportError:
        raise StudyError("needs dask.distributed (pip install 'dask[distributed]')",
                         where="--dask") from None
    cluster = None
    if address == "local":
        cluster = LocalCluster(n_workers=max(1, workers), threads_per_worker=1,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        try:
            client = Client(address, timeout=30)
        except OSError as exc:
            raise StudyError(f"cannot reach the scheduler ({exc})", where=f"--dask {address}") \
                from None
    try:
        ahead = AHEAD * max(1, sum(client.nthreads().values()))
        futures = as_completed([client.submit(run_chunk, text, b, pure=False)
                                for b in itertools.islice(blocks, ahead)])
        for fut in futures:
            commit(fut.result())
            nxt = next(blocks, None)
            if nxt is not None:
                futures.add(client.submit(run_chunk, text, nxt, pure=False))
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
