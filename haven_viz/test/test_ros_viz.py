"""The viz node in the running suite: namespaces, the projection eaten up, a toggle at run time."""

import math

import pytest
from geometry_msgs.msg import PoseStamped
from rcl_interfaces.msg import Parameter as ParameterMsg, ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, SetParameters
from std_msgs.msg import String
from visualization_msgs.msg import Marker, MarkerArray

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.nodes import conversions as conv, qos
from haven_viz.markers import MarkerSpec, Shape
from haven_viz.nodes.conversions import marker_msg, spec_from_msg

pytestmark = pytest.mark.ros


def test_marker_conversion_round_trips():
    spec = MarkerSpec(
        "path_projection",
        7,
        Shape.CUBE,
        (1.0, 2.0, 0.1),
        0.5,
        (0.2, 0.2, 0.2),
        (1, 1, 0, 1),
        "",
        ((0, 0, 0), (1, 1, 1)),
    )
    back = spec_from_msg(marker_msg(spec, 12.5))
    assert back.rounded() == spec.rounded()


class LiveMarkers:
    """What a viewer shows: markers added and deleted by (ns, id)."""

    def __init__(self):
        self.live = {}
        self.deleted = []

    def __call__(self, msg: MarkerArray):
        for m in msg.markers:
            if m.action == Marker.DELETE:
                self.live.pop((m.ns, m.id), None)
                self.deleted.append((m.ns, m.id))
            else:
                self.live[(m.ns, m.id)] = m

    def count(self, ns):
        return sum(1 for k in self.live if k[0] == ns)


def test_cues_in_the_running_suite(ros):
    live = LiveMarkers()
    ros.node.create_subscription(MarkerArray, "/haven/ar_markers", live, qos.RELIABLE)
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    thought = ros.node.create_publisher(String, "/haven/thought", qos.LATCHED)
    goal = ros.node.create_publisher(PoseStamped, "/goal_pose", qos.RELIABLE)
    world = "small_test"
    ros.start("haven_sim.nodes.sim_node", {"world": world, "real_time_factor": 2.0})
    for node in ("mux_node", "planner_node", "controller_node"):
        ros.start(f"haven_sim.nodes.{node}", {"use_sim_time": True})
    ros.start("haven_viz.nodes.viz_node", {"use_sim_time": True, "world": world, "thought_radius_m": 10.0})
    ros.wait_matched(goal)
    ros.wait_matched(thought)
    thought.publish(String(data="Going to the east room"))
    assert ros.spin_until(lambda: live.count("robot") == 2 and live.count("battery_indicator") == 3, 30)
    msg = PoseStamped()
    msg.header.frame_id = "map"
    msg.pose = conv.pose_msg(Pose2D(7.2, 4.5, math.pi / 2))
    goal.publish(msg)
    assert ros.spin_until(lambda: live.count("path_projection") > 5, 30)
    first = live.count("path_projection")
    wanted = {"path_projection", "battery_indicator", "thought_bubble", "robot", "humans"}
    assert ros.spin_until(lambda: {k[0] for k in live.live} >= wanted, 20), {k[0] for k in live.live}
    assert all(m.header.frame_id == "map" for m in live.live.values())
    assert ros.spin_until(lambda: live.count("path_projection") < first - 3, 60)  # eaten up as it drives
    # The study condition, switched at run time: the path projection goes away with explicit DELETEs.
    client = ros.node.create_client(SetParameters, "/viz/set_parameters")
    assert client.wait_for_service(timeout_sec=10)
    off = ParameterValue(type=ParameterType.PARAMETER_BOOL, bool_value=False)
    req = SetParameters.Request(parameters=[ParameterMsg(name="path_projection", value=off)])
    future = client.call_async(req)
    ros.spin_until(future.done, 10)
    assert future.result().results[0].successful
    assert ros.spin_until(lambda: live.count("path_projection") == 0, 10)
    assert any(ns == "path_projection" for ns, _ in live.deleted)
    toggled = [e for e in map(conv.event_from_msg, events) if e.kind is EventKind.CUE_TOGGLED]
    assert toggled and toggled[0]["cue"] == "path_projection" and toggled[0]["on"] is False
    half = ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=0.5)
    bad = SetParameters.Request(parameters=[ParameterMsg(name="marker_size_m", value=half)])
    future = client.call_async(bad)
    ros.spin_until(future.done, 10)
    assert not future.result().results[0].successful and "read-only" in future.result().results[0].reason
    # A start-up parameter says so in its descriptor (as `ros2 param describe` shows); a toggle does not.
    describe = ros.node.create_client(DescribeParameters, "/viz/describe_parameters")
    assert describe.wait_for_service(timeout_sec=10)
    future = describe.call_async(DescribeParameters.Request(names=["marker_size_m", "path_projection"]))
    ros.spin_until(future.done, 10)
    assert [d.read_only for d in future.result().descriptors] == [True, False]

    def refusals():
        return [e for e in map(conv.event_from_msg, events) if e.kind is EventKind.REQUEST_REFUSED]

    assert ros.spin_until(refusals, 10) and refusals()[0]["name"] == "marker_size_m"  # (said in the study log)


def test_world_markers_reach_a_late_viewer(ros):
    ros.start("haven_viz.nodes.viz_node", {"world": "small_test"})
    late = []
    ros.spin_until(lambda: ros.node.count_publishers("/haven/world_markers") > 0, 20)
    ros.node.create_subscription(MarkerArray, "/haven/world_markers", late.append, qos.LATCHED)
    assert ros.spin_until(lambda: late, 20)
    namespaces = {m.ns for m in late[-1].markers}
    assert namespaces >= {"walls", "rooms", "gems", "charging_base"}
