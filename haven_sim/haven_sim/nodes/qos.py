"""QoS profiles by topic role (DESIGN.md topic table), defined once for every node."""

from typing import Any

from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
)

# Latched state: /map, /haven/thought, /haven/world_markers, /haven/wait, our /haven/estop publishers.
LATCHED = QoSProfile(
    depth=1,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
# Commands and state streams: /cmd_vel*, /odom, /battery_state, /humans, /goal_pose.
RELIABLE = QoSProfile(depth=10, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
# Publishers of streams (/odom, /humans, /battery_state, /clock, /tf, cmd_vel, AR markers): reliable
# like RELIABLE, with a deep history so a reader that falls behind for a moment (a recorder on a
# busy machine at 10x real time: /odom comes 500 times a second) still gets every message re-sent.
# Depth does not affect QoS matching: any reliable or best-effort reader matches.
STREAM = QoSProfile(depth=1000, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
# Subscribers that act on the current state (controller, planner, viz, scenario) keep only the latest
# /odom, /humans or /battery_state: at 10x real time a backlog would make them act on old poses.
LATEST = QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
# Readers of what other nodes may publish either way: /plan (Nav2's planner_server: volatile),
# /haven/estop (`ros2 topic pub`: volatile, default QoS). A volatile reader matches volatile and
# transient-local publishers alike. In a node's first seconds, while only latched publishers are
# there (our planner, `haven`'s e-stop), a LATCHED reader beside it picks up what they sent before
# the readers matched (nodes/component_node.py).
ANY_DURABILITY = QoSProfile(depth=10, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)


def best_effort(profile: QoSProfile) -> QoSProfile:
    """`profile` read best effort and volatile: a reader that matches every publisher (reliable or
    best effort, volatile or transient local); the e-stop's second reader."""
    return QoSProfile(depth=profile.depth, history=profile.history, reliability=ReliabilityPolicy.BEST_EFFORT)


# /clock: the rosgraph default (reliable, depth 10) so every use_sim_time node matches.
CLOCK = RELIABLE
# /scan
SENSOR = qos_profile_sensor_data
# /tf: what tf2_ros broadcasters use (reliable, depth 100); /tf_static is LATCHED.
TF = QoSProfile(depth=100, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
# /haven/events: nothing may be dropped on the way to the recorder. Publishers keep their last 1000
# events for readers that match late (DDS discovery can take seconds; a goal storm before a trial
# made a planner log more than 100); the recorder reads with EVENTS_HISTORY and so gets them, other
# nodes read only what happens from now on (EVENTS).
EVENTS = QoSProfile(depth=100, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
EVENTS_PUB = QoSProfile(
    depth=1000,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
EVENTS_HISTORY = EVENTS_PUB
# Publishers of /plan and /haven/cue_state: latched like LATCHED, but the recorder needs every
# change and two can come within moments (a re-plan right after a plan, a condition toggled as the
# thought text changes). A late joiner's depth-1 reader still keeps only the newest.
CHANGES = EVENTS_PUB

# No middleware event handlers. rclpy gives every publisher and subscription two by default (a
# warning on an incompatible QoS or type), and its Python executor walks every handler on every
# wait: 146 in the suite process, about a fifth of a lockstep trial's CPU (bench/RESULTS.md).
# The suite's publishers go without them: the reader's side says it (rclpy's, rclcpp's, ros2 topic
# echo's and our own subscriptions keep theirs). The recorder's readers take each publisher's own QoS.
QUIET_PUBLISHER = PublisherEventCallbacks(use_default_callbacks=False)


def quiet_reader(**callbacks: object) -> SubscriptionEventCallbacks:
    """A reader's event callbacks: only those given (`message_lost=`, `matched=`, ...), no default ones."""
    return SubscriptionEventCallbacks(**callbacks, use_default_callbacks=False)  # type: ignore[arg-type]


class QuietNode(Node):
    """A node whose publishers have no default event handlers (`QUIET_PUBLISHER`), /parameter_events too."""

    def create_publisher(self, *args: Any, **kwargs: Any) -> Publisher:
        kwargs.setdefault("event_callbacks", QUIET_PUBLISHER)
        return super().create_publisher(*args, **kwargs)
