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
import os
from collections.abc import Callable, Iterator, Sequence
from typing import Any, TypeVar

from haven_scenarios.record.report import csv_row
from haven_scenarios.run.grid import TrialSpec
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.run.trial import run_trial
from haven_scenarios.run.workers import Lost, run_on_workers
from haven_scenarios.study.rules import EndReason

Row = dict[str, Any]
Done = tuple[int, Row]  # a trial's index and metrics
LOCAL = "local"  # --cluster local: a Dask LocalCluster on this machine
Item = TypeVar("Item")
Result = TypeVar("Result")


def cores() -> int:
    """The cores this process may use (a container's or taskset's limit, not the machine's count)."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


def run_spec(spec: TrialSpec, suite: SuiteConfig | None = None) -> Row:
    """One trial's metrics, as compute() gives them (the parent makes the CSV row: a worker then
    need not import the recording reader behind `csv_row`, a second of start-up on a loaded machine)."""
    return run_trial(spec.scenario, spec.seed, spec.toggles, suite).metrics


def row_of(spec: TrialSpec, metrics: Row) -> Row:
    """A trial's CSV row: its design columns, then its metrics (flat, as `haven report` writes them)."""
    design = spec.columns()
    return {**design, **{k: v for k, v in csv_row(metrics).items() if k not in design}}


def run_rows(
    specs: Sequence[TrialSpec], suite: SuiteConfig | None = None, workers: int = 1, cluster: str | None = None
) -> Iterator[Row]:
    """Every spec's row, in the order the trials finish."""
    done = farm(specs, functools.partial(_indexed, suite=suite), workers, cluster, _lost)
    by_index = {s.index: s for s in specs}
    return (row_of(by_index[i], metrics) for i, metrics in done)


def farm(
    items: Sequence[Item],
    task: Callable[[Item], Result],
    workers: int = 1,
    cluster: str | None = None,
    lost: Lost | None = None,
) -> Iterator[Result]:
    """`task` of every item (a picklable, module-level function), in the order they finish: here,
    on `workers` processes (run/workers.py: one whose worker ends without a result gives `lost`'s)
    or on the Dask `cluster`. Trials use it; so does `haven study power`."""
    if cluster is not None:
        return _on_dask(items, task, cluster, workers)
    if workers <= 1 or len(items) <= 1:
        return map(task, items)
    return run_on_workers(items, task, workers, lost)


def _indexed(spec: TrialSpec, suite: SuiteConfig | None) -> tuple[int, Row]:
    return spec.index, run_spec(spec, suite)


def _lost(spec: TrialSpec, why: str, stuck: bool) -> Done:
    """A trial whose worker process was ended without its row (a plugin stuck where its deadline
    cannot interrupt it, or a crash): its row, not valid with the reason."""
    reason = EndReason.PLUGIN_FAILED if stuck else EndReason.INTERRUPTED
    return spec.index, {
        "scenario": spec.scenario.name,
        "end_reason": str(reason),
        "duration_s": None,
        "valid": False,
        "invalid_reasons": [why],
    }


def _on_dask(specs: Sequence[Item], task: Callable[[Item], Result], cluster: str, workers: int) -> Iterator[Result]:
    """On a Dask cluster: a LocalCluster of `workers` processes (one thread each: a trial is
    CPU-bound Python), or the scheduler at `cluster`'s address with the workers it has."""
    import logging

    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError as e:
        raise ValueError("--cluster needs dask and distributed: pip install 'haven_scenarios[cluster]'") from e

    local = None
    if cluster == LOCAL:
        local = LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=logging.ERROR
        )
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
