"""The study's web door without ROS or a browser: roles, tokens, the pages' settings, the
WebSocket pass-through, the researcher's interventions and the start gate, and the committed
bundles (rebuilt from the sources and the npm lock file where npm is installed)."""

import filecmp
import http.client
import json
import shutil
import socket
import struct
import subprocess
import threading
import time
from pathlib import Path

import pytest

from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.web.access import CONSOLE, READY, door_key, role_token, roles, route, token_of, token_ok, urls
from haven_scenarios.web.door_hello import DOOR_TOPIC, hello_messages
from haven_scenarios.web.front_door import STATIC, FrontDoor
from haven_scenarios.web.page_config import PageSettings, page_config, robot_view
from haven_scenarios.web.wizard import DEFAULT_HOLD_S, MAX_THOUGHT_CHARS, StartGate, Wizard
from haven_sim.common.events import MAX_EVENT_BYTES, EventKind
from haven_sim.common.geometry import Twist2D
from haven_sim.robots.robot_kind import resolve_robot
from haven_viz.wizard_thought import WizardThought

pytestmark = pytest.mark.integration

WEB = Path(__file__).resolve().parents[1] / "web"


def test_each_page_may_publish_only_what_its_role_allows():
    r = roles(["h1", "h2"])
    assert r["h1"].may_publish("/humans/h1/cmd_vel", "geometry_msgs/msg/Twist") is None
    assert r["h1"].may_publish(READY, "std_msgs/msg/String") is None
    assert "may not publish on /humans/h2/cmd_vel" in r["h1"].may_publish(
        "/humans/h2/cmd_vel", "geometry_msgs/msg/Twist"
    )
    assert "may not publish on /cmd_vel_teleop" in r["h1"].may_publish("/cmd_vel_teleop", "geometry_msgs/msg/Twist")
    assert r["h1"].may_publish("/humans/h1/cmd_vel", "geometry_msgs/msg/TwistStamped") == (
        "/humans/h1/cmd_vel takes geometry_msgs/msg/Twist, not geometry_msgs/msg/TwistStamped"
    )
    console = r[CONSOLE]
    assert console.parameters and not r["h1"].parameters
    allowed = {
        "/cmd_vel_teleop": "geometry_msgs/msg/Twist",
        "/haven/wizard_thought": "std_msgs/msg/String",
        "/haven/trial_control": "std_msgs/msg/String",
    }
    for topic, kind in allowed.items():
        assert console.may_publish(topic, kind) is None
    assert console.may_publish("/cmd_vel", "geometry_msgs/msg/Twist") is not None  # never around the mux


@pytest.mark.parametrize("bad", ["../x", "console", "a b", ""])
def test_a_human_id_that_cannot_name_a_page_is_refused(bad):
    with pytest.raises(ValueError, match="cannot name a participant page"):
        roles([bad])


def test_routes_and_tokens():
    assert (route("/participant/h1?token=x").kind, route("/participant/h1").role) == ("page", "h1")
    assert (route("/ws/console?token=x").kind, route("/ws/participant/h2").role) == ("socket", "h2")
    assert route("/static/participant.js").rest == "participant.js"
    assert (
        route("/static/../secret").kind == ""
        and route("/static/.hidden").kind == ""
        and route("/etc/passwd").kind == ""
    )
    assert token_of({"token": "abc"}, {}, CONSOLE) == "abc"
    assert token_of({}, {"a": "1", "haven_token_console": "abc"}, CONSOLE) == "abc"
    assert (
        token_of({}, {"a": "1", "haven_token_h1": "abc"}, CONSOLE) == ""
    )  # a participant's cookie is not the console's
    assert token_ok("abc", "abc") and not token_ok("", "abc") and not token_ok("abd", "abc")
    assert urls("http://h:1", "S", ["h1"]) == {
        "h1": f"http://h:1/participant/h1?token={role_token('S', 'h1')}",
        CONSOLE: f"http://h:1/console?token={role_token('S', CONSOLE)}",
    }
    assert len({role_token("S", "h1"), role_token("S", "h2"), role_token("S", CONSOLE), role_token("T", "h1")}) == 4


def test_a_page_is_told_its_role_the_pose_order_and_how_to_encode_what_it_sends():
    scenario = load_scenario("hallway")
    c = page_config(roles(["h1"])["h1"], scenario, PageSettings(participant="p07"))
    assert c["humans"] == ["h1"] and c["role"] == "h1" and not c["console"] and c["participant"] == "p07"
    assert c["schemas"]["geometry_msgs/msg/Twist"].startswith("geometry_msgs/Vector3 linear")
    assert c["eye_height_m"] == 1.6 and c["kind"] == "hallway" and "rooms" in c["instructions"]
    x0, y0, x1, y1 = c["bounds"]
    assert x0 < x1 and y0 < y1


