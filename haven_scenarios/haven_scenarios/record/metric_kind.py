"""What a metric is: the plugin kind `haven.metrics` (a function of a trial's data giving its
columns), and a trial's metrics computed from every registered one, HAVEN's first."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any, Protocol, cast

from haven_scenarios.record.outsiders import Declared
from haven_scenarios.record.timeline import Recording, Timeline
from haven_scenarios.record.validity import check
from haven_sim.common import contain, plugins
from haven_sim.common.events import Event
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.fields import DEFAULT
from haven_sim.sim.world import World


def rounded(x: float | None, digits: int = 3) -> float | None:
    """`x` to `digits` places; None for a value that is missing or not finite (JSON has no NaN)."""
    return None if x is None or not math.isfinite(x) else round(float(x), digits)


@dataclass(frozen=True)
class TrialData:
    """What a metric reads: the trial on one time grid (`tl`, seconds since trial_start), its
    events (stamps from trial_start too), the recording itself (header stamps), and the world."""

    tl: Timeline
    events: Sequence[Event]
    rec: Recording
    t0: float  # trial_start and trial_end, in the recording's stamps
    t1: float
    world: World | None
    robot: RobotDescription = DEFAULT  # the robot of the trial (its footprint for distances and contacts)


# The groups HAVEN ships (`hunav`: HuNavSim's evaluator), in metrics.json's order; each registered
# as a plugin of kind `metrics` (pyproject.toml), as a lab's own metric is: a function of TrialData giving
# its columns. A lab's follow in name order.
OURS = ("robot", "navigation", "proximity", "contacts", "mission", "cues", "passes", "people", "hunav")


class Metric(Protocol):
    """A `haven.metrics` plugin: a function of the trial's data giving its columns."""

    def __call__(self, data: TrialData) -> Mapping[str, Any]: ...


Column = tuple[str, str, str, str]  # a documented column: name, unit, definition, source


@dataclass(frozen=True)
class MetricSpec:
    """A registered metric: its function and the columns it documents for the codebook."""

    compute: Metric
    columns: tuple[Column, ...] = ()


def accept_plugin(name: str, value: Any) -> MetricSpec:
    """A `haven.metrics` plugin (haven_sim/common/plugins.py): a function of TrialData returning a
    mapping of column -> value; its `columns` attribute, if any, documents them in the codebook as
    (name, unit, definition, source) rows."""
    if not callable(value):
        raise ValueError("is not a metric: a function taking TrialData and returning {column: value}")
    columns = getattr(value, "columns", ())
    if not all(isinstance(c, tuple) and len(c) == 4 and all(isinstance(x, str) for x in c) for c in columns):
        raise ValueError("columns: must be (name, unit, definition, source) rows of text")
    return MetricSpec(cast(Metric, value), tuple(columns))


def compute(
    rec: Recording,
    scenario: str = "",
    end_reason: str = "",
    world: World | None = None,
    declared: Declared | None = None,
    robot: RobotDescription = DEFAULT,
) -> dict[str, Any]:
    """`declared`: what a recorded run said of itself, for its validity (record/validity.py)."""
    window = rec.window()
    m: dict[str, Any] = {"scenario": scenario, "end_reason": end_reason}
    if window is None:
        return {**m, "duration_s": None, **check(rec, None, declared)}
    t0, t1 = window
    tl = Timeline.of(rec, t0, t1)
    events = sorted(
        (replace(e, stamp=e.stamp - t0) for e in rec.events if t0 - 1e-9 <= e.stamp <= t1 + 1e-9), key=lambda e: e.stamp
    )
    m["duration_s"], data = rounded(t1 - t0, 2), TrialData(tl, events, rec, t0, t1, world, robot)
    failed: list[str] = []
    registered = plugins.registry("metrics")
    for name in (*OURS, *(n for n in registered.names() if n not in OURS)):
        m.update(_one(name, registered.get(name).compute, data, m, failed))
    m.update(check(rec, window, declared))
    # (as for any plugin that failed)
    m.update(valid=m["valid"] and not failed, invalid_reasons=[*m["invalid_reasons"], *failed])
    return m


def _one(name: str, metric: Metric, data: TrialData, have: Mapping[str, Any], failed: list[str]) -> dict[str, Any]:
    """One metric plugin's columns, called as every plugin is (common/contain.py); one that fails (its
    reason in `failed`) or would overwrite a column gets a `<name>_error` column instead: the others stand."""
    try:
        got = dict(contain.call("metrics", name, metric, data))
    except contain.PluginFailed as e:
        failed.append(e.reason)
        return {f"{name}_error": e.error}
    taken = sorted(k for k in got if k in have)
    return {f"{name}_error": f"would overwrite {', '.join(taken[:3])}"} if taken else got
