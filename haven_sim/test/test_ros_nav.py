"""Cross-process navigation: goal in -> /plan out -> the simulated robot arrives; humans; foreign paths."""

import math

import pytest
import yaml
from foreign_paths import STYLE
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry, Path
from std_msgs.msg import Bool, String

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.common.paths import SegmentKind, read_path
from haven_sim.nav.navigator import Navigator
from haven_sim.nodes import conversions as conv, qos
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world

pytestmark = pytest.mark.ros
SIM, MUX, PLANNER, CONTROLLER = (
    f"haven_sim.nodes.{n}" for n in ("sim_node", "mux_node", "planner_node", "controller_node")
)


def start_suite(ros, world="small_test", rtf=4.0, planner=True, lockstep=False):
    """The navigation nodes; `lockstep`: on the lockstep clock, so how the robot drives does not
    depend on how busy the machine is (what is tested is where it ends up)."""
    nodes = {"velocity_mux": MUX, "controller": CONTROLLER} | ({"planner": PLANNER} if planner else {})
    stepped = {"lockstep": True, "use_sim_time": False} if lockstep else {"use_sim_time": True}
    sim = {"world": world, "real_time_factor": rtf}
    if lockstep:
        sim |= {"lockstep": True, "lockstep_participants": f"[{','.join(nodes)}]"}
    ros.start(SIM, sim)
    for module in nodes.values():
        ros.start(module, stepped)


def goal_msg(x, y, yaw=0.0, frame="map"):
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.pose = conv.pose_msg(Pose2D(x, y, yaw))
    return msg


def rest_pose(ros, odom, after_s):
    """Where the robot comes to rest after `after_s` (an event's stamp): the test reads /odom in a
    separate subscription, so its newest message may predate the event."""

    def resting():
        m = odom[-1]
        return (
            conv.time_from_msg(m.header.stamp) > after_s
            and abs(m.twist.twist.linear.x) < 1e-3
            and abs(m.twist.twist.angular.z) < 1e-3
        )

    assert ros.spin_until(resting, 30), "the robot did not come to rest"
    return conv.pose_from_msg(odom[-1].pose.pose)


def events_of(received, kind):
    return [e for e in map(conv.event_from_msg, received) if e.kind is kind]


def test_goal_pose_to_plan_to_arrival_without_touching_walls(ros):
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    plans = ros.collect(Path, "/plan", qos.LATCHED)
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    goal = ros.node.create_publisher(PoseStamped, "/goal_pose", qos.RELIABLE)
    start_suite(ros, lockstep=True)
    ros.wait_matched(goal)
    ros.wait_for_messages(odom, 5)
    goal.publish(goal_msg(7.2, 4.5, math.pi / 2))
    assert ros.spin_until(lambda: events_of(events, EventKind.GOAL_REACHED), 120)
    path = conv.path_from_msg(plans[-1])
    assert plans[-1].header.frame_id == "map"
    # The node publishes exactly what the planner core makes of the same map, start and goal.
    world = load_world(packaged_world("small_test"))
    expected = Navigator(rasterise(world)).set_goal(world.robot_start, Pose2D(7.2, 4.5, math.pi / 2), 0.0).path
    assert len(path) == len(expected) and all(
        a.distance_to(b) < 1e-6 and abs(a.yaw - b.yaw) < 1e-6 for a, b in zip(path, expected, strict=True)
    )
    # a door to go through, a yaw to end on
    assert {s.kind for s in read_path(path, *STYLE).segments} >= {SegmentKind.STRAIGHT, SegmentKind.ROTATE}
    p = rest_pose(ros, odom, events_of(events, EventKind.GOAL_REACHED)[0].stamp)
    assert math.hypot(p.x - 7.2, p.y - 4.5) <= 0.1
    assert abs(math.remainder(p.yaw - math.pi / 2, 2 * math.pi)) <= math.radians(6)
    made = events_of(events, EventKind.PLAN_MADE)
    assert len(made) == 1 and made[0]["goal"] == [7.2, 4.5]
    assert events_of(events, EventKind.CONTACT_BEGIN) == []