def test_a_page_is_told_the_trials_robot_its_look_footprint_and_flight(tmp_path):
    scenario = load_scenario("hallway")
    tb2 = page_config(roles(["h1"])["h1"], scenario, PageSettings())["robot"]
    assert (tb2["name"], tb2["kinematics"], tb2["footprint"], tb2["flight_height_m"], tb2["model_url"]) == (
        "turtlebot2", "diff_drive", {"radius_m": 0.177, "polygon": []}, None, None,
    )  # fmt: skip
    assert len(tb2["primitives"]) == len(scenario.robot.look.primitives) > 0
    assert tb2["primitives"][0] == {
        "shape": "cylinder",
        "size": [0.177, 0.177, 0.09],
        "at": [0, 0, 0.055],
        "rpy": [0, 0, 0],
        "colour": "#2b2b2e",
        "spin": False,
    }
    (tmp_path / "model.glb").write_bytes(b"glTF")
    (tmp_path / "drone.yaml").write_text(
        "extends: turtlebot2\nname: drone\ntitle: D\nkinematics: aerial\n"
        "footprint: {polygon: [[0.2, 0.1], [-0.2, 0.1], [0, -0.2]]}\n"
        "flight: {cruise_height_m: 1.5, climb_rate_mps: 0.5}\nlook: {model: model.glb}\n"
    )
    drone = robot_view(resolve_robot(str(tmp_path / "drone.yaml")))
    assert drone["footprint"]["polygon"] == [[0.2, 0.1], [-0.2, 0.1], [0, -0.2]] and drone["flight_height_m"] == 1.5
    assert drone["model_url"] == "/robot/model.glb" and abs(drone["radius_m"] - 0.2236) < 1e-3


class EchoBackend:
    """A stand-in for a role's Foxglove server (a real WebSocket server, the `websockets` library's):
    records the upgrade request and every message, and answers each after the door's hello (its
    first three) with it upper-cased."""

    def __init__(self, tls=None) -> None:
        from websockets.sync.server import serve

        self.request = None
        self.received = []
        self.server = serve(self._serve, "127.0.0.1", 0, subprotocols=["foxglove.sdk.v1"], max_size=None, ssl=tls)
        self.port = self.server.socket.getsockname()[1]
        threading.Thread(target=self.server.serve_forever, daemon=True).start()

    def _serve(self, ws) -> None:
        self.request = ws.request
        for message in ws:
            self.received.append(message)
            if len(self.received) > len(hello_messages("")):
                ws.send(message.upper())

    def close(self) -> None:
        self.server.shutdown()


SECRET = "secret"
H1, CON = role_token(SECRET, "h1"), role_token(SECRET, CONSOLE)


@pytest.fixture
def door():
    backend = EchoBackend()
    d = FrontDoor(
        "127.0.0.1",
        0,
        SECRET,
        {"h1": backend.port, CONSOLE: backend.port},
        lambda role: {"role": role, "x": "</script>"},
    )
    d.start()
    yield d, backend
    d.stop()
    backend.close()


def _get(door, path, headers=None):
    c = http.client.HTTPConnection("127.0.0.1", door.port, timeout=5)
    c.request("GET", path, headers=headers or {})
    r = c.getresponse()
    return r.status, r.read(), r


def test_nothing_is_served_without_the_token(door):
    d, _ = door
    for path in ("/participant/h1", "/console?token=wrong", "/static/participant.js", "/ws/participant/h1"):
        status, body, _ = _get(d, path)
        assert status == 403 and b"token" in body, path
    assert _get(d, f"/participant/h9?token={H1}")[0] == 404  # not a participant of this trial
    # A participant's token opens their page only: not the console, not its socket.
    assert _get(d, f"/console?token={H1}")[0] == 403
    assert _get(d, "/console", {"Cookie": f"haven_token_h1={H1}"})[0] == 403
    assert _get(d, f"/ws/console?token={H1}", {"Upgrade": "websocket"})[0] == 403
    assert _get(d, "/favicon.ico")[0] == 204


