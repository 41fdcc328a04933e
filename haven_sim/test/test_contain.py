"""Every plugin call contained (common/contain.py): a raise or an overrun of the kind's deadline is a
PluginFailed saying `<kind> <name> failed (<error>)`, in the main thread (a signal breaks even a
sleep) and in any other (a busy plugin), also for a plugin that swallows every Exception."""

from __future__ import annotations

import contextlib
import pickle
import threading
import time

import pytest

from haven_sim.common import contain
from haven_sim.common.events import EventKind
from haven_sim.common.params import ParamsError
from haven_sim.robots.fields import build_config

SHORT = contain.PluginDeadlines(plugin_deadline_participants_s=0.2, plugin_deadline_metrics_s=0.3)


def sleeps() -> None:
    while True:
        with contextlib.suppress(Exception):
            time.sleep(3600)


def spins() -> None:
    while True:
        with contextlib.suppress(Exception):
            pass


def breaks() -> None:
    raise RuntimeError("broke\nsecond line")


def failed(kind: str, fn) -> tuple[contain.PluginFailed, float]:
    started = time.monotonic()
    with pytest.raises(contain.PluginFailed) as e, contain.use(SHORT):
        contain.call(kind, "shy", fn)
    return e.value, time.monotonic() - started


def test_a_raise_is_one_line_naming_kind_plugin_and_error():
    e, _ = failed("participants", breaks)
    assert (e.kind, e.name, e.error, e.reason) == (
        "participants",
        "shy",
        "RuntimeError: broke",
        "participant model shy failed (RuntimeError: broke)",
    )
    event = contain.failed_event(e, 2.0, "scenario")
    assert event.kind is EventKind.PLUGIN_FAILED and dict(event.data) == {
        "kind": "participants",
        "name": "shy",
        "error": "RuntimeError: broke",
    }
    assert contain.failures([event]) == [e.reason]
    assert str(pickle.loads(pickle.dumps(e))) == e.reason  # (from a worker process to the sweep)


@pytest.mark.parametrize("hang", [sleeps, spins])
def test_a_hang_in_the_main_thread_ends_at_its_kinds_deadline(hang):
    e, took = failed("metrics", hang)
    assert e.reason == "metric shy failed (took longer than its deadline of 0.3 s)"
    assert 0.3 <= took < 0.3 + 1.0


def test_a_hang_in_another_thread_ends_at_its_deadline_too():
    got: list[tuple[contain.PluginFailed, float]] = []
    worker = threading.Thread(target=lambda: got.append(failed("participants", spins)))
    worker.start()
    worker.join(10.0)
    assert not worker.is_alive() and got[0][0].error == "took longer than its deadline of 0.2 s" and got[0][1] < 1.2


def test_a_call_in_time_gives_its_value_and_expected_exceptions_pass():
    with contain.use(SHORT):
        assert contain.call("participants", "ok", lambda x: x + 1, 1) == 2
        with pytest.raises(KeyError):
            contain.call("planners", "ok", lambda: {}["refused"], expected=(KeyError,))
        time.sleep(0.3)  # (past the deadline of a call that has ended: nothing is raised here)


def test_the_deadlines_are_parameters_with_bounds_one_per_kind():
    assert contain.deadlines().of("participants") == contain.PluginDeadlines().plugin_deadline_participants_s
    # (data: only loaded)
    assert contain.PluginDeadlines().of("robots") == contain.PluginDeadlines().plugin_deadline_load_s
    assert set(contain.kinds()) == {"participants", "missions", "planners", "cues", "metrics", "load"}
    with pytest.raises(ParamsError, match="plugin_deadline_metrics_s: must be positive"):
        build_config(contain.PluginDeadlines, {"plugin_deadline_metrics_s": 0.0}, where="/**: ")


def test_a_plugin_whose_import_hangs_is_left_out_at_the_load_deadline_in_one_line():
    from fake_plugins import Entry

    from haven_sim.common import plugins

    class Hangs(Entry):
        def load(self):
            sleeps()

    with contain.use(contain.PluginDeadlines(plugin_deadline_load_s=0.2)):
        reg = plugins.load("missions", [Hangs("stuck", "lab.m:Stuck", "lab_m")])
    assert reg.names() == []
    assert reg.problems == [
        "haven.missions stuck (lab.m:Stuck, from lab_m): does not load: took longer than its deadline of 0.2 s"
    ]
