"""Cross-process tests: the simulator and mux nodes as separate processes, driven from this test."""

import contextlib
import itertools
import math
import os
import signal
import time

import pytest
from geometry_msgs.msg import PoseArray, PoseStamped, Twist, TwistStamped
from nav_msgs.msg import OccupancyGrid, Odometry
from rclpy.duration import Duration
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from ros_harness import tracebacks
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import BatteryState, LaserScan
from std_msgs.msg import Bool, String
from std_srvs.srv import Trigger

from haven_sim.common.events import EventKind
from haven_sim.nodes import conversions as conv, qos
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world

pytestmark = pytest.mark.ros
SIM = "haven_sim.nodes.sim_node"
MUX = "haven_sim.nodes.mux_node"


def twist(vx=0.0, wz=0.0):
    return conv.twist_msg(conv.Twist2D(vx, 0.0, wz))


def stderr_of(proc):
    """A function returning what `proc` (started with capture) has written to stderr so far."""
    os.set_blocking(proc.stderr.fileno(), False)
    text = []

    def said():
        with contextlib.suppress(BlockingIOError):
            text.append(os.read(proc.stderr.fileno(), 1 << 16).decode(errors="replace"))
        return "".join(text)

    return said


def drive(ros, pub, msg, odom, sim_seconds):
    """Publish `msg` every 0.05 s of sim time (as a 20 Hz controller would) for sim_seconds."""
    start = conv.time_from_msg(odom[-1].header.stamp)
    next_t = start
    while True:
        now = conv.time_from_msg(odom[-1].header.stamp)
        if now - start >= sim_seconds:
            return
        if now >= next_t:
            pub.publish(msg)
            next_t = now + 0.05
        ros.executor.spin_once(timeout_sec=0.005)


def test_odom_rate_pose_scan_and_topics(ros):
    odom = ros.collect(Odometry, "/odom", qos.STREAM)  # deep, as a recorder reads: a busy test process loses none
    scans = ros.collect(LaserScan, "/scan", qos.SENSOR)
    clock = ros.collect(Clock, "/clock", qos.CLOCK)
    humans = ros.collect(PoseArray, "/humans", qos.RELIABLE)
    h1 = ros.collect(PoseStamped, "/humans/h1/pose", qos.RELIABLE)
    battery = ros.collect(BatteryState, "/battery_state", qos.RELIABLE)
    ros.start(SIM, {"real_time_factor": 2.0})
    ros.wait_matched(odom)
    ros.wait_for_messages(odom, 60)
    ros.wait_for_messages(scans, 3)
    ros.wait_for_messages(battery, 2)
    ros.wait_for_messages(humans, 2)
    ros.wait_for_messages(h1, 2)
    stamps = [conv.time_from_msg(m.header.stamp) for m in odom[-50:]]
    gaps = [b - a for a, b in itertools.pairwise(stamps)]
    assert all(g == pytest.approx(0.02, abs=1e-6) for g in gaps)  # 50 Hz in sim time, none lost
    assert clock and conv.time_from_msg(clock[-1].clock) >= stamps[0]
    m = odom[-1]
    assert (m.header.frame_id, m.child_frame_id) == ("odom", "base_footprint")
    assert conv.pose_from_msg(m.pose.pose) == pytest.approx((1.0, 2.5, 0.0), abs=1e-6)
    s = scans[-1]
    assert s.header.frame_id == "base_scan" and len(s.ranges) == 360
    assert (s.range_min, s.range_max) == pytest.approx((0.12, 3.5))
    assert s.ranges[0] == pytest.approx(1.0 - 0.05, abs=1e-4)  # beam 0 looks backwards at the west wall
    assert math.isinf(s.ranges[180])  # straight ahead through the door: nothing within 3.5 m
    ss = conv.time_from_msg(scans[-1].header.stamp) - conv.time_from_msg(scans[-2].header.stamp)
    assert ss == pytest.approx(0.1, abs=1e-6)
    assert humans[-1].header.frame_id == "map" and len(humans[-1].poses) == 1
    # the same person by id, on a topic of its own
    assert h1[-1].header.frame_id == "map" and conv.pose_from_msg(h1[-1].pose) == pytest.approx(
        (7.0, 1.0, 3.14159), abs=1e-4
    )
    b = battery[-1]
    assert b.percentage == pytest.approx(1.0) and b.power_supply_status == BatteryState.POWER_SUPPLY_STATUS_FULL