def test_the_trials_robot_model_is_served_to_a_page_with_a_token_and_nothing_else_is(tmp_path):
    (tmp_path / "bot.glb").write_bytes(b"glTF-bytes")
    d = FrontDoor("127.0.0.1", 0, SECRET, {"h1": 1}, lambda role: {}, robot_model=str(tmp_path / "bot.glb"))
    d.start()
    try:
        assert _get(d, "/robot/model.glb")[0] == 403
        status, body, r = _get(d, "/robot/model.glb", {"Cookie": f"haven_token_h1={H1}"})
        assert (status, body, r.getheader("Content-Type")) == (200, b"glTF-bytes", "model/gltf-binary")
        for other in ("/robot/model.gltf", "/robot/bot.glb", "/robot/../bot.glb"):
            assert _get(d, f"{other}?token={H1}")[0] == 404, other
    finally:
        d.stop()


def test_a_page_comes_with_its_settings_and_a_cookie_for_its_code(door):
    d, _ = door
    status, body, r = _get(d, f"/participant/h1?token={H1}")
    assert status == 200 and b'"role": "h1"' in body and b'</script>"' not in body  # escaped inside the page
    cookie = r.getheader("Set-Cookie")
    assert cookie.startswith(f"haven_token_h1={H1};") and "HttpOnly" in cookie
    status, js, r = _get(d, "/static/participant.js", {"Cookie": f"haven_token_h1={H1}"})
    assert status == 200 and r.getheader("Content-Type") == "text/javascript" and len(js) > 100_000


def test_a_socket_with_the_token_is_relayed_message_for_message(door):
    from websockets.sync.client import connect

    d, backend = door
    url = f"ws://127.0.0.1:{d.port}/ws/participant/h1?token={H1}"
    cookie = {"Cookie": f"haven_token_h1={H1}"}
    with connect(url, subprotocols=["foxglove.sdk.v1"], additional_headers=cookie, open_timeout=30) as page:
        assert page.subprotocol == "foxglove.sdk.v1"  # the role server's choice, passed on
        page.send(b"frame bytes")
        assert page.recv(timeout=30) == b"FRAME BYTES"
        page.send('{"op": "subscribe"}')
        assert page.recv(timeout=30) == '{"OP": "SUBSCRIBE"}'
    # The role's server heard the door's hello first (web/door_hello.py), then the page's messages as sent.
    advertise, hello, unadvertise, *rest = backend.received
    assert rest == [b"frame bytes", '{"op": "subscribe"}']
    channel = json.loads(advertise)["channels"][0]
    assert channel["topic"] == DOOR_TOPIC
    assert hello == struct.pack("<BI", 1, channel["id"]) + door_key(SECRET, "h1").encode()
    assert json.loads(unadvertise) == {"op": "unadvertise", "channelIds": [channel["id"]]}
    assert backend.request.path == "/" and "Cookie" not in backend.request.headers
    assert backend.request.headers["Sec-WebSocket-Protocol"] == "foxglove.sdk.v1"


def test_clients_that_leave_mid_request_or_send_their_headers_slowly_cost_no_traceback(capfd):
    backend = EchoBackend()
    d = FrontDoor(
        "127.0.0.1", 0, SECRET, {"h1": backend.port, CONSOLE: backend.port}, lambda role: {}, request_timeout_s=0.3
    )
    d.start()
    try:
        for k in range(60):  # half a request, then gone (the reply meets a closed socket), or a reset
            with socket.create_connection(("127.0.0.1", d.port), timeout=5) as s:
                s.sendall(b"GET /console HTTP/1.1\r\nHost: x\r\n" + (b"\r\n" if k % 2 else b""))
                if k % 3 == 0:
                    s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))  # RST on close
        slow = [socket.create_connection(("127.0.0.1", d.port), timeout=5) for _ in range(20)]
        for s in slow:
            s.sendall(b"GET /console HTTP/1.1\r\n")  # and never the rest
        assert _get(d, "/favicon.ico")[0] == 204  # the door still answers everyone else
        for s in slow:  # each is cut off once its headers are overdue
            assert s.recv(100) == b""
            s.close()
    finally:
        d.stop()  # (returns once the server's thread has ended: all it would say is said)
        backend.close()
    err = capfd.readouterr().err
    assert "Traceback" not in err and "Error" not in err, err[:2000]


