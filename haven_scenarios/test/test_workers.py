"""The sweep's worker processes (run/workers.py): a worker that ends without its result costs that
item only (what `lost` makes of it; a fresh worker takes the next), and a task's exception stops
the sweep as it did with a pool."""

from __future__ import annotations

import os

import pytest

from haven_scenarios.run.workers import WorkerLost, run_on_workers

pytestmark = pytest.mark.integration  # (worker processes)


def square_or_die(x: int) -> int:
    if x == 2:
        os._exit(9)  # (a crash in an extension, say)
    if x == 3:
        raise ValueError("three")
    return x * x


def test_a_worker_that_ends_costs_its_item_only_and_a_task_error_stops_the_sweep():
    got = list(run_on_workers([0, 1, 2, 4, 5], square_or_die, 2, lambda item, why, stuck: (item, why, stuck)))
    assert sorted(r for r in got if isinstance(r, int)) == [0, 1, 16, 25]
    assert [r for r in got if isinstance(r, tuple)] == [(2, "its worker process ended (exit code 9)", False)]
    with pytest.raises(
        WorkerLost, match=r"a worker process ended without a result: its worker process ended \(exit code 9\)"
    ):
        list(run_on_workers([2, 0], square_or_die, 2))
    with pytest.raises(ValueError, match="three"):
        list(run_on_workers([3, 0], square_or_die, 2))
