"""HuNavSim's evaluator metrics, computed as its source computes them: the `hunav_*` columns.

Source: robotics-upo/hunav_sim, commit afa974340901e244ce15a97e8ebc37c0699a3e6f,
hunav_evaluator/hunav_evaluator/hunav_metrics.py (each function below is named after the one it
follows) and hunav_evaluator_node.py (how samples are taken). Every quirk of the published code is
kept, because a column named after HuNavSim must give HuNavSim's number:

* distances are between surfaces (centre distance minus both radii) clamped at 0, except the
  maximum distance, which subtracts the robot's radius only;
* `avg_closest_person` divides by all samples, including any without a person;
* intrusions are % of samples whose closest clamped distance is in [0, 0.45), [0.45, 1.2), [1.2, 3.6);
* collisions are counted per sample (not per episode) and attributed by its angle/velocity rule,
  `alpha2 = atan2(nrx, nry)` (arguments as published);
* `time_not_moving` tests `r.linear_vel < 0.01 and abs(r.angular_vel < 0.02)`: the parenthesis
  takes abs() of the comparison, so the signed velocities are compared (turning clockwise in place,
  or reversing, counts as not moving). We follow the code as published, not the evident intent
  (our `robot_time_not_moving_s` is the |v|, |w| version);
* accelerations divide by all samples, N, though there are N - 1 differences; "overacceleration"
  is |dv/dt| / dt per sample, not a jerk.

Sampling: hunav_evaluator either keeps every message (`frequency` 0, its default) or, at
`frequency`, holds the newest robot and agents messages and appends them on a timer. We do the
latter at SAMPLE_HZ on the trial's own clock, from trial_start to the last tick at or before
trial_end, each sample stamped with its tick (HuNavSim stamps it with the held agents message,
which is at most one /humans period older). A person's `linear_vel` (HuNavSim's simulator
publishes it) is the held message's distance from the previous /humans message over their time.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from haven_scenarios.record.metric_table import HUNAV_METRICS, ZONES
from haven_scenarios.record.timeline import Recording
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import FloatArray
from haven_sim.robots.fields import DEFAULT

if TYPE_CHECKING:
    from haven_scenarios.record.metric_kind import TrialData

# 20 Hz: the rate /humans is published at by default, so a sample holds a fresh person pose (and
# the 50 Hz /odom); fixed, because per-sample counts (collisions) scale with the rate and /humans
# runs at 50 Hz under --web.
SAMPLE_HZ = 20.0
COLLISION_M = 0.02  # hunav_metrics.collisions: surface distance below this is a collision
STILL_MPS, STILL_RPS = 0.01, 0.02  # hunav_metrics.time_not_moving (signed, as published)
FAR_M = 10000.0  # hunav_metrics' "no person" closest distance (min_dist = 10000)
NAMES = tuple(row[0] for row in HUNAV_METRICS)


@dataclass(frozen=True)
class Samples:
    """HuNavSim's two lists, robot and agents, as arrays (one row per sample)."""

    t: FloatArray  # (N,) sample stamps, s since trial_start
    robot: FloatArray  # (N, 5): x, y, yaw, linear_vel, angular_vel (the held /odom)
    people: dict[str, FloatArray]  # id -> (N, 4): x, y, yaw, linear_vel; NaN where the person is absent
    robot_radius_m: float = DEFAULT.radius_m
    person_radius_m: float = HUMAN_BODY.radius_m


def _held(stamps: FloatArray, ticks: FloatArray) -> Any:
    """Index of the newest stamp at or before each tick (-1: none yet)."""
    return np.searchsorted(stamps, ticks + 1e-9, side="right") - 1