def test_a_client_advertising_thousands_of_channels_is_cut_off_after_a_few_and_said_once():
    """One advertise frame of 10,000 channels from a page with a valid token: the relay asks the
    role about the first MAX_CHANNELS_PER_CLIENT, ignores the rest at once, tells the clients once;
    another client of the same role is served as before."""
    from types import SimpleNamespace

    from haven_scenarios.web.foxglove_relay import MAX_CHANNELS_PER_CLIENT, FoxgloveRelay, _Listener

    asked, said, statuses = [], [], []

    class Sink:
        def advertised(self, topic, schema_name):
            asked.append(topic)
            return None if topic == "/humans/h1/cmd_vel" else f"may not publish on {topic}"

        def refused_client(self, why):
            said.append(why)

        def message(self, topic, schema_name, data):
            pass

    listener = _Listener(FoxgloveRelay(), Sink())
    listener.server = SimpleNamespace(publish_status=lambda message, level: statuses.append(message))
    hostile, page = SimpleNamespace(id=1), SimpleNamespace(id=2)
    for k in range(10_000):
        listener.on_client_advertise(hostile, SimpleNamespace(id=k, topic=f"/t{k}", schema_name="std_msgs/msg/String"))
    assert len(asked) == MAX_CHANNELS_PER_CLIENT and len(said) == 1 and len(statuses) == 1
    listener.on_client_advertise(
        page, SimpleNamespace(id=0, topic="/humans/h1/cmd_vel", schema_name="geometry_msgs/msg/Twist")
    )
    assert listener.accepted[(2, 0)] == ("/humans/h1/cmd_vel", "geometry_msgs/msg/Twist")


def said(text, hold_s=None, everywhere=None):
    """The console's thought message."""
    return json.dumps(
        {
            "text": text,
            **({} if hold_s is None else {"hold_s": hold_s}),
            **({} if everywhere is None else {"everywhere": everywhere}),
        }
    )


def test_a_thought_longer_than_the_logs_limit_or_held_wrong_is_refused_with_the_limit():
    w = Wizard()
    with pytest.raises(ValueError, match=f"at most {MAX_THOUGHT_CHARS}"):
        w.thought(said("x" * (MAX_THOUGHT_CHARS + 1)), 1.0)
    # the longest allowed, in the widest escapes, fits an event
    _, (e,) = w.thought(said("\U0001f600" * MAX_THOUGHT_CHARS), 1.0)
    assert len(e.to_json()) < MAX_EVENT_BYTES
    for bad, words in [
        ("plain text", "not JSON"),
        ("[]", "must be"),
        (said("hi", -1), "hold_s must be 0..3600"),
        (said("hi", True), "hold_s"),
    ]:
        with pytest.raises(ValueError, match=words):
            w.thought(bad, 1.0)


def test_the_researchers_driving_and_thought_text_are_events_and_the_text_is_held():
    w = Wizard()
    held, (e,) = w.thought(said("I will wait here", 20, True), 1.0)
    assert (e.kind, e["action"], e["text"], e["hold_s"], e["everywhere"], e["by"]) == (
        EventKind.INTERVENTION,
        "thought",
        "I will wait here",
        20.0,
        True,
        "researcher",
    )
    assert WizardThought.from_json(held.to_json()) == WizardThought("I will wait here", 21.0, True)
    assert w.thought(said("hm"), 5.0)[0] == WizardThought("hm", 5.0 + DEFAULT_HOLD_S, False)
    assert [e["action"] for e in w.drive(Twist2D(0.2, 0.0, 0.0), 2.0)] == ["drive"]
    assert w.drive(Twist2D(0.3, 0.0, 0.1), 2.1) == []  # one event per stretch of driving
    assert [e["action"] for e in w.drive(Twist2D(0.0, 0.0, 0.0), 3.0)] == ["drive_end"]


def test_the_trial_starts_when_every_participant_is_ready_unless_the_researcher_starts_it():
    gate = StartGate(["h1", "h2"])
    events, start = gate.ready("h1", 1.0)
    assert [e.kind for e in events] == [EventKind.PARTICIPANT_READY] and not start
    assert gate.ready("h9", 1.5) == ([], False)
    assert gate.ready("h2", 2.0)[1] is True
    assert gate.ready("h2", 3.0) == ([], False)
    assert StartGate(["h1"], researcher_only=True).ready("h1", 1.0)[1] is False


