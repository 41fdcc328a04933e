"""An independent scorer for session bags: reads the MCAP with the mcap library and deserialises
with the rosbags typestore, uses nothing of HAVEN's reading or metrics code, and computes a few
metrics its own way (header stamps, linear interpolation onto a 0.01 s grid over
[trial_start, trial_end]), so tests can hold metrics.json against it."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from mcap.reader import make_reader
from rosbags.typesys import Stores, get_typestore

STORE = get_typestore(Stores.ROS2_JAZZY)
GRID = 0.01


def _stamp(header) -> float:
    return header.stamp.sec + header.stamp.nanosec * 1e-9


@dataclass
class Score:
    duration_s: float
    robot_path_length_m: float
    human_path_length_m: dict[int, float]
    min_human_centre_distance_m: float
    odom_coverage: float  # recorded / expected (one per 0.02 s step) within the trial
    humans_coverage: float  # recorded / expected (20 Hz)
    odom_max_gap_s: float
    humans_max_gap_s: float


def score(bag: Path) -> Score:
    odom: list[tuple[float, float, float]] = []
    humans: list[tuple[float, list[tuple[float, float]]]] = []
    events: list[dict] = []
    with open(next(bag.glob("*.mcap")), "rb") as f:
        for schema, channel, message in make_reader(f).iter_messages(topics=["/odom", "/humans", "/haven/events"]):
            msg = STORE.deserialize_cdr(message.data, schema.name)
            if channel.topic == "/odom":
                odom.append((_stamp(msg.header), msg.pose.pose.position.x, msg.pose.pose.position.y))
            elif channel.topic == "/humans":
                humans.append((_stamp(msg.header), [(p.position.x, p.position.y) for p in msg.poses]))
            else:
                events.append(json.loads(msg.data))
    start = next(e["stamp"] for e in events if e["type"] == "trial_start")
    end = next(e["stamp"] for e in events if e["type"] == "trial_end")
    grid = np.arange(start, end + 1e-9, GRID)
    o = np.array(sorted(odom))
    robot = np.column_stack([np.interp(grid, o[:, 0], o[:, 1]), np.interp(grid, o[:, 0], o[:, 2])])
    humans.sort(key=lambda h: h[0])
    ht = np.array([t for t, _ in humans])
    people = {
        i: np.column_stack(
            [np.interp(grid, ht, [p[i][0] for _, p in humans]), np.interp(grid, ht, [p[i][1] for _, p in humans])]
        )
        for i in range(len(humans[0][1]))
    }

    def length(xy: np.ndarray) -> float:
        return float(np.sum(np.hypot(*np.diff(xy, axis=0).T)))

    def coverage(stamps: np.ndarray, period: float) -> tuple[float, float]:
        inside = np.sort(stamps[(stamps >= start - 1e-6) & (stamps <= end + 1e-6)])
        expected = (end - start) / period + 1
        return len(inside) / expected, float(np.max(np.diff(inside)))

    odom_cov, odom_gap = coverage(o[:, 0], 0.02)
    humans_cov, humans_gap = coverage(ht, 0.05)
    return Score(
        duration_s=end - start,
        robot_path_length_m=length(robot),
        human_path_length_m={i: length(xy) for i, xy in people.items()},
        min_human_centre_distance_m=float(min(np.min(np.hypot(*(xy - robot).T)) for xy in people.values())),
        odom_coverage=odom_cov,
        humans_coverage=humans_cov,
        odom_max_gap_s=odom_gap,
        humans_max_gap_s=humans_gap,
    )