def test_cmd_vel_drives_and_watchdog_stops(ros):
    """Read from /odom alone, so a command's latency on a busy machine does not matter: the robot
    ramps up at the 0.5 m/s^2 limit to the commanded speed; one command from standstill moves it for
    the 0.5 s watchdog (sim time), then it brakes to a stop."""
    odom = ros.collect(Odometry, "/odom", qos.STREAM)
    pub = ros.node.create_publisher(Twist, "/cmd_vel", qos.RELIABLE)
    ros.start(SIM, {"real_time_factor": 2.0})
    ros.wait_matched(pub)
    ros.wait_for_messages(odom, 5)
    n = len(odom)
    assert ros.spin_until(
        lambda: pub.publish(twist(0.4, 0.0)) or odom[-1].twist.twist.linear.x == pytest.approx(0.4, abs=1e-6), 30
    )
    speeds = [(conv.time_from_msg(m.header.stamp), m.twist.twist.linear.x) for m in odom[n:]]
    rises = [(v1 - v0) / (t1 - t0) for (t0, v0), (t1, v1) in itertools.pairwise(speeds) if v1 > v0]
    assert rises and max(rises) == pytest.approx(0.5, abs=1e-3)  # the ramp, never steeper

    assert ros.spin_until(lambda: abs(odom[-1].twist.twist.linear.x) < 1e-6, 30)  # the watchdog stops it
    n = len(odom)
    pub.publish(twist(0.4, 0.0))  # one command, then nothing
    assert ros.spin_until(
        lambda: any(m.twist.twist.linear.x > 0 for m in odom[n:]) and abs(odom[-1].twist.twist.linear.x) < 1e-6, 30
    )
    moving = [m for m in odom[n:] if m.twist.twist.linear.x > 0]
    peak = max(moving, key=lambda m: m.twist.twist.linear.x)
    held = conv.time_from_msg(peak.header.stamp) - conv.time_from_msg(moving[0].header.stamp)
    assert held == pytest.approx(0.5, abs=0.03)  # applied for 0.5 s of sim time (one 0.02 s step either way)
    assert peak.twist.twist.linear.x == pytest.approx(0.5 * (held + 0.02), abs=0.011)  # ramping all the while