def test_the_committed_bundles_are_what_the_sources_build(tmp_path):
    """The pages' code ships built (users need no Node); rebuilding gives the same bytes."""
    if shutil.which("node") is None or not (WEB / "node_modules" / "esbuild").exists():
        pytest.skip("no Node.js or no haven_scenarios/web/node_modules (scripts/setup.sh runs npm ci where npm exists)")
    subprocess.run(["node", "build.mjs", "--out", str(tmp_path)], cwd=WEB, check=True, timeout=120)
    built = sorted(p.name for p in tmp_path.iterdir())
    assert built == ["console.js", "editor.js", "instruments.js", "participant.js", "participant.js.LEGAL.txt"]
    _, mismatch, errors = filecmp.cmpfiles(tmp_path, Path(str(STATIC)), built, shallow=False)
    assert mismatch == errors == [], "the committed bundles are stale: run `node build.mjs` in haven_scenarios/web"
    assert json.loads((WEB / "package-lock.json").read_text())["lockfileVersion"] >= 3


class _RoleSink:
    """What a role's server was sent (a stand-in for the web node's RoleSink)."""

    def __init__(self):
        self.messages, self.refusals, self.parameter_sets = [], [], []

    def advertised(self, topic, schema_name):
        return None

    def refused_client(self, why):
        self.refusals.append(why)

    def message(self, topic, schema_name, data):
        self.messages.append((topic, bytes(data)))

    def get_parameters(self, names):
        return []

    def set_parameters(self, parameters):
        self.parameter_sets.append(parameters)
        return parameters


def _publish_and_set(ws, text):
    """What a client would do to drive the robot and change a cue: advertise, send, set a parameter."""
    channel = {"id": 1, "topic": "/cmd_vel_teleop", "encoding": "cdr", "schemaName": "geometry_msgs/msg/Twist"}
    ws.send(json.dumps({"op": "advertise", "channels": [channel]}))
    ws.send(struct.pack("<BI", 1, 1) + text)
    ws.send(json.dumps({"op": "setParameters", "parameters": [{"name": "viz.path_projection", "value": False}]}))


def test_only_connections_through_the_front_door_reach_a_role_server():
    """Real Foxglove servers behind the real door: a page's socket through the door publishes and sets
    parameters; a client that connects to the server's port directly is served nothing and its
    connection is closed (the guard's sweep), whatever it sends first."""
    from websockets.exceptions import ConnectionClosed, InvalidHandshake
    from websockets.sync.client import connect

    from haven_scenarios.web.door_hello import BackendGuard
    from haven_scenarios.web.foxglove_relay import DoorCheck, FoxgloveRelay

    relay, guard, sink = FoxgloveRelay(), BackendGuard(), _RoleSink()
    server = relay.serve(
        "127.0.0.1", 0, "haven console", sink, parameters=True, door=DoorCheck(door_key(SECRET, CONSOLE), guard.sweep)
    )
    d = FrontDoor("127.0.0.1", 0, SECRET, {CONSOLE: server.port}, lambda role: {}, guard=guard)
    d.start()
    try:
        # Closed by the server (a limit, not a wait): after its first requests, or during its handshake
        # already where the periodic sweep comes first (a busy machine).
        with (
            pytest.raises((ConnectionClosed, InvalidHandshake, EOFError, ConnectionError)),
            connect(f"ws://127.0.0.1:{server.port}/", subprotocols=["foxglove.sdk.v1"], open_timeout=30) as direct,
        ):
            _publish_and_set(direct, b"direct")
            while True:
                direct.recv(timeout=60)
        deadline = time.monotonic() + 60
        while guard.cut < 1 and time.monotonic() < deadline:  # (the sweeping thread counts just after the shutdown)
            time.sleep(0.01)
        assert guard.cut >= 1 and all("did not come through the front door" in r for r in sink.refusals), sink.refusals
        with connect(
            f"ws://127.0.0.1:{d.port}/ws/console?token={CON}", subprotocols=["foxglove.sdk.v1"], open_timeout=30
        ) as page:
            _publish_and_set(page, b"through the door")
            deadline = time.monotonic() + 60
            while not (sink.messages and sink.parameter_sets) and time.monotonic() < deadline:
                time.sleep(0.01)
        assert sink.messages == [("/cmd_vel_teleop", b"through the door")]  # the direct client's never arrived
        assert len(sink.parameter_sets) == 1
        with (
            # the periodic sweep closes it too
            pytest.raises((ConnectionClosed, InvalidHandshake, EOFError, ConnectionError)),
            # asks for nothing
            connect(f"ws://127.0.0.1:{server.port}/", subprotocols=["foxglove.sdk.v1"], open_timeout=30) as lurker,
        ):
            while True:
                lurker.recv(timeout=60)
    finally:
        d.stop()
        relay.stop()
