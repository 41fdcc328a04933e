"""HuNavSim's evaluator re-implemented from its source for tests, on a session bag: shares no code
with record/hunav.py, record/bag.py or our Timeline.

Source: robotics-upo/hunav_sim, commit afa974340901e244ce15a97e8ebc37c0699a3e6f,
hunav_evaluator/hunav_evaluator/hunav_metrics.py: total_time, robot_path_length,
cumulative_heading_changes, normalize_angle, avg_closest_person, minimum_distance_to_people,
maximum_distance_to_people, space_intrusions / indicator_function, collisions, time_not_moving,
avg_robot_linear_speed, avg_robot_angular_speed, avg_acceleration, avg_overacceleration,
avg_pedestrian_velocity; each below keeps its loop shape. Sampling as hunav_evaluator_node.py does
with `frequency` set (timer_record_callback appends the newest robot and agents messages), at the
codebook's stated 20 Hz from trial_start. The bag is read with the mcap library and deserialised
with the rosbags typestore.
"""

from __future__ import annotations

import json
import math
from bisect import bisect_right
from pathlib import Path

from mcap.reader import make_reader
from rosbags.typesys import Stores, get_typestore

STORE = get_typestore(Stores.ROS2_JAZZY)
RATE_HZ = 20.0  # the codebook's stated sampling rate
ROBOT_RADIUS, AGENT_RADIUS = 0.177, 0.25  # TurtleBot2 (Kobuki) and a person, haven_sim/common/bodies.py


def _stamp(header) -> float:
    return header.stamp.sec + header.stamp.nanosec * 1e-9


def _yaw(q) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def read(bag: Path) -> tuple[list[float], list[dict], list[list[dict]]]:
    """(stamps, robot, agents): HuNavSim's lists, one entry per 20 Hz tick in [trial_start, trial_end]."""
    odom, humans, events = [], [], []
    with open(next(bag.glob("*.mcap")), "rb") as f:
        for schema, channel, message in make_reader(f).iter_messages(topics=["/odom", "/humans", "/haven/events"]):
            msg = STORE.deserialize_cdr(message.data, schema.name)
            if channel.topic == "/odom":
                p, v = msg.pose.pose, msg.twist.twist
                robot_msg = {
                    "x": p.position.x,
                    "y": p.position.y,
                    "yaw": _yaw(p.orientation),
                    "lin": v.linear.x,
                    "ang": v.angular.z,
                }
                odom.append((_stamp(msg.header), robot_msg))
            elif channel.topic == "/humans":
                humans.append(
                    (_stamp(msg.header), [(p.position.x, p.position.y, _yaw(p.orientation)) for p in msg.poses])
                )
            else:
                events.append(json.loads(msg.data))
    start = next(e["stamp"] for e in events if e["type"] == "trial_start")
    end = next(e["stamp"] for e in events if e["type"] == "trial_end")
    odom.sort(key=lambda m: m[0])
    humans.sort(key=lambda m: m[0])
    agents_msgs = []  # each person's linear_vel: distance from the previous /humans message over its time
    for k, (t, poses) in enumerate(humans):
        prev = humans[k - 1] if k else None
        agents_msgs.append(
            [
                {
                    "x": x,
                    "y": y,
                    "yaw": yaw,
                    "lin": math.hypot(x - prev[1][i][0], y - prev[1][i][1]) / (t - prev[0])
                    if prev and t > prev[0]
                    else 0.0,
                }
                for i, (x, y, yaw) in enumerate(poses)
            ]
        )
    ots, hts = [t for t, _ in odom], [t for t, _ in humans]
    stamps, robot, agents = [], [], []
    k = 0
    while start + k / RATE_HZ <= end + 1e-9:
        tick = start + k / RATE_HZ
        i, j = bisect_right(ots, tick + 1e-9) - 1, bisect_right(hts, tick + 1e-9) - 1
        if i >= 0 and j >= 0:
            stamps.append(tick)
            robot.append(odom[i][1])
            agents.append(agents_msgs[j])
        k += 1
    return stamps, robot, agents


def _dist(a: dict, b: dict) -> float:
    return math.sqrt((a["x"] - b["x"]) ** 2 + (a["y"] - b["y"]) ** 2)


def normalize_angle(ang: float) -> float:
    while ang <= -math.pi:
        ang += 2 * math.pi
    while ang > math.pi:
        ang -= 2 * math.pi
    return ang


def _closest(robot: list[dict], agents: list[list[dict]], i: int) -> float:
    min_dist = 10000.0
    for agent in agents[i]:
        d = _dist(robot[i], agent) - ROBOT_RADIUS - AGENT_RADIUS
        if d < min_dist:
            min_dist = d
            if min_dist < 0.0:
                min_dist = 0.0
    return min_dist