def test_non_finite_command_is_dropped_with_a_warning(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    pub = ros.node.create_publisher(Twist, "/cmd_vel", qos.RELIABLE)
    proc = ros.start(SIM, {"real_time_factor": 2.0}, capture=True)
    ros.wait_matched(pub)
    ros.wait_for_messages(odom, 5)
    drive(ros, pub, twist(math.nan, 0.5), odom, 1.0)
    assert conv.pose_from_msg(odom[-1].pose.pose) == pytest.approx((1.0, 2.5, 0.0), abs=1e-6)
    drive(ros, pub, twist(0.0, 1.0), odom, 1.0)  # still obeys finite commands
    assert odom[-1].twist.twist.angular.z == pytest.approx(1.0, abs=0.01)
    assert ros.stop(proc) == 0
    err = proc.stderr.read()
    assert "dropped a non-finite command on /cmd_vel" in err
    assert err.count("non-finite") < 5  # throttled
    assert tracebacks(err) == []


def test_latched_map_reaches_a_late_subscriber_and_reset_service(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    pub = ros.node.create_publisher(Twist, "/cmd_vel", qos.RELIABLE)
    ros.start(SIM, {"real_time_factor": 2.0})
    ros.wait_for_messages(odom, 5)
    ros.wait_matched(pub)
    drive(ros, pub, twist(0.5, 0.0), odom, 3.0)
    maps = ros.collect(OccupancyGrid, "/map", qos.LATCHED)  # subscribes only now
    ros.wait_for_messages(maps, 1)
    world = load_world(packaged_world("small_test"))
    grid = conv.occupancy_from_msg(maps[0])
    assert maps[0].header.frame_id == "map" and grid.resolution_m == pytest.approx(0.05)
    assert grid.is_occupied(4.0, 1.0) and not grid.is_occupied(2.0, 2.5)
    assert grid.width * grid.resolution_m > world.bounds()[2] - world.bounds()[0]
    client = ros.node.create_client(Trigger, "/haven/reset")
    assert client.wait_for_service(timeout_sec=10.0)
    future = client.call_async(Trigger.Request())
    ros.spin_until(future.done)
    assert future.result().success
    ros.spin_until(lambda: conv.pose_from_msg(odom[-1].pose.pose).x == pytest.approx(1.0, abs=1e-6))
    assert any(conv.event_from_msg(e).kind is EventKind.RESET for e in events)


def test_wall_contact_is_an_event(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    pub = ros.node.create_publisher(Twist, "/cmd_vel", qos.RELIABLE)
    ros.start(SIM, {"real_time_factor": 4.0})
    ros.wait_matched(pub)
    ros.wait_matched(events)
    ros.wait_for_messages(odom, 5)
    drive(ros, pub, twist(-0.5, 0.0), odom, 3.0)  # backwards into the west wall, 0.95 m behind
    first = conv.event_from_msg(events[0])
    assert (first.kind, first["other"], first.source) == (EventKind.CONTACT_BEGIN, "wall", "sim")


def test_mux_teleop_beats_nav_then_hands_back_and_estop(ros):
    out = ros.collect(Twist, "/cmd_vel", qos.RELIABLE)
    nav = ros.node.create_publisher(Twist, "/cmd_vel_nav", qos.RELIABLE)
    teleop = ros.node.create_publisher(Twist, "/cmd_vel_teleop", qos.RELIABLE)
    estop = ros.node.create_publisher(Bool, "/haven/estop", qos.LATCHED)
    # Wall time, no simulator needed; a teleop timeout far above any stall of a busy machine, so
    # that only the mux's rule decides who holds control.
    ros.start(MUX, {"teleop_timeout_s": 3.0})
    for e in (out, nav, teleop, estop):
        ros.wait_matched(e)

    def last_after(pub, msg, expect_vx):
        pub.publish(msg)
        return ros.spin_until(lambda: out and out[-1].linear.x == pytest.approx(expect_vx), 5.0)

    assert last_after(nav, twist(0.2), 0.2)
    assert last_after(teleop, twist(-0.3), -0.3)
    nav.publish(twist(0.2))
    ros.spin_for(0.1)
    assert out[-1].linear.x == pytest.approx(-0.3)  # teleop still holds control
    # keep nav alive; teleop goes quiet and control returns to nav after the timeout
    assert ros.spin_until(lambda: (nav.publish(twist(0.2)) or True) and out[-1].linear.x == pytest.approx(0.2), 15.0)
    estop.publish(Bool(data=True))
    assert ros.spin_until(lambda: (nav.publish(twist(0.2)) or True) and out[-1].linear.x == 0.0, 5.0)
    for _ in range(5):
        nav.publish(twist(0.2))
        teleop.publish(twist(0.3))
        ros.spin_for(0.05)
        assert out[-1].linear.x == 0.0
    estop.publish(Bool(data=False))  # released once no true has come for estop_hold_s (2 s)
    assert ros.spin_until(lambda: (teleop.publish(twist(0.3)) or True) and out[-1].linear.x == pytest.approx(0.3), 10.0)


def test_estop_from_default_qos_publishers_several_at_once_and_a_latched_one_before_start(ros):
    """The e-stop as other tools send it: `ros2 topic pub` (default QoS: reliable, volatile, depth
    10, repeated once a second) while another node keeps saying false; and a latched true sent
    before the mux started."""
    out = ros.collect(Twist, "/cmd_vel", qos.RELIABLE)
    nav = ros.node.create_publisher(Twist, "/cmd_vel_nav", 10)
    latched = ros.node.create_publisher(Bool, "/haven/estop", qos.LATCHED)
    latched.publish(Bool(data=True))  # before the mux exists
    # A hold well above the CLI's 1 s repeat (default 2 s), so that a stalled test process between
    # two repeats does not release the stop.
    ros.start(MUX, {"estop_hold_s": 4.0})
    ros.wait_matched(out)
    ros.wait_matched(nav)
    # the mux's volatile (reliable, best effort) and latched readers
    assert ros.spin_until(lambda: latched.get_subscription_count() >= 3)
    assert latched.wait_for_all_acked(Duration(seconds=5.0))  # the stop has reached both

    def drives(seconds):
        """Whether any command over `seconds` of nav asking for 0.2 m/s moved the robot."""
        del out[:]
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            nav.publish(twist(0.2))
            ros.spin_for(0.05)
        return any(m.linear.x != 0.0 for m in out)

    assert not drives(2.5)  # the late-joining mux honours the latched stop
    latched.publish(Bool(data=False))
    assert ros.spin_until(
        lambda: (nav.publish(twist(0.2)) or True) and bool(out) and out[-1].linear.x == pytest.approx(0.2), 15.0
    )

    cli = ros.node.create_publisher(Bool, "/haven/estop", 10)  # what `ros2 topic pub` creates
    other = ros.node.create_publisher(Bool, "/haven/estop", 10)
    ros.wait_matched(cli)
    ros.wait_matched(other)
    cli.publish(Bool(data=True))
    assert ros.spin_until(lambda: (nav.publish(twist(0.2)) or True) and out[-1].linear.x == 0.0, 3.0)
    end = time.monotonic() + 4.0
    stopped = True
    next_true = time.monotonic() + 1.0
    while time.monotonic() < end:  # the CLI repeats its true at 1 Hz; the other says false at 10 Hz
        if time.monotonic() >= next_true:
            cli.publish(Bool(data=True))
            next_true += 1.0
        other.publish(Bool(data=False))
        nav.publish(twist(0.2))
        ros.spin_for(0.1)
        stopped = stopped and out[-1].linear.x == 0.0
    assert stopped
    # The CLI is stopped: the other publisher's false releases the stop after the hold.
    assert ros.spin_until(
        lambda: (other.publish(Bool(data=False)), nav.publish(twist(0.2))) and out[-1].linear.x == pytest.approx(0.2),
        15.0,
    )


def test_teleop_from_another_node_drives_the_simulated_robot(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    teleop = ros.node.create_publisher(Twist, "/cmd_vel_teleop", qos.RELIABLE)
    # Timeouts far above any stall of this test process between two commands (a loaded machine can
    # stall it for seconds): only the driving is tested, not how steadily this process publishes.
    ros.start(SIM, {"cmd_timeout_s": 20.0})
    ros.start(MUX, {"use_sim_time": True, "teleop_timeout_s": 20.0})
    ros.wait_matched(teleop)
    ros.wait_for_messages(odom, 5)
    drive(ros, teleop, twist(0.0, 1.0), odom, 2.0)
    assert odom[-1].twist.twist.angular.z == pytest.approx(1.0, abs=0.02)
    assert conv.pose_from_msg(odom[-1].pose.pose).yaw > 1.0


def test_stamped_velocity_commands_drive_the_robot_when_configured(ros):
    """TwistStamped as Nav2 Jazzy (enable_stamped_cmd_vel) and `teleop_twist_keyboard stamped:=true`
    send it, through the mux to the simulator."""
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    teleop = ros.node.create_publisher(TwistStamped, "/cmd_vel_teleop", 10)
    ros.start(SIM, {"real_time_factor": 2.0, "stamped_cmd_vel": True, "cmd_timeout_s": 3.0})
    ros.start(MUX, {"use_sim_time": True, "stamped_cmd_vel": True, "teleop_timeout_s": 3.0})
    ros.wait_matched(teleop)
    ros.wait_for_messages(odom, 5)
    msg = TwistStamped()
    msg.header.frame_id = "base_footprint"
    msg.twist = twist(0.0, 1.0)
    drive(ros, teleop, msg, odom, 2.0)
    assert odom[-1].twist.twist.angular.z == pytest.approx(1.0, abs=0.02)


def test_a_publisher_of_the_wrong_type_is_named_in_a_warning(ros):
    teleop = ros.node.create_publisher(TwistStamped, "/cmd_vel_teleop", 10)
    mux = ros.start(MUX, capture=True)
    warning = (
        "/cmd_vel_teleop: haven_test_probe publishes geometry_msgs/msg/TwistStamped, "
        "this node reads geometry_msgs/msg/Twist; ignored (set the stamped_cmd_vel parameter to match)"
    )
    teleop.publish(TwistStamped())
    said = stderr_of(mux)
    assert ros.spin_until(lambda: warning in said(), 30.0), said()
    ros.stop(mux)


def test_invalid_world_fails_fast_with_one_line(ros, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: bad\nwalls: []\nrobot: {start: [0, 0, 0]}\n")
    proc = ros.start(SIM, {"world": str(bad)}, capture=True)
    assert proc.wait(timeout=30) == 2
    err = proc.stderr.read().strip()
    assert err == f"error: {bad}: walls: needs at least one wall (or a map: to make them from)"


def test_declared_bounds_are_the_parameters_ros_ranges_and_out_of_range_is_one_line(ros):
    """A parameter's bounds are declared once, with it (common/params.py): ROS tools see them as the
    descriptor's range, and a value outside them is refused in one line before the node runs."""
    from rclpy.parameter_client import AsyncParameterClient

    proc = ros.start(SIM, {"battery_initial_level": 1.5}, capture=True)
    assert proc.wait(timeout=30) == 2
    assert proc.stderr.read().strip() == "error: sim_node: parameter battery_initial_level: must be within 0..1"
    ros.start(SIM)
    client = AsyncParameterClient(ros.node, "sim_node")
    assert client.wait_for_services(timeout_sec=30)
    described = client.describe_parameters(["battery_initial_level", "battery_pack_m"])
    assert ros.spin_until(described.done, 30)
    level, capacity = described.result().descriptors
    assert [(r.from_value, r.to_value) for r in level.floating_point_range] == [(0.0, 1.0)]
    assert list(capacity.floating_point_range) == []  # (only not negative: no closed range to show)


def test_sigint_shuts_the_node_down_cleanly(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    proc = ros.start(SIM, capture=True)
    ros.wait_for_messages(odom, 1)
    assert ros.stop(proc, signal.SIGINT) == 0
    assert tracebacks(proc.stderr.read()) == []


def test_tf_tree_follows_rep105(ros):
    from tf2_msgs.msg import TFMessage

    static = ros.collect(TFMessage, "/tf_static", qos.LATCHED)
    tf = ros.collect(TFMessage, "/tf", qos.TF)
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    pub = ros.node.create_publisher(Twist, "/cmd_vel", qos.RELIABLE)
    ros.start(SIM, {"real_time_factor": 2.0})
    ros.wait_for_messages(static, 1)
    ros.wait_matched(pub)
    ros.wait_for_messages(odom, 5)
    drive(ros, pub, twist(0.3, 0.5), odom, 1.0)
    pairs = {(t.header.frame_id, t.child_frame_id) for t in static[0].transforms}
    assert pairs == {("map", "odom"), ("base_footprint", "base_link"), ("base_link", "base_scan")}
    ros.wait_for_messages(tf, 20)
    robot = [t for m in tf for t in m.transforms if (t.header.frame_id, t.child_frame_id) == ("odom", "base_footprint")]
    last = robot[-1]
    match = next(o for o in reversed(odom) if o.header.stamp == last.header.stamp)
    assert last.transform.translation.x == pytest.approx(match.pose.pose.position.x)
    assert last.transform.rotation.z == pytest.approx(match.pose.pose.orientation.z)
    humans = {t.child_frame_id for m in tf for t in m.transforms if t.header.frame_id == "map"}
    assert humans == {"human_h1"}


def test_an_unknown_robot_fails_fast_with_one_line(ros):
    proc = ros.start(SIM, {"robot": "no_such_bot"}, capture=True)
    assert proc.wait(timeout=30) == 2
    err = proc.stderr.read().strip()
    assert err.startswith("error: sim_node: ") and "unknown robot 'no_such_bot'" in err and "\n" not in err


def test_with_the_estop_on_a_publisher_on_cmd_vel_beside_the_mux_moves_nothing_and_is_named(ros):
    """teleop_twist_keyboard publishes /cmd_vel by default (default QoS, depth 10): straight to the
    simulator, past the mux. With the e-stop on, the simulator itself stops the robot, and warns
    about the publisher by name; released, the same commands drive it again."""
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    keyboard = ros.node.create_publisher(Twist, "/cmd_vel", 10)
    estop = ros.node.create_publisher(Bool, "/haven/estop", qos.LATCHED)
    sim = ros.start(SIM, {"cmd_timeout_s": 20.0, "estop_hold_s": 1.0}, capture=True)
    ros.start(MUX, {"use_sim_time": True})
    ros.wait_matched(keyboard)
    ros.wait_for_messages(odom, 5)
    estop.publish(Bool(data=True))
    assert ros.spin_until(lambda: estop.get_subscription_count() >= 2)  # the mux and the simulator
    assert estop.wait_for_all_acked(Duration(seconds=5.0))
    start = conv.pose_from_msg(odom[-1].pose.pose)
    drive(ros, keyboard, twist(0.5, 0.0), odom, 2.0)
    moved = conv.pose_from_msg(odom[-1].pose.pose)
    assert math.hypot(moved.x - start.x, moved.y - start.y) < 0.01, (start, moved)
    said = stderr_of(sim)
    named = ("/haven_test_probe publishes on /cmd_vel beside the velocity mux", "cmd_vel:=cmd_vel_teleop")
    assert ros.spin_until(lambda: all(n in said() for n in named), 30.0), said()
    estop.publish(Bool(data=False))  # released once no true has come for estop_hold_s
    drive(ros, keyboard, twist(0.5, 0.0), odom, 3.0)
    assert conv.pose_from_msg(odom[-1].pose.pose).x - moved.x > 0.3


def test_an_estop_of_any_qos_stops_teleop_in_the_mux_and_the_simulator(ros):
    """A joystick or safety node often publishes its e-stop best effort; `ros2 topic pub` reliable
    and volatile; `haven` latched. Each holds the robot still while teleop (through the mux) and a
    keyboard node (on /cmd_vel, past the mux) ask it to turn, and nobody logs incompatible QoS."""
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    events = ros.collect(String, "/haven/events", qos.EVENTS)
    teleop = ros.node.create_publisher(Twist, "/cmd_vel_teleop", 10)
    keyboard = ros.node.create_publisher(Twist, "/cmd_vel", 10)
    sim = ros.start(SIM, {"cmd_timeout_s": 20.0, "estop_hold_s": 0.5}, capture=True)
    mux = ros.start(MUX, {"use_sim_time": True, "estop_hold_s": 0.5}, capture=True)
    for e in (teleop, keyboard, events):
        ros.wait_matched(e)
    ros.wait_for_messages(odom, 5)
    turn = twist(0.0, 1.0)
    best_effort = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    transient_best_effort = QoSProfile(
        depth=1, reliability=ReliabilityPolicy.BEST_EFFORT, durability=DurabilityPolicy.TRANSIENT_LOCAL
    )
    for name, profile in (
        ("best effort", best_effort),
        ("reliable", 10),
        ("latched", qos.LATCHED),
        ("best effort latched", transient_best_effort),
    ):
        estop = ros.node.create_publisher(Bool, "/haven/estop", profile)
        # the mux and the simulator
        assert ros.spin_until(lambda estop=estop: estop.get_subscription_count() >= 2, 15.0), name
        del events[:]

        def send(stop: bool, estop=estop):
            estop.publish(Bool(data=stop))
            teleop.publish(turn)
            keyboard.publish(turn)

        assert ros.spin_until(
            lambda: (send(True), ros.spin_for(0.05)) and odom[-1].twist.twist.angular.z == 0.0, 10.0
        ), name
        still = conv.pose_from_msg(odom[-1].pose.pose)
        stamp = conv.time_from_msg(odom[-1].header.stamp)
        while conv.time_from_msg(odom[-1].header.stamp) - stamp < 1.5:  # 1.5 s of sim time asking to turn at 1 rad/s
            send(True)
            ros.spin_for(0.05)
        assert abs(conv.pose_from_msg(odom[-1].pose.pose).yaw - still.yaw) < 0.02, name
        assert any(conv.event_from_msg(m).get("to") == "estop" for m in events), name  # the mux too
        # Released: a false, and no true for estop_hold_s; the same commands turn it again.
        assert ros.spin_until(
            lambda: (send(False), ros.spin_for(0.05)) and abs(odom[-1].twist.twist.angular.z) > 0.5, 15.0
        ), name
        ros.node.destroy_publisher(estop)
    for proc in (sim, mux):
        said = stderr_of(proc)()
        assert "incompatible QoS" not in said, said
