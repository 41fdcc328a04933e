"""`haven bridge`: a real WebSocket client lists the channels and decodes an Odometry and a MarkerArray."""

import asyncio
import json
import socket
import struct
import threading

import pytest
import websockets
from nav_msgs.msg import Odometry

from haven_scenarios.record.bag import TYPESTORE
from haven_sim.nodes import qos

pytestmark = pytest.mark.ros


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def connect(port):
    return websockets.connect(f"ws://127.0.0.1:{port}", subprotocols=["foxglove.sdk.v1", "foxglove.websocket.v1"])


async def frames(ws, timeout_s, done):
    """The server's frames until `done()` holds or `timeout_s` passes."""
    loop = asyncio.get_running_loop()
    deadline = loop.time() + timeout_s
    while loop.time() < deadline and not done():
        try:
            yield await asyncio.wait_for(ws.recv(), timeout=1.0)
        except TimeoutError:
            continue


async def fetch(port, topics, timeout_s=30.0, ready=lambda topic, msg: True):
    """Connect, wait for the channels, subscribe to `topics`, return (channels, {topic: the first
    decoded message for which `ready(topic, message)` holds})."""
    async with connect(port) as ws:
        channels, got, subs = {}, {}, {}
        async for frame in frames(ws, timeout_s, lambda: len(got) >= len(topics)):
            if isinstance(frame, str):
                msg = json.loads(frame)
                if msg.get("op") == "advertise":
                    for ch in msg["channels"]:
                        channels[ch["topic"]] = ch
                        if ch["topic"] in topics and ch["topic"] not in subs.values():
                            sub_id = len(subs) + 1
                            subs[sub_id] = ch["topic"]
                            await ws.send(
                                json.dumps(
                                    {"op": "subscribe", "subscriptions": [{"id": sub_id, "channelId": ch["id"]}]}
                                )
                            )
            elif frame[0] == 1:  # message data: opcode, subscription id, log time, payload
                sub_id, _ = struct.unpack_from("<IQ", frame, 1)
                topic = subs[sub_id]
                msg = TYPESTORE.deserialize_cdr(frame[13:], channels[topic]["schemaName"])
                if topic not in got and ready(topic, msg):
                    got[topic] = msg
        return channels, got