def test_unreachable_goal_is_refused_with_an_event(ros):
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    goal = ros.node.create_publisher(PoseStamped, "/goal_pose", qos.RELIABLE)
    start_suite(ros, lockstep=True)
    ros.wait_matched(goal)
    goal.publish(goal_msg(6.3, 3.8))  # inside the pillar
    assert ros.spin_until(lambda: events_of(events, EventKind.PLAN_REFUSED), 30)
    assert "inside an obstacle" in events_of(events, EventKind.PLAN_REFUSED)[0]["reason"]
    goal.publish(goal_msg(1.0, 1.0, frame="base_link"))
    assert ros.spin_until(lambda: len(events_of(events, EventKind.PLAN_REFUSED)) == 2, 30)
    assert "frame 'base_link'" in events_of(events, EventKind.PLAN_REFUSED)[1]["reason"]


def corridor_world(tmp_path, human, width=3.0):
    data = {
        "name": "corridor",
        "walls": [
            {"segment": [[0, 0], [12, 0]], "thickness": 0.1},
            {"segment": [[12, 0], [12, width]], "thickness": 0.1},
            {"segment": [[12, width], [0, width]], "thickness": 0.1},
            {"segment": [[0, width], [0, 0]], "thickness": 0.1},
        ],
        "robot": {"start": [1.0, width / 2, 0.0]},
        "humans": [{"id": "h1", "start": list(human)}],
    }
    path = tmp_path / "corridor.yaml"
    path.write_text(yaml.safe_dump(data))
    return str(path)


# A 1.6 m corridor leaves no room beside a person: the robot waits. In 3 m it passes them.
@pytest.mark.parametrize(
    "human,width,expected", [((4.0, 0.8, 3.14), 1.6, EventKind.WAITING), ((6.0, 1.25, 3.14), 3.0, EventKind.REPLANNED)]
)
def test_human_on_the_path_makes_the_robot_wait_or_pass(ros, tmp_path, human, width, expected):
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    waits = ros.collect(Bool, "/haven/wait", qos.LATCHED)
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    goal = ros.node.create_publisher(PoseStamped, "/goal_pose", qos.RELIABLE)
    start_suite(ros, world=corridor_world(tmp_path, human, width))
    ros.wait_matched(goal)
    ros.wait_for_messages(odom, 5)
    goal.publish(goal_msg(11.0, width / 2))
    assert ros.spin_until(lambda: events_of(events, expected), 60)
    if expected is EventKind.WAITING:
        assert ros.spin_until(lambda: waits and waits[-1].data, 10)
        assert "no room to pass" in events_of(events, EventKind.WAITING)[0]["reason"]
        ros.spin_until(lambda: abs(odom[-1].twist.twist.linear.x) < 0.01, 10)
        t0, held = conv.time_from_msg(odom[-1].header.stamp), conv.pose_from_msg(odom[-1].pose.pose)
        ros.spin_until(lambda: conv.time_from_msg(odom[-1].header.stamp) > t0 + 3.0, 30)
        assert conv.pose_from_msg(odom[-1].pose.pose).distance_to((held.x, held.y)) < 0.05  # held still
        # Before the person, not at them: braking starts wait_gap_m (1.2 m) ahead; how far the robot
        # then rolls depends on the latency of a free-running loop on a loaded machine (0.75 m seen).
        assert 4.0 - held.x >= 0.5
    else:
        assert events_of(events, EventKind.REPLANNED)[0]["side"] == "left"
        assert ros.spin_until(lambda: events_of(events, EventKind.GOAL_REACHED), 120)
        assert events_of(events, EventKind.CONTACT_BEGIN) == []


def test_controller_follows_a_path_published_by_someone_else(ros):
    """No planner of ours: the test is the planner and publishes /plan itself."""
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    plan = ros.node.create_publisher(Path, "/plan", qos.LATCHED)
    start_suite(ros, planner=False, lockstep=True)
    ros.wait_matched(plan)
    ros.wait_for_messages(odom, 5)
    poses = [Pose2D(1.0 + 0.1 * i, 2.5 - 0.04 * i, -0.38) for i in range(26)]  # 2.8 m, slightly downhill
    plan.publish(conv.path_msg(0.0, poses))
    assert ros.spin_until(lambda: events_of(events, EventKind.GOAL_REACHED), 90)
    assert rest_pose(ros, odom, events_of(events, EventKind.GOAL_REACHED)[0].stamp).distance_to((3.5, 1.5)) <= 0.1
