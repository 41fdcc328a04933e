"""Robot contacts as episodes, with who ran into whom.

The simulator reports every touch that begins and ends (`contact_begin` / `contact_end`); bodies
that graze each other flicker between the two. An episode is a run of touches with the same body
separated by less than `DEBOUNCE_S`. For a person, the episode is attributed by our own rule (SEAN
2.0 and the HuNavSim evaluator also separate robot-on-person from person-on-robot collisions, by
other rules; HuNavSim's, per sample, is in record/hunav.py): at its first touch, the robot's speed
toward the person is compared with the person's speed toward the robot (velocities along the line
between their centres); the faster closer ran into the other.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from haven_scenarios.record.timeline import Timeline
from haven_sim.common.events import Event, EventKind

DEBOUNCE_S = 0.5
ROBOT_ON_PERSON, PERSON_ON_ROBOT = "robot_on_person", "person_on_robot"


@dataclass(frozen=True)
class Episode:
    other: str  # "wall" or "human:<id>"
    start: float  # seconds since trial_start
    end: float
    by: str = ""  # who ran into whom, for a person


def episodes(events: Sequence[Event], t0: float, t1: float) -> list[Episode]:
    """Debounced contact episodes within [t0, t1] (times relative to t0)."""
    touches: dict[str, list[list[float]]] = {}
    open_: dict[str, float] = {}
    for e in sorted(events, key=lambda e: e.stamp):
        if e.kind is EventKind.CONTACT_BEGIN:
            open_.setdefault(e["other"], e.stamp)
        elif e.kind is EventKind.CONTACT_END and e["other"] in open_:
            touches.setdefault(e["other"], []).append([open_.pop(e["other"]), e.stamp])
    for other, since in open_.items():
        touches.setdefault(other, []).append([since, t1])
    out = []
    for other, spans in touches.items():
        merged: list[list[float]] = []
        for a, b in sorted(spans):
            if merged and a - merged[-1][1] < DEBOUNCE_S:
                merged[-1][1] = max(merged[-1][1], b)
            else:
                merged.append([a, b])
        out += [Episode(other, a - t0, min(b, t1) - t0) for a, b in merged if t0 - 1e-9 <= a <= t1 + 1e-9]
    return sorted(out, key=lambda e: e.start)


def attribute(ep: Episode, tl: Timeline) -> Episode:
    """Who closed in faster at the first touch (robot-on-person on a tie)."""
    hid = ep.other.split(":", 1)[1] if ep.other.startswith("human:") else None
    if hid is None or hid not in tl.humans or len(tl.t) < 2:
        return ep
    i = min(int(np.searchsorted(tl.t, ep.start)), len(tl.t) - 1)
    j = max(i - 1, 0)
    robot, person = tl.robot_xy[i], tl.humans[hid][i]
    gap = person - robot
    norm = float(np.hypot(*gap))
    if norm < 1e-9:
        return Episode(ep.other, ep.start, ep.end, ROBOT_ON_PERSON)
    u = gap / norm
    yaw = tl.robot_yaw[i]
    robot_toward = float(tl.robot_v[i] * (np.cos(yaw) * u[0] + np.sin(yaw) * u[1]))
    dt = max(tl.t[i] - tl.t[j], 1e-9)
    person_velocity = (tl.humans[hid][i] - tl.humans[hid][j]) / dt if i > j else np.zeros(2)
    person_toward = float(-(person_velocity @ u))
    return Episode(ep.other, ep.start, ep.end, ROBOT_ON_PERSON if robot_toward >= person_toward else PERSON_ON_ROBOT)
