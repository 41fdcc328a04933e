"""Every call into a plugin's code contained: a raise or an overrun of the kind's deadline becomes a
`PluginFailed` naming the kind, the plugin and the error, for the caller to end that trial with (not
valid: `<kind> <name> failed (<error>)`, record/validity.py), never the sweep or the suite.

A hanging Python call cannot be killed from outside, so a watchdog interrupts it: a daemon thread
looks at the calls under way every WATCH_S and, for one past its deadline, raises `Overrun` inside
it: in the main thread by a real-time signal whose handler raises (this also breaks a `time.sleep`
or a lock wait), in another thread by `PyThreadState_SetAsyncExc` (Python code only; a call blocked
in C is interrupted when it comes back). `Overrun` is a BaseException, so a plugin's own `except
Exception` cannot swallow it. A call no exception reaches (C code that never returns, signals
blocked) is found stuck after STUCK_SENDS tries and `on_stuck` is called: a sweep's worker process
(haven_scenarios/run/workers.py) or a node (nodes/component_node.py) then says so and ends itself,
and the sweep writes the trial's row not valid (the suite's supervisor ends the trial).

The deadlines are parameters of every node (`PluginDeadlines`, the "/**" section of a parameter
file), set for the process by the node or the batch trial (`use`). Their defaults are ours, far
above what HAVEN's own items take (milliseconds a call; a metric group, a second at most), so that
only a plugin that is stuck meets them on a loaded machine.
"""

from __future__ import annotations

import ctypes
import os
import signal
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, fields
from typing import Any, TypeVar

from haven_sim.common.events import Event, EventKind
from haven_sim.common.params import POSITIVE, config, param

T = TypeVar("T")
WATCH_S = 0.05  # how often the watchdog looks (an overrun is interrupted at most this late)
_SIGNAL = signal.SIGRTMIN + 3 if hasattr(signal, "SIGRTMIN") else None  # (not one of the suite's stop signals)


@config
class PluginDeadlines:
    """How long one call into a plugin's code may take before its trial is ended not valid, per kind."""

    plugin_deadline_participants_s: float = param(
        2.0, "a participant model's one call (made, or its command at a scenario tick)", POSITIVE
    )
    plugin_deadline_missions_s: float = param(2.0, "a mission behaviour's one call (arrange, pick)", POSITIVE)
    plugin_deadline_planners_s: float = param(10.0, "a planner plugin's one call (made for a map, plan)", POSITIVE)
    plugin_deadline_cues_s: float = param(1.0, "a cue's one call (made, show)", POSITIVE)
    plugin_deadline_metrics_s: float = param(60.0, "one metric over the whole trial", POSITIVE)
    plugin_deadline_load_s: float = param(
        30.0, "importing one plugin of any kind (questionnaires and robots are data: only loaded)", POSITIVE
    )

    def of(self, kind: str) -> float:
        value: float = getattr(self, f"plugin_deadline_{kind}_s", self.plugin_deadline_load_s)
        return value


_deadlines = PluginDeadlines()


def deadlines() -> PluginDeadlines:
    return _deadlines


def set_deadlines(d: PluginDeadlines) -> None:
    """The deadlines of this process (a node sets them from its parameters)."""
    global _deadlines
    _deadlines = d


@contextmanager
def use(d: PluginDeadlines | None) -> Iterator[None]:
    """`d` as this process's deadlines while the block runs (a batch trial's, from its suite)."""
    before = _deadlines
    set_deadlines(d if d is not None else before)
    try:
        yield
    finally:
        set_deadlines(before)


def kinds() -> list[str]:
    return [f.name.removeprefix("plugin_deadline_").removesuffix("_s") for f in fields(PluginDeadlines)]


class Overrun(BaseException):
    """Raised inside a call that is past its deadline."""


class PluginFailed(Exception):
    """A plugin's call raised or overran its deadline: `reason` is the trial's invalid reason."""

    def __init__(self, kind: str, name: str, error: str) -> None:
        super().__init__(reason(kind, name, error))
        self.kind, self.name, self.error = kind, name, error

    @property
    def reason(self) -> str:
        return str(self)

    def __reduce__(self) -> tuple[Any, ...]:  # (it crosses from a worker process to the sweep)
        return PluginFailed, (self.kind, self.name, self.error)


def failed_event(failed: PluginFailed, now: float, source: str) -> Event:
    """The `plugin_failed` event that says so on the study log."""
    return Event(
        EventKind.PLUGIN_FAILED, now, source, {"kind": failed.kind, "name": failed.name, "error": failed.error}
    )