def test_a_websocket_client_sees_the_channels_and_decodes_messages(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    ros.start("haven_sim.nodes.sim_node", {"real_time_factor": 2.0})
    ros.start("haven_viz.nodes.viz_node", {"use_sim_time": True, "world": "small_test"})
    port = free_port()
    ros.start("haven_scenarios.nodes.bridge", {"port": port})
    ros.wait_for_messages(odom, 5)
    ros.spin_until(lambda: ros.node.count_subscribers("/haven/world_markers") > 0, 20)

    def ready(topic, msg):  # the cue markers come as deltas; the full set at least every 2 s
        return topic != "/haven/ar_markers" or "robot" in {m.ns for m in msg.markers}

    channels, got = asyncio.run(fetch(port, ["/odom", "/haven/ar_markers", "/haven/world_markers"], ready=ready))
    assert {"/odom", "/scan", "/map", "/haven/ar_markers", "/haven/world_markers"} <= set(channels)
    ch = channels["/odom"]
    assert (ch["encoding"], ch["schemaEncoding"], ch["schemaName"]) == ("cdr", "ros2msg", "nav_msgs/msg/Odometry")
    assert "MSG: std_msgs/Header" in ch["schema"]
    o = got["/odom"]
    assert o.child_frame_id == "base_footprint" and abs(o.pose.pose.position.x - 1.0) < 1e-6
    namespaces = {m.ns for m in got["/haven/ar_markers"].markers}
    assert "robot" in namespaces
    # The latched world markers reach this late client too.
    assert "walls" in {m.ns for m in got["/haven/world_markers"].markers}


def test_bridge_is_local_by_default():
    from haven_scenarios.tools.cli import build_parser

    args = build_parser().parse_args(["bridge"])
    assert args.host == "127.0.0.1" and args.port == 8765


async def foxglove_client(port, goal_cdr, goal_arrived, timeout_s=45.0):
    """As Foxglove's app does: read the server's capabilities and time, flip a cue toggle from the
    Parameters panel, publish a goal (allowed) and try a topic that is not. Stays connected until
    `goal_arrived` is set (a client that leaves at once may take its last message with it)."""
    async with connect(port) as ws:
        seen = {"values": [], "status": [], "time": []}
        info = None
        sent = False

        def done():
            # (the time: once it is the suite's; until the bridge has read /clock it sends 0)
            return (
                info
                and len(seen["values"]) >= 2
                and seen["status"]
                and seen["time"]
                and seen["time"][-1] > 0
                and goal_arrived.is_set()
            )

        async for frame in frames(ws, timeout_s, done):
            if isinstance(frame, bytes):
                if frame[0] == 2:  # time
                    seen["time"].append(struct.unpack_from("<Q", frame, 1)[0])
                continue
            msg = json.loads(frame)
            if msg["op"] == "serverInfo":
                info = msg
            elif msg["op"] == "parameterValues":
                seen["values"].append({p["name"]: p["value"] for p in msg["parameters"]})
            elif msg["op"] == "status":
                seen["status"].append(msg["message"])
            if info and not sent:
                sent = True
                await ws.send(json.dumps({"op": "getParameters", "parameterNames": [], "id": "get"}))
                await ws.send(
                    json.dumps(
                        {
                            "op": "setParameters",
                            "parameters": [{"name": "/viz.thought_bubble", "value": False}],
                            "id": "set",
                        }
                    )
                )
                channels = [
                    {"id": 1, "topic": "/goal_pose", "encoding": "cdr", "schemaName": "geometry_msgs/msg/PoseStamped"},
                    {"id": 2, "topic": "/cmd_vel", "encoding": "cdr", "schemaName": "geometry_msgs/msg/Twist"},
                ]
                await ws.send(json.dumps({"op": "advertise", "channels": channels}))
                await ws.send(b"\x01" + struct.pack("<I", 1) + goal_cdr)
        return info, seen


def test_foxglove_parameters_panel_toggles_a_cue_and_clients_publish_only_the_allow_list(ros):
    from geometry_msgs.msg import PoseStamped
    from rclpy.parameter_client import AsyncParameterClient
    from rclpy.serialization import serialize_message

    goals = ros.collect(PoseStamped, "/goal_pose", qos.RELIABLE)
    ros.start("haven_sim.nodes.sim_node", {"real_time_factor": 2.0})
    ros.start("haven_viz.nodes.viz_node", {"use_sim_time": True, "world": "small_test"})
    port = free_port()
    ros.start("haven_scenarios.nodes.bridge", {"port": port})
    viz = AsyncParameterClient(ros.node, "viz")
    assert ros.spin_until(lambda: viz.services_are_ready() and ros.node.count_subscribers("/clock") >= 2, 30)
    goal = PoseStamped()
    goal.header.frame_id = "map"
    goal.pose.position.x, goal.pose.position.y, goal.pose.orientation.w = 2.0, 3.0, 1.0
    goal_arrived, answer = threading.Event(), {}
    client = threading.Thread(
        target=lambda: answer.update(r=asyncio.run(foxglove_client(port, bytes(serialize_message(goal)), goal_arrived)))
    )
    client.start()
    try:
        ros.wait_for_messages(goals, 1, timeout_s=30.0)
    finally:
        goal_arrived.set()
        client.join(60)
    info, seen = answer["r"]
    assert {"parameters", "clientPublish", "time"} <= set(info["capabilities"])
    assert seen["values"][0]["/viz.thought_bubble"] is True and seen["values"][1]["/viz.thought_bubble"] is False
    assert any("may not publish on /cmd_vel" in s for s in seen["status"])  # refused: not on the allow-list
    assert seen["time"][-1] > 0  # the suite's sim time
    future = viz.get_parameters(["thought_bubble"])
    ros.spin_until(future.done, 10)
    assert future.result().values[0].bool_value is False  # the viz node's own parameter changed
    assert (goals[0].pose.position.x, goals[0].pose.position.y) == (2.0, 3.0)


def test_start_up_parameters_are_read_only_and_lists_are_string_arrays_even_when_empty(ros):
    """As rqt_reconfigure, Foxglove and `ros2 param` see them: what a node reads once at start-up is
    read-only (not offered for editing); an empty list is a string array, not a byte array."""
    from rcl_interfaces.msg import ParameterType
    from rclpy.parameter_client import AsyncParameterClient

    ros.start("haven_sim.nodes.sim_node", {"real_time_factor": 2.0})
    ros.start("haven_scenarios.nodes.bridge", {"port": 0})
    for node, names in (
        ("sim_node", ["lockstep_participants", "real_time_factor"]),
        ("haven_bridge", ["topics", "port"]),
    ):
        client = AsyncParameterClient(ros.node, node)
        assert ros.spin_until(client.services_are_ready, 30), node
        described, got = client.describe_parameters(names), client.get_parameters(names[:1])
        assert ros.spin_until(lambda described=described, got=got: described.done() and got.done(), 10)
        assert [d.read_only for d in described.result().descriptors] == [True, True], node
        assert described.result().descriptors[0].type == ParameterType.PARAMETER_STRING_ARRAY, node
        value = got.result().values[0]
        assert (value.type, list(value.string_array_value)) == (ParameterType.PARAMETER_STRING_ARRAY, []), node