def sample(rec: Recording, t0: float, t1: float, rate_hz: float = SAMPLE_HZ) -> Samples:
    """Ticks t0, t0 + 1/rate_hz, ... <= t1, each holding the newest /odom and /humans at or before
    it; ticks before either topic's first message are not samples (HuNavSim waits for both)."""
    odom = sorted(rec.odom, key=lambda s: s[0])
    humans = sorted(rec.humans, key=lambda s: s[0])
    ticks = t0 + np.arange(math.floor((t1 - t0) * rate_hz + 1e-9) + 1) / rate_hz
    ots, hts = np.array([s for s, _ in odom]), np.array([s for s, _ in humans])
    oi, hi = _held(ots, ticks), _held(hts, ticks)
    keep = (oi >= 0) & (hi >= 0)
    ticks, oi, hi = ticks[keep], oi[keep], hi[keep]
    robot = np.array([(st.pose.x, st.pose.y, st.pose.yaw, st.twist.vx, st.twist.wz) for _, st in odom]).reshape(-1, 5)[
        oi
    ]
    people: dict[str, FloatArray] = {}
    for hid in dict.fromkeys(h for _, poses in humans for h in poses):
        track = np.full((len(humans), 4), math.nan)
        last: tuple[float, float, float] | None = None
        for k, (stamp, poses) in enumerate(humans):
            p = poses.get(hid)
            if p is None:
                continue
            speed = (
                math.hypot(p.x - last[1], p.y - last[2]) / (stamp - last[0])
                if last is not None and stamp > last[0]
                else 0.0
            )
            track[k] = (p.x, p.y, p.yaw, speed)
            last = (stamp, p.x, p.y)
        people[hid] = track[hi]
    return Samples(ticks - t0, robot, people)


def _centre(s: Samples) -> FloatArray:
    """(N, people) centre distances, NaN where a person is absent."""
    if not s.people:
        return np.zeros((len(s.t), 0))
    return np.column_stack([np.hypot(p[:, 0] - s.robot[:, 0], p[:, 1] - s.robot[:, 1]) for p in s.people.values()])


def _closest(s: Samples) -> FloatArray:
    """Per sample, the closest person's surface distance clamped at 0 (FAR_M with nobody there)."""
    surface = _centre(s) - s.robot_radius_m - s.person_radius_m
    present = ~np.isnan(surface)
    out = np.full(len(s.t), FAR_M)
    some = present.any(axis=1)
    if some.any():
        out[some] = np.maximum(np.nanmin(surface[some], axis=1), 0.0)
    return out


def total_time(s: Samples) -> float:
    return float(s.t[-1] - s.t[0])


def robot_path_length(s: Samples) -> float:
    return float(np.sum(np.hypot(*np.diff(s.robot[:, :2], axis=0).T)))


def normalize_angle(a: float) -> float:
    """Into (-pi, pi], as hunav_metrics.normalize_angle."""
    return a - 2.0 * math.pi * math.ceil((a - math.pi) / (2.0 * math.pi))


def cumulative_heading_changes(s: Samples) -> float:
    yaw = s.robot[:, 2]
    return float(sum(abs(normalize_angle(float(a - b))) for a, b in itertools.pairwise(yaw)))


def avg_closest_person(s: Samples) -> float | None:
    closest = _closest(s)
    return float(np.sum(closest[closest < FAR_M]) / len(s.t)) if s.people else None


def minimum_distance_to_people(s: Samples) -> float | None:
    surface = _centre(s) - s.robot_radius_m - s.person_radius_m
    return float(np.nanmin(np.maximum(surface, 0.0))) if surface.size and not np.all(np.isnan(surface)) else None


def maximum_distance_to_people(s: Samples) -> float | None:
    centre = _centre(s)
    return float(np.nanmax(centre) - s.robot_radius_m) if centre.size and not np.all(np.isnan(centre)) else None


def space_intrusions(s: Samples, lo: float, hi: float) -> float:
    """% of samples whose closest clamped surface distance is in [lo, hi)."""
    closest = _closest(s)
    return 100.0 * float(np.sum((closest >= lo) & (closest < hi))) / len(s.t)


def collisions(s: Samples) -> tuple[int, int]:
    """(robot on person, person on robot), counted per sample and person as published."""
    robot_on, person_on = 0, 0
    surface = _centre(s) - s.robot_radius_m - s.person_radius_m
    for j, p in enumerate(s.people.values()):
        for i in np.flatnonzero(surface[:, j] < COLLISION_M):
            rx, ry, ryaw, rv = s.robot[i, :4]
            ax, ay, ayaw, av = p[i]
            alpha = math.atan2(
                -(rx - ax) * math.sin(ayaw) + (ry - ay) * math.cos(ayaw),
                (rx - ax) * math.cos(ayaw) + (ry - ay) * math.sin(ayaw),
            )
            nrx = (ax - rx) * math.cos(ryaw) + (ay - ry) * math.sin(ryaw)
            nry = -(ax - rx) * math.sin(ryaw) + (ay - ry) * math.cos(ryaw)
            alpha2 = math.atan2(nrx, nry)  # (sic: hunav_metrics.collisions)
            a, a2 = abs(alpha), abs(alpha2)
            # Its five branches, merged: the angles decide whenever the speeds differ; a tie in both
            # counts for each; any other tie counts for neither.
            if a < a2 and rv != av:
                robot_on += 1
            elif a > a2 and rv != av:
                person_on += 1
            elif a == a2 and rv == av:
                robot_on, person_on = robot_on + 1, person_on + 1
    return robot_on, person_on