def _indicator(norm: float, k: str) -> int:
    if k == "intimate":
        return 1 if norm < 0.45 else 0
    if k == "personal":
        return 1 if 0.45 <= norm < 1.2 else 0
    if k == "social":
        return 1 if 1.2 <= norm < 3.6 else 0
    return 0


def metrics(bag: Path) -> dict[str, float]:
    """The hunav_* columns, named as record/hunav.py names them."""
    stamps, robot, agents = read(bag)
    n = len(robot)
    total = stamps[-1] - stamps[0]
    path = sum(_dist(robot[i + 1], robot[i]) for i in range(n - 1))
    chc = 0.0
    for i in range(n - 1):
        chc += abs(normalize_angle(robot[i]["yaw"] - robot[i + 1]["yaw"]))
    avg = 0.0
    for i in range(n):
        if agents[i]:
            avg += _closest(robot, agents, i)
    minimum = min(max(_dist(robot[i], a) - ROBOT_RADIUS - AGENT_RADIUS, 0.0) for i in range(n) for a in agents[i])
    maximum = max(_dist(robot[i], a) - ROBOT_RADIUS for i in range(n) for a in agents[i])
    zones = {
        k: 100.0 * sum(_indicator(_closest(robot, agents, i), k) for i in range(n)) / n
        for k in ("intimate", "personal", "social")
    }
    robot_coll = person_coll = 0
    for i in range(n):
        r = robot[i]
        for a in agents[i]:
            if _dist(r, a) - ROBOT_RADIUS - AGENT_RADIUS < 0.02:
                nrx = (r["x"] - a["x"]) * math.cos(a["yaw"]) + (r["y"] - a["y"]) * math.sin(a["yaw"])
                nry = -(r["x"] - a["x"]) * math.sin(a["yaw"]) + (r["y"] - a["y"]) * math.cos(a["yaw"])
                alpha = math.atan2(nry, nrx)
                nrx = (a["x"] - r["x"]) * math.cos(r["yaw"]) + (a["y"] - r["y"]) * math.sin(r["yaw"])
                nry = -(a["x"] - r["x"]) * math.sin(r["yaw"]) + (a["y"] - r["y"]) * math.cos(r["yaw"])
                alpha2 = math.atan2(nrx, nry)
                if abs(alpha) < abs(alpha2) and r["lin"] > a["lin"]:
                    robot_coll += 1
                elif abs(alpha) > abs(alpha2) and r["lin"] < a["lin"]:
                    person_coll += 1
                elif abs(alpha) < abs(alpha2) and r["lin"] < a["lin"]:
                    robot_coll += 1
                elif abs(alpha) > abs(alpha2) and r["lin"] > a["lin"]:
                    person_coll += 1
                elif abs(alpha) == abs(alpha2) and r["lin"] == a["lin"]:
                    robot_coll += 1
                    person_coll += 1
    count = sum(1 for r in robot if r["lin"] < 0.01 and abs(r["ang"] < 0.02))
    accel = over = 0.0
    for i in range(n - 1):
        dv, dt = robot[i + 1]["lin"] - robot[i]["lin"], stamps[i + 1] - stamps[i]
        if dt != 0.0:
            accel += abs(dv / dt)
            over += abs(dv / dt / dt)
    ped = sum(a["lin"] for i in range(n) for a in agents[i]) / (n * len(agents[0]))
    return {
        "hunav_time_to_reach_goal_s": total,
        "hunav_path_length_m": path,
        "hunav_cumulative_heading_changes_rad": chc,
        "hunav_avg_distance_to_closest_person_m": avg / n,
        "hunav_minimum_distance_to_people_m": minimum,
        "hunav_maximum_distance_to_people_m": maximum,
        "hunav_intimate_space_intrusions_pct": zones["intimate"],
        "hunav_personal_space_intrusions_pct": zones["personal"],
        "hunav_social_space_intrusions_pct": zones["social"],
        "hunav_robot_on_person_collisions": robot_coll,
        "hunav_person_on_robot_collisions": person_coll,
        "hunav_time_not_moving_s": total / n * count,
        "hunav_avg_robot_linear_speed_mps": sum(r["lin"] for r in robot) / n,
        "hunav_avg_robot_angular_speed_rps": sum(abs(r["ang"]) for r in robot) / n,
        "hunav_avg_acceleration_mps2": accel / n,
        "hunav_avg_overacceleration": over / n,
        "hunav_avg_pedestrian_velocity_mps": ped,
    }
