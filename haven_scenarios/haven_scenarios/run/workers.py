"""Worker processes a sweep can end and replace: one item at a time each, over a pipe.

A trial whose plugin is stuck where no deadline can interrupt it (C code that never returns; the
plugin watchdog, haven_sim/common/contain.py, says so after `STUCK_SENDS` tries), or whose worker
dies (a crash in an extension), costs that trial only: the worker is ended, the trial's result is
what `lost(item, reason)` makes of it (a row not valid with the reason), a fresh worker takes the
next item, and the sweep goes on. (multiprocessing's Pool cannot do this: a worker that dies takes
its task's result with it and the pool waits for ever.) Workers are started with "spawn", fresh
interpreters, as sweep.py explains.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from multiprocessing.process import BaseProcess
from typing import Any, TypeVar

from haven_sim.common import contain

Item = TypeVar("Item")
Result = TypeVar("Result")
Lost = Callable[[Any, str, bool], Any]  # (item, why, a plugin was stuck) -> its result


class WorkerLost(RuntimeError):
    """A worker ended without a result and nothing says what a lost item's result is."""


def _serve(conn: Connection, task: Callable[[Any], Any]) -> None:
    """A worker: items in, ("ok", result) or ("error", exception) out, until None comes."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # (Ctrl-C is the parent's: it ends the workers)

    def stuck(failed: contain.PluginFailed) -> None:
        conn.send(("stuck", failed.reason))
        os._exit(contain.STUCK_EXIT)

    contain.on_stuck = stuck
    while (item := conn.recv()) is not None:
        try:
            conn.send(("ok", task(item)))
        except Exception as e:
            try:
                conn.send(("error", e))
            except Exception:
                conn.send(("error", RuntimeError(f"{type(e).__name__}: {e}")))


@dataclass
class _Worker:
    process: BaseProcess
    conn: Connection
    item: Any = None
    busy: bool = False
    why: str = ""  # how it ended without a result
    stuck: bool = False  # ... a plugin stuck past its deadline (its watchdog said so)


def _start(task: Callable[[Any], Any]) -> _Worker:
    parent, child = multiprocessing.get_context("spawn").Pipe()
    process = multiprocessing.get_context("spawn").Process(target=_serve, args=(child, task), daemon=True)
    main = threading.current_thread() is threading.main_thread()  # (only the main thread may set handlers)
    # inherited: a Ctrl-C while it starts is not its
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    try:
        process.start()
    finally:
        if main:
            signal.signal(signal.SIGINT, previous)
    child.close()
    return _Worker(process, parent)


def _end(w: _Worker) -> None:
    if w.process.is_alive():
        w.process.kill()
    w.process.join(5.0)
    w.conn.close()


def run_on_workers(
    items: Sequence[Item], task: Callable[[Item], Result], workers: int, lost: Lost | None = None
) -> Iterator[Result]:
    """`task` of every item on `workers` processes, in the order they finish. An item whose worker
    ended without a result gives `lost(item, why, stuck)` (None: WorkerLost). A task's exception or a
    Ctrl-C stops the sweep (raised here; the finished results have been yielded; the workers ended)."""
    todo: deque[Any] = deque(items)
    pool: list[_Worker] = []
    try:
        pool = [_start(task) for _ in range(min(workers, len(todo)))]
        while todo or any(w.busy for w in pool):
            for k, w in enumerate(pool):
                if not w.busy and todo:
                    if not w.process.is_alive():  # (ended while idle: replaced before it is given work)
                        _end(w)
                        pool[k] = w = _start(task)
                    w.item, w.busy = todo.popleft(), True
                    w.conn.send(w.item)
            ready = wait([w.conn for w in pool if w.busy] + [w.process.sentinel for w in pool if w.busy])
            for k, w in enumerate(pool):
                if not w.busy or (w.conn not in ready and w.process.sentinel not in ready):
                    continue
                got = _result(w)
                if got is None:  # (ended: its item is lost, a fresh worker takes its place)
                    yield _lost(w, lost)
                    _end(w)
                    pool[k] = _start(task)
                    continue
                w.busy = False
                if got[0] == "error":
                    raise got[1]
                yield got[1]
    finally:
        for w in pool:
            _end(w)


def _result(w: _Worker) -> tuple[str, Any] | None:
    """The worker's answer; None if it ended without one (`why` says how)."""
    try:
        if w.conn.poll():
            got: tuple[str, Any] = w.conn.recv()
            if got[0] != "stuck":
                return got
            w.why, w.stuck = got[1], True
            return None
    except (EOFError, OSError):
        pass
    w.process.join(5.0)
    w.why = f"its worker process ended ({_how(w.process.exitcode)})"
    return None


def _how(code: int | None) -> str:
    if code is None:
        return "still running"
    return f"signal {signal.Signals(-code).name}" if code < 0 else f"exit code {code}"


def _lost(w: _Worker, lost: Lost | None) -> Any:
    if lost is None:
        raise WorkerLost(f"a worker process ended without a result: {w.why}")
    return lost(w.item, w.why, w.stuck)