def time_not_moving(s: Samples) -> float:
    still = (s.robot[:, 3] < STILL_MPS) & (s.robot[:, 4] < STILL_RPS)  # (signed: see the module docstring)
    return total_time(s) / len(s.t) * float(np.sum(still))


def avg_robot_linear_speed(s: Samples) -> float:
    return float(np.mean(s.robot[:, 3]))


def avg_robot_angular_speed(s: Samples) -> float:
    return float(np.mean(np.abs(s.robot[:, 4])))


def _accelerations(s: Samples) -> tuple[FloatArray, FloatArray]:
    dv, dt = np.diff(s.robot[:, 3]), np.diff(s.t)
    ok = dt != 0.0
    return dv[ok] / dt[ok], dt[ok]


def avg_acceleration(s: Samples) -> float:
    accel, _ = _accelerations(s)
    return float(np.sum(np.abs(accel)) / len(s.t))


def avg_overacceleration(s: Samples) -> float:
    accel, dt = _accelerations(s)
    return float(np.sum(np.abs(accel / dt)) / len(s.t))


def avg_pedestrian_velocity(s: Samples) -> float | None:
    """Sum of every present person's speed over all samples / (samples x people in the first sample)."""
    if not s.people:
        return None
    speeds = np.column_stack([p[:, 3] for p in s.people.values()])
    first = int(np.sum(~np.isnan(speeds[0])))
    return float(np.nansum(speeds) / (len(s.t) * first)) if first else None


def _r(x: float | None, digits: int = 4) -> float | None:
    return None if x is None or not math.isfinite(x) else round(float(x), digits)


def columns(s: Samples) -> dict[str, Any]:
    """The hunav_* columns of one trial's samples (metric_table has their definitions)."""
    if len(s.t) == 0:
        return {name: None for name in NAMES}
    (_, intimate), (_, personal), (_, social) = ZONES.items()
    robot_on, person_on = collisions(s)
    return {
        "hunav_time_to_reach_goal_s": _r(total_time(s)),
        "hunav_path_length_m": _r(robot_path_length(s)),
        "hunav_cumulative_heading_changes_rad": _r(cumulative_heading_changes(s)),
        "hunav_avg_distance_to_closest_person_m": _r(avg_closest_person(s)),
        "hunav_minimum_distance_to_people_m": _r(minimum_distance_to_people(s)),
        "hunav_maximum_distance_to_people_m": _r(maximum_distance_to_people(s)),
        "hunav_intimate_space_intrusions_pct": _r(space_intrusions(s, 0.0, intimate)),
        "hunav_personal_space_intrusions_pct": _r(space_intrusions(s, intimate, personal)),
        "hunav_social_space_intrusions_pct": _r(space_intrusions(s, personal, social)),
        "hunav_robot_on_person_collisions": robot_on,
        "hunav_person_on_robot_collisions": person_on,
        "hunav_time_not_moving_s": _r(time_not_moving(s)),
        "hunav_avg_robot_linear_speed_mps": _r(avg_robot_linear_speed(s)),
        "hunav_avg_robot_angular_speed_rps": _r(avg_robot_angular_speed(s)),
        "hunav_avg_acceleration_mps2": _r(avg_acceleration(s)),
        "hunav_avg_overacceleration": _r(avg_overacceleration(s)),
        "hunav_avg_pedestrian_velocity_mps": _r(avg_pedestrian_velocity(s)),
    }


def hunav(d: TrialData) -> dict[str, Any]:
    """The `hunav` metrics plugin: HuNavSim's evaluator on the trial's samples."""
    return columns(replace(sample(d.rec, d.t0, d.t1), robot_radius_m=d.robot.radius_m))