def failures(events: Iterable[Event]) -> list[str]:
    """The one validity rule for plugins: each `plugin_failed` (and the `cue_failed` of older
    recordings) is a reason the trial is not valid, said as `reason` says it."""
    out = []
    for e in events:
        if e.kind is EventKind.PLUGIN_FAILED:
            out.append(reason(str(e["kind"]), str(e["name"]), str(e["error"])))
        elif e.kind is EventKind.CUE_FAILED:
            out.append(reason("cues", str(e["cue"]), str(e["error"])))
    return out


def reason(kind: str, name: str, error: str) -> str:
    """The one line a failed plugin gives its trial (validity, batch rows and session.json say it so)."""
    return f"{singular(kind)} {name} failed ({error})"


@dataclass
class _Call:
    kind: str
    name: str
    deadline: float
    sent: int = 0  # how often Overrun was sent


STUCK_SENDS = 5  # sent this often (a second apart) and still running: stuck where no exception lands (C code)
STUCK_EXIT = 70  # the exit code of a process that ends itself for a stuck plugin (a batch worker, a node)
# then called once, from the watchdog (a batch worker: ends its process)
on_stuck: Callable[[PluginFailed], None] | None = None


_active: dict[int, _Call] = {}
_lock = threading.Lock()
_watching_pid = 0  # the process whose watchdog runs (a forked child starts its own)
_handler_pid = 0  # the process whose main thread has the signal's handler


def call(kind: str, name: str, fn: Callable[..., T], *args: Any, expected: tuple[type[Exception], ...] = ()) -> T:
    """`fn(*args)`, a plugin's code: its value, or PluginFailed (one line) when it raised (other than
    the `expected` exceptions its kind may raise, which pass) or ran past `kind`'s deadline. A
    PluginFailed from a call nested in it passes through unchanged (while a nested call runs, only
    its deadline is watched)."""
    limit = _deadlines.of(kind)
    passing: tuple[type[Exception], ...] = (PluginFailed, *expected)
    tid = threading.get_ident()
    me, outer = _Call(kind, name, time.monotonic() + limit), _active.get(tid)
    _start_watchdog(tid)
    try:
        try:
            _active[tid] = me
            return fn(*args)
        finally:
            with _lock:
                if outer is not None:
                    _active[tid] = outer
                else:
                    _active.pop(tid, None)
                if me.sent and tid != threading.main_thread().ident:
                    # (one sent but not yet raised: withdrawn)
                    ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(tid), None)
    except Overrun:
        raise PluginFailed(kind, name, f"took longer than its deadline of {limit:g} s") from None
    except passing:
        raise
    except Exception as e:
        raise PluginFailed(kind, name, failure(e)) from None


def _on_signal(signum: int, frame: Any) -> None:
    mine = _active.get(threading.get_ident())
    if mine is not None and mine.sent:
        raise Overrun


def _start_watchdog(tid: int) -> None:
    """The watchdog of this process, and the signal's handler once the main thread calls."""
    global _watching_pid, _handler_pid
    pid = os.getpid()
    if _handler_pid != pid and _SIGNAL is not None and tid == threading.main_thread().ident:
        signal.signal(_SIGNAL, _on_signal)
        _handler_pid = pid
    if _watching_pid != pid:
        with _lock:
            if _watching_pid != pid:
                threading.Thread(target=_watch, name="haven-plugin-watchdog", daemon=True).start()
                _watching_pid = pid


def _watch() -> None:
    """Interrupt each call past its deadline (again every second until it ends)."""
    main = threading.main_thread().ident
    while True:
        time.sleep(WATCH_S)
        now = time.monotonic()
        with _lock:
            for tid, c in list(_active.items()):
                if now <= c.deadline:
                    continue
                c.sent, c.deadline = c.sent + 1, now + 1.0
                if c.sent == STUCK_SENDS and on_stuck is not None:
                    why = (
                        f"still running {c.sent - 1} s past its deadline of "
                        f"{_deadlines.of(c.kind):g} s, where it cannot be interrupted"
                    )
                    on_stuck(PluginFailed(c.kind, c.name, why))
                if tid == main and _SIGNAL is not None and _handler_pid == os.getpid():
                    signal.pthread_kill(tid, _SIGNAL)
                else:
                    ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(tid), ctypes.py_object(Overrun))


def singular(kind: str) -> str:
    return {"participants": "participant model", "missions": "mission behaviour"}.get(kind, kind.rstrip("s"))


def failure(e: BaseException) -> str:
    """What a plugin's code raised, in one line (`ValueError: what it said`, at most 200 characters):
    every place that contains a failing plugin says it so."""
    return f"{type(e).__name__}: {first_line(e)}"[:200].rstrip(": ")


def first_line(e: BaseException) -> str:
    """What an exception says, its first line only."""
    return str(e).splitlines()[0] if str(e) else ""
