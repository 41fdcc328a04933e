"""Where a sweep's trials run: in this process, in worker processes on every core, or on a Dask cluster.

A trial's row depends only on its `TrialSpec` (its own seed; no module-level random state, caches
that change results or set-ordering in the core), so one worker, all cores and a cluster give
byte-identical rows. Worker processes are started with "spawn": a fresh interpreter, like a Dask
worker, so nothing inherited from the parent (an RNG, a cache, numpy's thread pools) can leak in.
Rows come back in the order trials finish; `run/batch.py` journals them and sorts the CSV.

Dask rather than Ray for the cluster: Dask's wheels are pure Python (dask, distributed and their
dependencies add about 37 MB), a `LocalCluster` needs no daemon, and a lab's machines run
`dask scheduler` on one and `dask worker tcp://HOST:8786` on the others.
"""

from __future__ import annotations

import functools
import itertools
import multiprocessing
import os
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any

from haven_scenarios.record.report import csv_row
from haven_scenarios.run.grid import TrialSpec
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.run.trial import run_trial

Row = dict[str, Any]
LOCAL = "local"  # --cluster local: a Dask LocalCluster on this machine
IN_FLIGHT_PER_WORKER = 4  # trials handed to the pool ahead of need (bounded memory on a long sweep)


def cores() -> int:
    """The cores this process may use (a container's or taskset's limit, not the machine's count)."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


def run_spec(spec: TrialSpec, suite: SuiteConfig | None = None) -> Row:
    """One trial's CSV row: its design columns, then its metrics (flat, as `haven report` writes them)."""
    result = run_trial(spec.scenario, spec.seed, spec.toggles, suite)
    design = spec.columns()
    return {**design, **{k: v for k, v in csv_row(result.metrics).items() if k not in design}}


def run_rows(specs: Sequence[TrialSpec], suite: SuiteConfig | None = None, workers: int = 1, cluster: str | None = None) -> Iterator[Row]:
    """Every spec's row, in the order the trials finish."""
    task = functools.partial(run_spec, suite=suite)
    if cluster is not None:
        return _on_dask(specs, task, cluster, workers)
    if workers <= 1 or len(specs) <= 1:
        return map(task, specs)
    return _on_processes(specs, task, workers)


def _on_processes(specs: Sequence[TrialSpec], task: Callable[[TrialSpec], Row], workers: int) -> Iterator[Row]:
    """A pool of fresh worker processes; a failed trial stops the sweep (the pending ones are cancelled)."""
    todo = iter(specs)
    with ProcessPoolExecutor(max_workers=min(workers, len(specs)), mp_context=multiprocessing.get_context("spawn")) as pool:
        running: set[Future[Row]] = set()
        try:
            while True:
                running |= {pool.submit(task, s) for s in itertools.islice(todo, workers * IN_FLIGHT_PER_WORKER - len(running))}
                if not running:
                    return
                done, running = wait(running, return_when=FIRST_COMPLETED)
                for f in done:
                    yield f.result()
        finally:
            for f in running:
                f.cancel()


def _on_dask(specs: Sequence[TrialSpec], task: Callable[[TrialSpec], Row], cluster: str, workers: int) -> Iterator[Row]:
    """On a Dask cluster: a LocalCluster of `workers` processes (one thread each: a trial is
    CPU-bound Python), or the scheduler at `cluster`'s address with the workers it has."""
    import logging

    from distributed import Client, LocalCluster, as_completed

    local = None
    if cluster == LOCAL:
        local = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=logging.ERROR)
    try:
        with Client(local if local is not None else cluster, timeout="10s") as client:
            futures = client.map(task, specs, pure=False)
            try:
                for f in as_completed(futures):
                    yield f.result()
            finally:
                client.cancel(futures)
    finally:
        if local is not None:
            local.close()
