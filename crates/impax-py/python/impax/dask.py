"""Sweeps on a Dask cluster: the points of a space cut into chunks, each resolved by
:func:`impax.resolve_batch` on a worker, the results reduced on the client.

Needs ``dask[distributed]`` (``pip install "impax[dask]"``), and impax installed on every
worker (the tasks call :func:`impax.study.run_chunk` by reference). The same call works on a
``LocalCluster`` and on a cluster of many machines::

    from distributed import LocalCluster
    import impax, impax.dask
    space = impax.study.RandomSample("rod", 10**8, {"angle": (0.1, 3.0)}, seed=1)
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster:
        r = impax.dask.sweep(space, "whittaker", client=cluster.scheduler_address, threads=1)
    print(r.summary.energy_gain_fraction)

On several machines: start ``dask scheduler`` on one, ``dask worker tcp://SCHEDULER:8786`` on
each (every machine with the same impax wheel installed), and pass
``client="tcp://SCHEDULER:8786"``. Parquet output (``parquet=DIR``) is written by the workers:
``DIR`` must be a path every worker can write to (a shared file system).
"""

from __future__ import annotations

import time

from . import study
from .study import SweepResult


def _workers(client) -> int:
    try:
        return len(client.scheduler_info()["workers"])
    except Exception:  # pragma: no cover - informational only
        return 0


def sweep(
    space,
    law: str = "energetic",
    *,
    chunk_size: int = 1 << 18,
    client=None,
    map: str | None = None,
    parquet: str | None = None,
    on_invalid: str = "mark",
    threads: int | None = None,
) -> SweepResult:
    """Resolve every point of ``space`` (an :class:`impax.study.Grid` or
    :class:`impax.study.RandomSample`) with ``law`` on a Dask cluster and reduce.

    ``client``: a ``distributed.Client``, a scheduler address (``"tcp://host:8786"``; a client
    is opened and closed here), or None (the current default client if there is one, else
    this process, as :func:`impax.study.run`). One task per chunk of ``chunk_size`` points;
    results are reduced as they arrive. ``map``, ``parquet``, ``on_invalid`` as in
    :func:`impax.study.run`; ``threads``: threads of each task's batch, 1 to
    ``impax.MAX_THREADS`` (256; default: every core of the worker's machine; use 1 with one
    single-threaded worker per core), checked before any task is sent.

    The numbers do not depend on the cluster: every point is a pure function of its index,
    so counts and maps are identical to :func:`impax.study.run` (and to one
    :func:`impax.resolve_batch` over all the points).
    """
    from distributed import Client, as_completed, get_client

    own = False
    if client is None:
        try:
            client = get_client()
        except ValueError:
            return study.run(
                space, law, chunk_size=chunk_size, map=map, parquet=parquet, on_invalid=on_invalid, threads=threads
            )
    elif isinstance(client, str):
        client = Client(client)
        own = True
    try:
        study._check(space, law, map, parquet, threads)
        t = time.perf_counter()
        n_chunks = len(study.chunks(len(space), chunk_size))
        collector = study._Collector(space, law, chunk_size, map)
        if n_chunks:
            [space_future] = client.scatter([space], broadcast=True, hash=False)
            futures = client.map(
                study.run_chunk,
                range(n_chunks),
                space=space_future,
                law=law,
                chunk_size=chunk_size,
                map=map,
                parquet=parquet,
                on_invalid=on_invalid,
                threads=threads,
                pure=False,
            )
            for future, r in as_completed(futures, with_results=True):
                if isinstance(r, BaseException):
                    raise r
                collector.add(r)
                future.release()
            del futures
        return collector.result(time.perf_counter() - t, _workers(client))
    finally:
        if own:
            client.close()
