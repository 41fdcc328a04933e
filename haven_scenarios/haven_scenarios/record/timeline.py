"""A trial's streams and their common time grid: what every metric is computed on.

`Recording` collects the messages a recording holds (or batch mode's in-process messages), each
with its header stamp (sim time, not the time a recorder happened to receive it). `Timeline` puts
the robot and every person on one uniform grid over exactly [trial_start, trial_end], interpolating
linearly between samples, and the cue state as the step function it is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from haven_scenarios.record.outsiders import PublisherLog
from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.events import Event, EventKind
from haven_sim.common.geometry import FloatArray, Pose2D
from haven_sim.common.state import Goal, HumanPoses, RobotState
from haven_viz.cues import CueState, Toggles

GRID_S = 0.02  # the physics step: /odom comes every step
# The topics a recording holds for the metrics and the validity checks (read from a bag, or observed
# in batch mode).
RECORDED = (topics.ODOM, topics.HUMANS, topics.BATTERY, topics.CUE_STATE, topics.PLAN, topics.EVENTS, topics.GOAL)


@dataclass
class Recording:
    odom: list[tuple[float, RobotState]] = field(default_factory=list)
    humans: list[tuple[float, HumanPoses]] = field(default_factory=list)
    battery: list[tuple[float, float]] = field(default_factory=list)
    cues: list[tuple[float, CueState]] = field(default_factory=list)
    plans: list[tuple[float, list[Pose2D]]] = field(default_factory=list)
    goals: list[tuple[float, Goal]] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    lost: dict[str, int] = field(default_factory=dict)  # topic -> messages the recorder reported lost
    publishers: PublisherLog | None = None  # who published what, as the recorder saw it (None: not kept)

    def add(self, m: Message) -> None:
        """One message, stamped with its header stamp."""
        if m.topic == topics.ODOM:
            self.odom.append((m.stamp, m.data))
        elif m.topic == topics.HUMANS:
            self.humans.append((m.stamp, m.data))
        elif m.topic == topics.BATTERY:
            self.battery.append((m.stamp, float(m.data.level)))
        elif m.topic == topics.CUE_STATE:
            self.cues.append((m.stamp, m.data))
        elif m.topic == topics.PLAN:
            self.plans.append((m.stamp, list(m.data)))
        elif m.topic == topics.EVENTS:
            self.events.append(m.data)
        elif m.topic == topics.GOAL:
            self.goals.append((m.stamp, m.data))

    def first(self, kind: EventKind, **match: object) -> Event | None:
        for e in sorted(self.events, key=lambda e: e.stamp):
            if e.kind is kind and all(e.get(k) == v for k, v in match.items()):
                return e
        return None

    def window(self) -> tuple[float, float] | None:
        """[trial_start, trial_end]; the end of the robot's data when the trial never ended."""
        start = self.first(EventKind.TRIAL_START)
        if start is None or not self.odom:
            return None
        end = self.first(EventKind.TRIAL_END)
        return start.stamp, (end.stamp if end is not None else max(t for t, _ in self.odom))


def _interp(t: FloatArray, ts: FloatArray, values: FloatArray) -> FloatArray:
    return np.interp(t, ts, values) if len(ts) else np.full(len(t), math.nan)


@dataclass
class Timeline:
    """Everything on one grid `t` (seconds since trial_start)."""

    t: FloatArray
    robot_xy: FloatArray  # (N, 2)
    robot_yaw: FloatArray  # unwrapped
    robot_v: FloatArray  # forward speed, from /odom's twist
    robot_w: FloatArray
    humans: dict[str, FloatArray]  # id -> (N, 2)
    battery: FloatArray
    cues: list[CueState]  # the state shown at each grid time

    @staticmethod
    def of(rec: Recording, start: float, end: float, step: float = GRID_S) -> Timeline:
        n = max(1, math.floor((end - start) / step + 1e-9) + 1)
        grid: FloatArray = start + step * np.arange(n, dtype=float)
        if grid[-1] < end - 1e-9:
            grid = np.append(grid, end)
        odom = sorted(rec.odom, key=lambda s: s[0])
        ts = np.array([s for s, _ in odom])
        pose = np.array([(st.pose.x, st.pose.y, st.pose.yaw, st.twist.vx, st.twist.wz) for _, st in odom]).reshape(
            -1, 5
        )
        yaw = np.unwrap(pose[:, 2]) if len(pose) else pose[:, 2]
        humans: dict[str, FloatArray] = {}
        samples = sorted(rec.humans, key=lambda s: s[0])
        for hid in dict.fromkeys(h for _, poses in samples for h in poses):
            hs = [(s, poses[hid]) for s, poses in samples if hid in poses]
            hts = np.array([s for s, _ in hs])
            humans[hid] = np.column_stack(
                [_interp(grid, hts, np.array([p.x for _, p in hs])), _interp(grid, hts, np.array([p.y for _, p in hs]))]
            )
        bts = sorted(rec.battery)
        battery = _interp(grid, np.array([s for s, _ in bts]), np.array([v for _, v in bts]))
        return Timeline(
            t=grid - start,
            robot_xy=np.column_stack([_interp(grid, ts, pose[:, 0]), _interp(grid, ts, pose[:, 1])]),
            robot_yaw=_interp(grid, ts, yaw),
            robot_v=_interp(grid, ts, pose[:, 3]),
            robot_w=_interp(grid, ts, pose[:, 4]),
            humans=humans,
            battery=battery,
            cues=_steps(grid, sorted(rec.cues, key=lambda s: s[0])),
        )

    @property
    def dt(self) -> FloatArray:
        """The time each grid point stands for (to the next one; 0 for the last)."""
        return np.diff(self.t, append=self.t[-1]) if len(self.t) else np.zeros(0)


def _steps(grid: FloatArray, cues: list[tuple[float, CueState]]) -> list[CueState]:
    """The cue state in force at each grid time (nothing shown before the first one)."""
    if not cues:
        return [CueState(Toggles.none())] * len(grid)
    stamps = np.array([s for s, _ in cues])
    index = np.searchsorted(stamps, grid + 1e-9, side="right") - 1
    blank = CueState(cues[0][1].toggles)
    return [cues[i][1] if i >= 0 else blank for i in index]
