"""The topic table: for each HAVEN topic, its message type, its QoS on each side, and how its
payload (a core type) becomes a message and back. Every node wires its component through this
table, so a topic's type, QoS and conversion are defined once."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from geometry_msgs.msg import PoseArray, PoseStamped, Twist, TwistStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rclpy.qos import QoSProfile
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import BatteryState, LaserScan
from std_msgs.msg import Bool, String

from haven_sim.common import topics
from haven_sim.common.topics import ROBOT_CMD_VEL, WireParams
from haven_sim.nodes import conversions as conv, qos

try:  # not on PyPI: the pip setup builds it with colcon (scripts/build_interfaces.py)
    from tf2_msgs.msg import TFMessage
except ImportError:  # pragma: no cover - depends on the machine
    TFMessage = None


def type_name(msg_type: Any) -> str:
    """'nav_msgs/msg/Odometry' for the rclpy class nav_msgs.msg.Odometry."""
    return f"{msg_type.__module__.split('.')[0]}/msg/{msg_type.__name__}"


@dataclass(frozen=True)
class TopicSpec:
    msg_type: Any
    encode: Callable[[Any, float], Any]  # (payload, stamp) -> message
    decode: Callable[[Any], Any]  # message -> payload; raises ValueError on a bad message
    pub_qos: QoSProfile
    sub_qos: QoSProfile
    late_qos: QoSProfile | None = None  # also read with this (a latched publisher's last message, for a late joiner)
    best_effort_too: bool = False  # also read best effort, so a best-effort publisher (a joystick's e-stop) is heard


@dataclass(frozen=True)
class Frames:
    map: str = "map"
    odom: str = "odom"
    base: str = "base_footprint"
    scan: str = "base_scan"


def _twist() -> TopicSpec:
    return TopicSpec(Twist, lambda t, _: conv.twist_msg(t), conv.twist_from_msg, qos.STREAM, qos.RELIABLE)


def _twist_stamped() -> TopicSpec:
    return TopicSpec(
        TwistStamped,
        lambda t, stamp: conv.twist_stamped_msg(t, stamp),
        lambda m: conv.twist_from_msg(m.twist),
        qos.STREAM,
        qos.RELIABLE,
    )


def with_wire_params(table: dict[str, TopicSpec], params: WireParams) -> dict[str, TopicSpec]:
    """The topic table as these parameters set it (the robot's velocity topics stamped or not)."""
    if params.stamped_cmd_vel:
        return {**table, **{t: _twist_stamped() for t in ROBOT_CMD_VEL if t in table}}
    return table


def _unsupported(msg: Any) -> Any:
    raise ValueError("no HAVEN node reads this topic")


def specs(frames: Frames = Frames(), human_ids: Sequence[str] = ()) -> dict[str, TopicSpec]:
    """The haven_sim topics; `human_ids` name the /humans poses and the per-human command topics."""
    f = frames
    table = {
        topics.CLOCK: TopicSpec(
            Clock, lambda t, _: conv.clock_msg(t), lambda m: conv.time_from_msg(m.clock), qos.STREAM, qos.CLOCK
        ),
        topics.PACE_NAV: TopicSpec(
            Clock, lambda t, _: conv.clock_msg(t), lambda m: conv.time_from_msg(m.clock), qos.LATEST, qos.LATEST
        ),
        topics.PACE: TopicSpec(
            Clock, lambda t, _: conv.clock_msg(t), lambda m: conv.time_from_msg(m.clock), qos.LATEST, qos.LATEST
        ),
        topics.MAP: TopicSpec(
            OccupancyGrid,
            lambda g, t: conv.occupancy_msg(t, g, f.map),
            conv.occupancy_from_msg,
            qos.LATCHED,
            qos.LATCHED,
        ),
        topics.ODOM: TopicSpec(
            Odometry,
            lambda s, t: conv.odometry_msg(t, s, f.odom, f.base),
            conv.odometry_from_msg,
            qos.STREAM,
            qos.LATEST,
        ),
        topics.SCAN: TopicSpec(
            LaserScan, lambda s, t: conv.scan_msg(t, s, f.scan), _unsupported, qos.SENSOR, qos.SENSOR
        ),
        topics.BATTERY: TopicSpec(
            BatteryState, lambda r, t: conv.battery_msg(t, r), conv.battery_from_msg, qos.STREAM, qos.LATEST
        ),
        topics.HUMANS: TopicSpec(
            PoseArray,
            lambda h, t: conv.humans_msg(t, h, f.map),
            lambda m: conv.humans_from_msg(m, human_ids),
            qos.STREAM,
            qos.LATEST,
        ),
        topics.CMD_VEL: _twist(),
        topics.CMD_VEL_NAV: _twist(),
        topics.CMD_VEL_TELEOP: _twist(),
        topics.ESTOP: TopicSpec(
            Bool,
            lambda b, _: Bool(data=b),
            lambda m: bool(m.data),
            qos.LATCHED,
            qos.ANY_DURABILITY,
            qos.LATCHED,
            best_effort_too=True,
        ),
        topics.GOAL: TopicSpec(
            PoseStamped, lambda g, t: conv.goal_msg(t, g), conv.goal_from_msg, qos.RELIABLE, qos.RELIABLE
        ),
        topics.PLAN: TopicSpec(
            Path,
            lambda p, t: conv.path_msg(t, p, f.map),
            conv.path_from_msg,
            qos.CHANGES,
            qos.ANY_DURABILITY,
            qos.LATCHED,
        ),
        topics.WAIT: TopicSpec(Bool, lambda b, _: Bool(data=b), lambda m: bool(m.data), qos.LATCHED, qos.LATCHED),
        topics.THOUGHT: TopicSpec(String, lambda s, _: String(data=s), lambda m: str(m.data), qos.LATCHED, qos.LATCHED),
        topics.WIZARD_THOUGHT: TopicSpec(
            String, lambda s, _: String(data=s), lambda m: str(m.data), qos.LATCHED, qos.LATCHED
        ),
        topics.EVENTS: TopicSpec(
            String, lambda e, _: conv.event_msg(e), conv.event_from_msg, qos.EVENTS_PUB, qos.EVENTS
        ),
        topics.REMOVE_OBSTRUCTION: TopicSpec(
            String, lambda s, _: String(data=s), lambda m: str(m.data), qos.RELIABLE, qos.RELIABLE
        ),
        topics.CANCEL_GOAL: TopicSpec(
            String, lambda s, _: String(data=s), lambda m: str(m.data), qos.RELIABLE, qos.RELIABLE
        ),
        topics.TRIAL_STATUS: TopicSpec(
            String, lambda s, _: String(data=s), lambda m: str(m.data), qos.LATCHED, qos.LATCHED
        ),
        topics.TRIAL_CONTROL: TopicSpec(
            String, lambda s, _: String(data=s), lambda m: str(m.data), qos.RELIABLE, qos.RELIABLE
        ),
    }
    if TFMessage is not None:
        table[topics.TF] = TopicSpec(TFMessage, lambda fr, t: conv.tf_msg(t, fr), _unsupported, qos.STREAM, qos.TF)
        table[topics.TF_STATIC] = TopicSpec(
            TFMessage, lambda fr, t: conv.tf_msg(t, fr), _unsupported, qos.LATCHED, qos.LATCHED
        )
    for hid in human_ids:
        table[topics.human_cmd_vel(hid)] = _twist()
        table[topics.human_pose(hid)] = TopicSpec(
            PoseStamped, lambda p, t: conv.pose_stamped_msg(t, p, f.map), conv.pose_from_stamped, qos.STREAM, qos.LATEST
        )
    return table
