"""A trial as samples and events (`TrialLog`), built the same way from a bag and from batch mode.

`LogBuilder` takes the messages of a trial (core payloads: /odom, /humans, /battery_state,
/haven/cue_state, /haven/events) in stamp order and samples the state at a fixed rate of sim time,
so a recording read back and a batch trial yield the same kind of log for the metrics.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from haven_sim.common import topics
from haven_sim.common.events import Event
from haven_sim.runtime.component import Message
from haven_viz.cues import CueState

RobotSample = tuple[float, float, float, float]  # x, y, yaw, angular velocity


@dataclass
class TrialLog:
    """Samples at a fixed rate plus the event list."""

    t: list[float] = field(default_factory=list)
    robot: list[RobotSample] = field(default_factory=list)
    humans: dict[str, list[tuple[float, float]]] = field(default_factory=dict)
    battery: list[float] = field(default_factory=list)
    bubble: list[bool] = field(default_factory=list)
    signal: list[int] = field(default_factory=list)  # +1 left, -1 right, 0 off
    events: list[Event] = field(default_factory=list)

    def sample(self, t: float, robot: RobotSample, humans: Mapping[str, tuple[float, float]], battery: float, bubble: bool, signal: int) -> None:
        self.t.append(t)
        self.robot.append(robot)
        for hid, xy in humans.items():
            self.humans.setdefault(hid, []).append(xy)
        self.battery.append(battery)
        self.bubble.append(bubble)
        self.signal.append(signal)


class LogBuilder:
    def __init__(self, rate_hz: float = 10.0) -> None:
        self.log = TrialLog()
        self.step_s = 1.0 / rate_hz
        self._next: float | None = None
        self._robot: RobotSample | None = None
        self._humans: dict[str, tuple[float, float]] = {}
        self._battery = 1.0
        self._cues = CueState()

    def add(self, m: Message) -> None:
        if m.topic == topics.EVENTS:
            self.log.events.append(m.data)
            return
        if self._next is not None and self._robot is not None:
            while m.stamp >= self._next - 1e-9:
                self.log.sample(self._next, self._robot, dict(self._humans), self._battery, bool(self._cues.thought), self._cues.turn_signal)
                self._next += self.step_s
        if m.topic == topics.ODOM:
            p, tw = m.data.pose, m.data.twist
            self._robot = (p.x, p.y, p.yaw, tw.wz)
            if self._next is None:
                self._next = (int(m.stamp / self.step_s + 1e-9) + 1) * self.step_s
        elif m.topic == topics.HUMANS:
            self._humans = {hid: (p.x, p.y) for hid, p in m.data.items()}
        elif m.topic == topics.BATTERY:
            self._battery = float(m.data.level)
        elif m.topic == topics.CUE_STATE:
            self._cues = m.data
