"""The study in a real browser: `haven run --web` with headless Chromium (software WebGL).

A participant page and the researcher console against a running suite: the scene loads (waited on
by page state, never by time), W walks the avatar (seen on /humans), walking up to the robot shows
its thought bubble in the rendered pixels, a lab's installed cue is drawn and is a console toggle,
a cue toggled in the console leaves the participant's view and is recorded, the researcher's Stop
ends the trial, and nothing is served without the token.
Two participants (one through the machine's network address) see each other, Enter VR works
with an emulated headset, and a participant sees the flying drone's NavPoints, Arrow and Gaze. Skipped, with one line,
where no Chromium can be had.
"""

import csv
import http.client
import json
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import threading
import time
from io import BytesIO
from urllib.parse import urlsplit

import pytest
from ros_harness import tracebacks
from test_example_plugins import installed

pytestmark = [pytest.mark.ros, pytest.mark.browser]
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
PAGE_TIMEOUT_MS = 90_000  # software rendering on a loaded 2-core machine is slow to start
PAGE_LOAD_MS = 120_000  # a limit, not a wait: on a loaded 2-core machine a page took over 30 s to load
WEB_SOURCES = os.path.join(os.path.dirname(__file__), "..", "web")


def hallway_world(tmp_path, humans):
    """The hallway world with these humans ({id: start}) in place of its own."""
    from importlib import resources

    world = (resources.files("haven_scenarios") / "worlds" / "hallway.yaml").read_text()
    listed = "".join(f'  - {{"id": "{h}", "start": {list(start)}}}\n' for h, start in humans.items())
    world = world.replace('  - {"id": "h1", "start": [16.0, 16.0, 3.14159]}\n', listed)
    (tmp_path / "world.yaml").write_text(world)
    return "world.yaml"


def head_on_scenario(tmp_path):
    """The hallway with the participant 6 m ahead of the robot, facing it, so walking forward
    brings them within the thought bubble's 3 m."""
    world = hallway_world(tmp_path, {"h1": (8.0, 2.0, 3.14159)})
    path = tmp_path / "head_on.yaml"
    path.write_text(
        f"name: head_on\nworld: {world}\nkind: hallway\ntimeout_s: 300\nrobot: {{route: [B, A]}}\n"
        "humans: [{id: h1, model: walker, route: [A, B], speed_mps: 1.0}]\n"
    )
    return path


class WebTrial:
    """`haven run ... --web` in the background; its output collected, its URLs parsed."""

    def __init__(self, ros, argv, env=None):
        self.proc = subprocess.Popen(
            [*HAVEN, *argv, "--domain-id", str(ros.domain_id)],
            env=env or ros.env,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            start_new_session=True,
        )
        ros.procs.append(self.proc)
        self.lines: list[str] = []
        self.reader = threading.Thread(
            target=lambda: self.lines.extend(iter(self.proc.stdout.readline, "")), daemon=True
        )
        self.reader.start()

    def ended(self, timeout_s=120):
        """The exit code, once the process has ended and all it printed has been read."""
        code = self.proc.wait(timeout=timeout_s)
        self.reader.join(timeout=timeout_s)
        return code

    def urls(self, timeout_s=90, pages=2):
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            found = dict(re.findall(r"web: (participant \w+|researcher console): (\S+)", "".join(self.lines)))
            if len(found) == pages:
                return found
            assert self.proc.poll() is None, "".join(self.lines)[-3000:]
            time.sleep(0.1)
        raise AssertionError("no URLs printed:\n" + "".join(self.lines)[-3000:])

    def session(self):
        (line,) = [ln for ln in self.lines if ln.startswith("haven: session in ")]
        return line.split(" in ", 1)[1].split(" (")[0]


def descendants(pid):
    """`pid`'s processes below it (from /proc's parent pids)."""
    children = {}
    for p in (p for p in os.listdir("/proc") if p.isdigit()):
        try:
            with open(f"/proc/{p}/stat") as f:
                children.setdefault(int(f.read().rsplit(")", 1)[1].split()[1]), []).append(int(p))
        except (OSError, IndexError, ValueError):
            continue
    out, todo = [], list(children.get(pid, []))
    while todo:
        p = todo.pop()
        out.append(p)
        todo += children.get(p, [])
    return out


def listening_ports(parent, module):
    """The TCP ports on 127.0.0.1 a node of this trial (by its module in the command line, below the
    `haven run` process `parent`) listens on, read from /proc (proc(5)): the process's socket inodes
    matched against the kernel's LISTEN rows."""
    pids = []
    for p in descendants(parent):
        try:
            with open(f"/proc/{p}/cmdline", "rb") as f:
                if module in f.read().decode(errors="replace"):
                    pids.append(p)
        except OSError:
            continue
    ports = set()
    for pid in pids:
        inodes = set()
        for fd in os.listdir(f"/proc/{pid}/fd"):
            try:
                inodes.add(os.readlink(f"/proc/{pid}/fd/{fd}"))
            except OSError:
                continue
        with open(f"/proc/{pid}/net/tcp") as tcp:
            rows = tcp.read().splitlines()[1:]
        for row in rows:
            f = row.split()
            if f[3] == "0A" and f[1].startswith("0100007F:") and f"socket:[{f[9]}]" in inodes:  # LISTEN on 127.0.0.1
                ports.add(int(f[1].split(":")[1], 16))
    return ports


def read_json(path):
    """A session file's JSON (session.json, metrics.json, questionnaires.json)."""
    with open(path) as f:
        return json.load(f)


def read_events(path):
    """An events.jsonl file's events, in order."""
    with open(path) as f:
        return [json.loads(line) for line in f]


def cdr_string(text):
    """A std_msgs/String in CDR (little-endian encapsulation), as a page would send it."""
    data = text.encode() + b"\0"
    return b"\x00\x01\x00\x00" + struct.pack("<I", len(data)) + data


def try_the_backends_directly(ports):
    """Connect to each page server's port, skipping the door, and try what the console may do: start
    and stop the trial, switch a cue off. Each connection must be closed by the server: during its
    handshake already (the guard's sweep came first, as on a busy machine), or after the first requests."""
    from websockets.exceptions import ConnectionClosed, InvalidHandshake
    from websockets.sync.client import connect

    for port in ports:
        with (
            # (not a recv timeout: the server closes it)
            pytest.raises((ConnectionClosed, InvalidHandshake, EOFError, ConnectionError)),
            connect(f"ws://127.0.0.1:{port}/", subprotocols=["foxglove.sdk.v1"], open_timeout=30) as ws,
        ):
            channel = {"id": 1, "topic": "/haven/trial_control", "encoding": "cdr", "schemaName": "std_msgs/msg/String"}
            ws.send(json.dumps({"op": "advertise", "channels": [channel]}))
            ws.send(struct.pack("<BI", 1, 1) + cdr_string("stop"))
            ws.send(
                json.dumps({"op": "setParameters", "parameters": [{"name": "/viz.thought_bubble", "value": False}]})
            )
            while True:
                ws.recv(timeout=60)


def status_of(url):
    u = urlsplit(url)
    c = http.client.HTTPConnection(u.hostname, u.port, timeout=10)
    c.request(
        "GET", u.path + ("?" + u.query if u.query else ""), headers={"Upgrade": "websocket", "Connection": "Upgrade"}
    )
    return c.getresponse().status


def screenshot(name, png):
    """The pictures in the README and the docs: written where HAVEN_SCREENSHOTS points (haven_scenarios/doc to update
    them)."""
    folder = os.environ.get("HAVEN_SCREENSHOTS")
    if folder:
        with open(os.path.join(folder, name), "wb") as f:
            f.write(png)


def bubble_pixels(png, centre, half=40):
    """Near-white pixels (the bubble's label) around a screen point, and dark ones (its text) within
    the label's extent: the label is white at 0.9 over the scene (the sky is ~229), its text dark,
    and a small or distant label's text is anti-aliased to greys, so dark is below half-grey."""
    from PIL import Image

    img = Image.open(BytesIO(png)).convert("L")
    x, y = int(centre["x"]), int(centre["y"])
    crop = img.crop((max(0, x - half), max(0, y - half), x + half, y + half))
    white = crop.point(lambda v: 255 if v >= 243 else 0)
    box = white.getbbox()
    if box is None:
        return 0, 0
    return sum(crop.histogram()[243:]), sum(crop.crop(box).histogram()[:128])


def test_a_participant_walks_up_to_the_robot_and_the_researcher_runs_the_trial(ros, browser, tmp_path):
    from geometry_msgs.msg import PoseArray
    from rclpy.qos import QoSProfile

    scenario = head_on_scenario(tmp_path)
    lab = {**ros.env, "PYTHONPATH": installed(tmp_path)["PYTHONPATH"]}  # with a lab's cue installed: `all` has it too
    trial = WebTrial(
        ros,
        [
            "run",
            str(scenario),
            "--teleop",
            "h1",
            "--web",
            "--port",
            "0",
            "--condition",
            "all",
            "--sessions",
            str(tmp_path / "s"),
        ],
        lab,
    )
    urls = trial.urls()
    participant_url, console_url = urls["participant h1"], urls["researcher console"]

    # Nobody gets in without the token: not the page, not its socket.
    assert status_of(participant_url.split("?")[0]) == 403
    assert status_of(participant_url.replace("/participant/", "/ws/participant/").split("?")[0]) == 403

    page = browser.new_page(viewport={"width": 800, "height": 450})
    page.goto(participant_url, timeout=PAGE_LOAD_MS)
    page.wait_for_function(
        "s => (s = window.havenState) && s.world > 0 && s.pose && "
        "s.robot && s.trial && s.trial.state === 'held' && s.frames > 2",
        timeout=PAGE_TIMEOUT_MS,
    )
    assert page.evaluate("havenState.prompt") == "Welcome"
    console = browser.new_page(viewport={"width": 1100, "height": 600})
    console.goto(console_url, timeout=PAGE_LOAD_MS)
    console.wait_for_function("s => (s = window.havenState) && s.toggles && s.trial", timeout=PAGE_TIMEOUT_MS)

    # Around the door: each role's server on 127.0.0.1 refuses a connection that skipped it.
    backends = listening_ports(trial.proc.pid, "haven_scenarios.nodes.web_node") - {int(urlsplit(console_url).port)}
    assert len(backends) == 2, backends  # the console's and h1's
    try_the_backends_directly(backends)
    assert (
        console.evaluate("havenState.toggles.thought_bubble") is True
        and page.evaluate("havenState.trial.state") == "held"
    )

    page.click("#start")  # read the instructions, ready: the trial starts
    page.wait_for_function(
        "() => havenState.trial.state === 'running' && havenState.prompt === null", timeout=PAGE_TIMEOUT_MS
    )
    # The lab's cue (the example's floor arrows) is drawn with no page code of its own, and is a console toggle.
    page.wait_for_function("() => (havenState.markers.floor_arrows || 0) >= 1", timeout=PAGE_TIMEOUT_MS)
    console.wait_for_function(
        "() => (t => t && t.checked)(document.getElementById('cue-floor_arrows'))", timeout=PAGE_TIMEOUT_MS
    )

    # Before: 6 m apart, no bubble where it would be drawn.
    robot = page.evaluate("havenState.robot")
    before_spot = page.evaluate(f"havenProject({robot['x']}, {robot['y']}, 1.0)")
    before = page.screenshot()
    assert "thought_bubble" not in page.evaluate("havenState.markers")

    # Hold W: the avatar walks (its pose on /humans moves) towards the robot, which drives on towards
    # them until its thought bubble shows, 3 m away. (The walk is short, so that a busy machine's late
    # key-up cannot take the participant past the robot.)
    humans = ros.collect(PoseArray, "/humans", QoSProfile(depth=10))
    assert ros.spin_until(lambda: bool(humans), timeout_s=30)
    start_x = humans[-1].poses[0].position.x
    page.keyboard.down("KeyW")
    assert ros.spin_until(lambda: start_x - humans[-1].poses[0].position.x > 0.5, timeout_s=60), (
        "the avatar did not walk"
    )
    page.keyboard.up("KeyW")
    page.wait_for_function("() => (havenState.markers.thought_bubble || 0) >= 1", timeout=PAGE_TIMEOUT_MS)
    # The bubble in view, and where it is drawn, from one frame.
    spot = page.wait_for_function(
        "() => { const m = havenMarker('thought_bubble', 0); "
        f"return ({IN_VIEW})(m) && havenProject(m.x, m.y, m.z); }}",
        timeout=PAGE_TIMEOUT_MS,
    ).json_value()
    after = page.screenshot()
    screenshot("web_participant.png", after)
    assert 0 < spot["x"] < 800 and 0 < spot["y"] < 450 and spot["z"] < 1, spot
    white, dark = bubble_pixels(after, spot)
    white_before, _ = bubble_pixels(before, before_spot)
    assert white > 1000 and dark > 40 and white_before < 100, (
        "no thought bubble drawn where it should be",
        white,
        dark,
        white_before,
    )

    # The researcher switches the thought bubble off: it leaves the participant's view at once.
    console.uncheck("#cue-thought_bubble")
    page.wait_for_function("() => !havenState.markers.thought_bubble", timeout=PAGE_TIMEOUT_MS)
    console.wait_for_function("() => havenState.toggles.thought_bubble === false", timeout=PAGE_TIMEOUT_MS)

    screenshot("web_console.png", console.screenshot())

    # A console opened mid-trial has the whole study log, each event once.
    late = browser.new_page(viewport={"width": 1100, "height": 600})
    late.goto(console_url, timeout=PAGE_LOAD_MS)
    late.wait_for_function("() => havenState.events.some(e => e.type === 'participant_ready')", timeout=PAGE_TIMEOUT_MS)
    keys = late.evaluate("havenState.events.map(e => e.source + '/' + e.seq)")
    assert len(keys) == len(set(keys)) and "scenario/1" in keys

    # ... and stops the trial: the participant is told, the session is complete.
    console.click("#stop")
    page.wait_for_function("() => havenState.prompt === 'Trial over'", timeout=PAGE_TIMEOUT_MS)
    assert trial.ended() == 0, "".join(trial.lines)[-3000:]
    folder = trial.session()
    events = read_events(os.path.join(folder, "events.jsonl"))
    kinds = [(e["type"], e.get("cue"), e.get("on"), e.get("reason"), e.get("by")) for e in events]
    assert ("participant_ready", None, None, None, "h1") in kinds
    assert ("cue_toggled", "thought_bubble", False, None, None) in kinds
    assert ("trial_end", None, None, "stopped", "researcher") in kinds
    # (the direct connections' stop and cue change never happened: only the console's)
    assert [k for k in kinds if k[0] in ("trial_end", "cue_toggled")] == [
        ("cue_toggled", "thought_bubble", False, None, None),
        ("trial_end", None, None, "stopped", "researcher"),
    ]
    assert "did not come through the front door" in "".join(trial.lines)
    assert read_json(os.path.join(folder, "metrics.json"))["end_reason"] == "stopped"
    assert tracebacks("".join(trial.lines)) == []


IN_VIEW = """m => { if (!m) return false; const p = havenProject(m.x, m.y, m.z);
  return p.z < 1 && p.x > 0 && p.x < innerWidth && p.y > 0 && p.y < innerHeight; }"""


def test_a_participant_sees_the_flying_drone_with_its_navpoints_arrow_and_gaze(ros, browser, tmp_path):
    """`haven run shared_room --robot quadrotor --teleop h1 --web`: the participant starts facing
    the drone's pad; once it has taken off, its three intent cues of Walker et al. 2018 are drawn
    in the air, in view, and the participant walks among them."""
    trial = WebTrial(
        ros,
        [
            "run",
            "shared_room",
            "--robot",
            "quadrotor",
            "--teleop",
            "h1",
            "--web",
            "--port",
            "0",
            "--sessions",
            str(tmp_path / "s"),
        ],
    )
    urls = trial.urls()
    page = browser.new_page(viewport={"width": 960, "height": 540})
    page.goto(urls["participant h1"], timeout=PAGE_LOAD_MS)
    page.wait_for_function(
        "s => (s = window.havenState) && s.world > 0 && s.robot && s.trial && s.trial.state === 'held'",
        timeout=PAGE_TIMEOUT_MS,
    )
    page.click("#start")
    seen = (
        f"() => {{ const inView = {IN_VIEW}; const s = havenState;\n"
        "      return s.robot && s.robot.z > 1.2 && ['nav_points', 'arrow', 'gaze']"
        ".every(ns => inView(havenMarker(ns, ns === 'nav_points' ? 1 : 0))); }"
    )
    page.wait_for_function(seen, timeout=PAGE_TIMEOUT_MS)  # up at cruise height, its cues in front of the participant
    screenshot("web_drone.png", page.screenshot())
    drone = page.evaluate("havenState.robot")
    assert drone["z"] == pytest.approx(1.5, abs=0.3), drone  # it flies at its cruise height (the catalogue's 1.5 m)
    countdown = page.evaluate("havenMarker('nav_points', 2)")  # each NavPoint's arrival countdown, above it
    assert countdown is not None and countdown["z"] > 1.2
    x0 = page.evaluate("havenState.pose.x")
    page.keyboard.down("KeyW")
    page.wait_for_function(f"() => havenState.pose.x > {x0} + 0.3", timeout=PAGE_TIMEOUT_MS)  # walks toward the pad
    page.keyboard.up("KeyW")
    os.killpg(trial.proc.pid, signal.SIGINT)  # the researcher's Ctrl-C: the session is kept
    trial.ended()
    out = "".join(trial.lines)
    assert "haven: interrupted" in out and tracebacks(out) == [], out[-3000:]
    assert read_json(os.path.join(trial.session(), "metrics.json"))["robot"] == "quadrotor"


LIBRARY_CUES = ("path_line", "projected_arrows", "light_ring")


def test_a_participant_sees_the_library_cues_in_a_world_made_from_a_ros_map_whose_walls_hold(ros, browser, tmp_path):
    """A world from a map the test makes (map_maker.py: map_server PGM + YAML + overlay), with the
    cue library's three cues (condition path_line+projected_arrows+light_ring): the page draws the
    map's walls and each cue with no page code of its own, and the participant walking into the
    dividing wall is held by it (the walls are the simulator's too)."""
    from map_maker import make_map_world

    argv = [
        "run",
        str(make_map_world(tmp_path / "map")),
        "--teleop",
        "h1",
        "--web",
        "--port",
        "0",
        "--condition",
        *LIBRARY_CUES,
    ]
    trial = WebTrial(ros, [*argv, "--sessions", str(tmp_path / "s")])
    page = browser.new_page(viewport={"width": 960, "height": 540})
    page.goto(trial.urls()["participant h1"], timeout=PAGE_LOAD_MS)
    page.wait_for_function(
        "s => (s = window.havenState) && s.world > 0 && s.pose && s.trial && s.trial.state === 'held' && s.frames > 2",
        timeout=PAGE_TIMEOUT_MS,
    )
    page.click("#start")
    page.wait_for_function(
        "() => havenState.trial.state === 'running' && havenState.prompt === null", timeout=PAGE_TIMEOUT_MS
    )
    drawn = " && ".join(f"(havenState.markers.{ns} || 0) >= 1" for ns in LIBRARY_CUES)
    # on its way to the door
    page.wait_for_function(f"() => {drawn} && havenState.robot && havenState.robot.x > 2.0", timeout=PAGE_TIMEOUT_MS)
    # the dividing wall ahead, the robot coming through its door with the library cues
    screenshot("web_map_world.png", page.screenshot())
    page.keyboard.down("KeyW")  # from (5.5, 3.0) facing west: the dividing wall's east face is at x = 3.65
    page.wait_for_function("() => havenState.pose.x < 4.0", timeout=PAGE_TIMEOUT_MS)
    frames = page.evaluate("havenState.frames")
    page.wait_for_function(f"() => havenState.frames > {frames} + 20", timeout=PAGE_TIMEOUT_MS)  # still pressing on
    page.keyboard.up("KeyW")
    assert page.evaluate("havenState.pose.x") > 3.65 + 0.25 - 0.05  # the body (0.25 m) against the wall, not through it
    os.killpg(trial.proc.pid, signal.SIGINT)
    trial.ended()
    out = "".join(trial.lines)
    assert "haven: interrupted" in out and tracebacks(out) == [], out[-3000:]


def lan_address():
    """This machine's address on its network (not loopback), as another machine would use it."""
    import socket

    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.connect(("192.0.2.1", 9))  # no packet is sent: this only picks the outgoing interface
            address = s.getsockname()[0]
        except OSError:
            return None
    return None if address.startswith("127.") else address


def test_two_participants_one_from_the_network_see_each_other(ros, browser, tmp_path):
    address = lan_address()
    if address is None:
        pytest.skip("this machine has no network address besides loopback")
    trial = WebTrial(
        ros,
        [
            "run",
            "hallway_pair",
            "--teleop",
            "h1",
            "h2",
            "--web",
            "--host",
            "0.0.0.0",
            "--port",
            "0",
            "--sessions",
            str(tmp_path / "s"),
        ],
    )
    urls = trial.urls(pages=3)
    # The printed addresses are the machine's network address: h2 comes "from another machine"
    # through it, h1 sits at this one.
    remote = urls["participant h2"]
    assert urlsplit(remote).hostname == address
    local = urls["participant h1"].replace(f"://{address}:", "://localhost:")
    assert status_of(remote.split("?")[0]) == 403  # on the network, the token is all the more needed
    pages = {}
    for who, url in (("h1", local), ("h2", remote)):
        pages[who] = browser.new_page(viewport={"width": 480, "height": 270})
        pages[who].goto(url, timeout=PAGE_LOAD_MS)
    for page in pages.values():
        page.wait_for_function(
            "s => (s = window.havenState) && s.pose && s.others === 1 && s.trial && s.trial.state === 'held'",
            timeout=PAGE_TIMEOUT_MS,
        )
    pages["h1"].click("#start")
    assert pages["h2"].evaluate("havenState.trial.state") == "held"  # the trial waits for everyone
    pages["h2"].click("#start")
    for page in pages.values():
        page.wait_for_function("() => havenState.trial.state === 'running'", timeout=PAGE_TIMEOUT_MS)
    # h2 walks; h1 sees h2's avatar move.
    seen = pages["h1"].evaluate("havenOthers().h2")
    pages["h2"].keyboard.down("KeyW")
    pages["h1"].wait_for_function(f"() => havenOthers().h2.x > {seen['x'] + 0.5}", timeout=PAGE_TIMEOUT_MS)
    pages["h2"].keyboard.up("KeyW")


GAMEPAD = (
    "\n"
    'window.testPad = { id: "test pad", index: 0, connected: true, mapping: "standard", timestamp: 0, '
    "axes: [0, 0, 0, 0], buttons: [] };\n"
    "navigator.getGamepads = () => [window.testPad];\n"
)


def test_a_gamepad_walks_and_enter_vr_works_with_an_emulated_headset(ros, browser, tmp_path):
    """A gamepad (a stand-in behind the Gamepad API) walks the avatar; then WebXR with Meta's
    emulation runtime (iwer) standing in for a headset: Enter VR, the same scene is drawn in the
    session, and turning the head turns the participant's view."""
    if shutil.which("node") is None or not os.path.isdir(os.path.join(WEB_SOURCES, "node_modules", "iwer")):
        pytest.skip("no Node.js or no haven_scenarios/web/node_modules to build the emulated headset: XR test skipped")
    emulator = tmp_path / "xr_emulator.js"
    subprocess.run(["node", "build.mjs", "--xr-emulator", str(emulator)], cwd=WEB_SOURCES, check=True, timeout=120)
    trial = WebTrial(
        ros,
        [
            "run",
            str(head_on_scenario(tmp_path)),
            "--teleop",
            "h1",
            "--web",
            "--port",
            "0",
            "--sessions",
            str(tmp_path / "s"),
        ],
    )
    context = browser.new_context(viewport={"width": 480, "height": 270})
    context.add_init_script(path=str(emulator))
    context.add_init_script(GAMEPAD)
    page = context.new_page()
    page.goto(trial.urls()["participant h1"], timeout=PAGE_LOAD_MS)
    page.wait_for_function(
        "s => (s = window.havenState) && s.world > 0 && s.pose && s.xrOffered && s.trial && s.trial.state === 'held'",
        timeout=PAGE_TIMEOUT_MS,
    )
    page.click("#start")
    page.wait_for_function(
        "() => havenState.trial.state === 'running' && havenState.prompt === null", timeout=PAGE_TIMEOUT_MS
    )
    # A gamepad's left stick walks the avatar (the Gamepad API's standard mapping: up is -1).
    x0 = page.evaluate("havenState.pose.x")
    page.evaluate("window.testPad.axes[1] = -1")
    page.wait_for_function(f"() => havenState.pose.x < {x0} - 0.3", timeout=PAGE_TIMEOUT_MS)  # facing -x
    page.evaluate("window.testPad.axes[1] = 0")
    page.click("#enter-vr")
    page.wait_for_function("() => havenState.xr === true", timeout=PAGE_TIMEOUT_MS)
    frames = page.evaluate("havenState.frames")
    page.wait_for_function(f"() => havenState.frames > {frames + 3}", timeout=PAGE_TIMEOUT_MS)
    ahead = page.evaluate("havenState.view")
    # The participant faces -x (yaw pi); the headset turns 90 deg to the left about its up axis.
    page.evaluate("havenXrDevice.quaternion.set(0, Math.SQRT1_2, 0, Math.SQRT1_2)")
    page.wait_for_function("() => havenState.view.y < -0.9", timeout=PAGE_TIMEOUT_MS)
    assert ahead["x"] < -0.9, ahead  # before: straight down the hallway


def stopped_trial(ros, browser, tmp_path, questionnaires, viewport, argv=None):
    """`haven run --web --teleop h1 --questionnaire ...` (or `argv`): the participant starts, the
    researcher stops the trial (the console's text before it is kept as havenState.before)."""
    argv = argv or [
        "run",
        str(head_on_scenario(tmp_path)),
        "--teleop",
        "h1",
        "--web",
        "--port",
        "0",
        "--sessions",
        str(tmp_path / "s"),
    ]
    trial = WebTrial(ros, [*argv, *(["--questionnaire", *questionnaires] if questionnaires else [])])
    urls = trial.urls()
    page = browser.new_page(viewport=viewport)
    page.goto(urls["participant h1"], timeout=PAGE_LOAD_MS)
    page.wait_for_function(
        "s => (s = window.havenState) && s.world > 0 && s.trial && s.trial.state === 'held'", timeout=PAGE_TIMEOUT_MS
    )
    console = browser.new_page(viewport={"width": 1100, "height": 600})
    console.goto(urls["researcher console"], timeout=PAGE_LOAD_MS)
    console.wait_for_function("s => (s = window.havenState) && s.trial", timeout=PAGE_TIMEOUT_MS)
    console.evaluate("havenState.before = document.getElementById('questionnaires').textContent")
    page.click("#start")
    page.wait_for_function("() => havenState.trial.state === 'running'", timeout=PAGE_TIMEOUT_MS)
    console.click("#stop")
    return trial, page, console


def answer_with_clicks(page, q, values):
    for item, value in values.items():
        page.check(f'input[name="{q}.{item}"][value="{value}"]')


def submit_and_wait(page, q, answered):
    page.click("#questionnaire button[type=submit]")
    page.wait_for_function(
        f"() => havenState.answered.length === {answered} && havenState.questionnaire !== '{q}'",
        timeout=PAGE_TIMEOUT_MS,
    )


STUDY_YAML = """name: browser_study
scenarios: [head_on.yaml]
conditions: {signals: [turn_signals]}
participants: [p01]
counterbalancing: none
questionnaires:
  - nasa_tlx
  - {name: godspeed, shuffle: true}
  - name: legibility
    title: About the robot
    points: 7
    anchors: [Strongly disagree, Strongly agree]
    items:
      - {id: side, text: "I could tell which way the robot would pass me."}
      - {id: surprise, text: "The robot surprised me.", reverse: true}
"""


def test_a_study_participant_answers_the_questionnaires_in_the_page_and_the_report_has_them(ros, browser, tmp_path):
    """A study with nasa_tlx, godspeed (items mixed) and its own Likert items, run for p01 in the browser
    (`haven study run --web`): the researcher stops the trial; the page asks each questionnaire in
    turn (TLX by keyboard alone, the others by clicks), refuses Submit while an item is unanswered;
    the answers and scores land in questionnaires.json, the events and session.json; the study run
    then ends by itself, and `haven study report` has the scores in its tidy table."""
    from haven_scenarios.study.questionnaires import BUILTINS, score

    head_on_scenario(tmp_path)
    (tmp_path / "study.yaml").write_text(STUDY_YAML)
    argv = [
        "study",
        "run",
        str(tmp_path / "study.yaml"),
        "--participant",
        "p01",
        "--web",
        "--teleop",
        "h1",
        "--port",
        "0",
        "--no-pause",
    ]
    argv += ["--dir", str(tmp_path / "study")]
    trial, page, console = stopped_trial(ros, browser, tmp_path, [], {"width": 1000, "height": 700}, argv)
    assert console.evaluate("havenState.before") == "after the trial: nasa_tlx, godspeed, legibility"

    # The trial is over: the first questionnaire instead of "Thank you"; haven run waits.
    page.wait_for_function(
        "() => havenState.questionnaire === 'nasa_tlx' && havenState.prompt === null", timeout=PAGE_TIMEOUT_MS
    )
    console.wait_for_function(
        "() => document.getElementById('questionnaires').textContent === 'h1: questionnaire 1 of 3'",
        timeout=PAGE_TIMEOUT_MS,
    )
    assert console.is_visible("#skip-questionnaires")
    assert page.locator("#questionnaire input:checked").count() == 0  # nothing preselected
    assert (
        page.locator("#questionnaire fieldset").count() == 6
        and page.locator("#questionnaire input[name='nasa_tlx.mental']").count() == 21
    )

    # Submit with nothing answered, then with one item left: refused, the missing items marked.
    page.click("#questionnaire button[type=submit]")
    assert page.evaluate("havenForm.refused") == 1 and page.locator("fieldset.unanswered").count() == 6
    assert "6 are not answered yet" in page.inner_text("#questionnaire .missing")
    # By keyboard: the first mark has the focus; each right arrow chooses the next mark (5 more);
    # Tab goes on to the next item. Mental demand 5, physical 10, ... frustration left out.
    tlx = [i.id for i in BUILTINS["nasa_tlx"].items]
    for k, _ in enumerate(tlx[:-1]):
        for _ in range(k + 1):
            page.keyboard.press("ArrowRight")
        page.keyboard.press("Tab")
    page.keyboard.press("Tab")  # (past the last item, left out: Submit)
    page.keyboard.press("Enter")
    assert page.evaluate("havenForm.refused") == 2 and page.locator("fieldset.unanswered").count() == 1
    assert "1 is not answered yet" in page.inner_text("#questionnaire .missing")
    assert page.evaluate("havenState.answered.length") == 0
    screenshot("web_questionnaire.png", page.screenshot())
    assert page.evaluate("document.activeElement.name") == "nasa_tlx.frustration"  # the refusal took the focus to it
    page.keyboard.press("ArrowRight")  # frustration: 5
    assert page.inner_text("#questionnaire .missing") == ""  # every item answered: the refusal is gone
    submit_and_wait(page, "nasa_tlx", 1)
    console.wait_for_function(
        "() => document.getElementById('questionnaires').textContent === 'h1: questionnaire 2 of 3'",
        timeout=PAGE_TIMEOUT_MS,
    )

    page.wait_for_function("() => havenState.questionnaire === 'godspeed'", timeout=PAGE_TIMEOUT_MS)
    godspeed = {item.id: 1 + k % 5 for k, item in enumerate(BUILTINS["godspeed"].items)}
    assert page.locator("#questionnaire fieldset.differential").count() == len(godspeed)
    # Asked as published: the robot's impression, then perceived safety about the participant's own state.
    assert page.locator("#questionnaire p.prompt").all_inner_texts() == [
        "Please rate your impression of the robot on these scales.",
        "Please rate your emotional state on these scales.",
    ]
    assert "Bartneck, Kulić, Croft & Zoghbi (2009)" in page.inner_text("#questionnaire .source")  # the citation with it
    godspeed_shown = page.eval_on_selector_all("#questionnaire fieldset", "sets => sets.map(s => s.dataset.item)")
    assert sorted(godspeed_shown) == sorted(godspeed) and godspeed_shown != list(godspeed)  # mixed ...
    assert [i.split("_")[0] for i in godspeed_shown[-3:]] == ["safety"] * 3  # ... under each item's own prompt
    answer_with_clicks(page, "godspeed", godspeed)
    page.locator("#questionnaire p.prompt").last.scroll_into_view_if_needed()
    screenshot("web_godspeed.png", page.screenshot())
    submit_and_wait(page, "godspeed", 2)
    page.wait_for_function("() => havenState.questionnaire === 'legibility'", timeout=PAGE_TIMEOUT_MS)
    assert page.locator("#questionnaire input[name='legibility.side']").count() == 7
    answer_with_clicks(page, "legibility", {"side": 6, "surprise": 2})
    submit_and_wait(page, "legibility", 3)
    page.wait_for_function("() => havenState.prompt === 'Trial over'", timeout=PAGE_TIMEOUT_MS)
    assert "Thank you for your answers" in page.inner_text("#prompt")

    # Every answer in: haven run stops by itself.
    assert trial.ended() == 0, "".join(trial.lines)[-3000:]
    folder = trial.session()
    data = read_json(os.path.join(folder, "questionnaires.json"))
    assert set(data) == {"h1"} and list(data["h1"]) == ["godspeed", "legibility", "nasa_tlx"]
    tlx_answers = {item: 5 * (k + 1) for k, item in enumerate(tlx[:-1])} | {tlx[-1]: 5}
    assert data["h1"]["nasa_tlx"]["answers"] == tlx_answers
    assert abs(data["h1"]["nasa_tlx"]["scores"]["nasa_tlx_raw"] - (5 + 10 + 15 + 20 + 25 + 5) / 6) < 1e-3
    assert data["h1"]["godspeed"]["answers"] == godspeed
    assert data["h1"]["godspeed"]["scores"] == score(BUILTINS["godspeed"], godspeed)  # (the order does not change them)
    # the order shown, stored
    assert data["h1"]["godspeed"]["order"] == godspeed_shown and data["h1"]["nasa_tlx"]["order"] == tlx
    assert data["h1"]["legibility"]["scores"] == {"legibility": 6.0}  # (6 + (8 - 2)) / 2: "surprised" reversed
    events = read_events(os.path.join(folder, "events.jsonl"))
    answered = [(e["by"], e["questionnaire"], e["scores"]) for e in events if e["type"] == "questionnaire_answered"]
    assert [(b, q) for b, q, _ in answered] == [("h1", "nasa_tlx"), ("h1", "godspeed"), ("h1", "legibility")]
    assert [s for *_, s in answered] == [data["h1"][q]["scores"] for q in ("nasa_tlx", "godspeed", "legibility")]
    session = read_json(os.path.join(folder, "session.json"))
    assert session["questionnaires"] == ["nasa_tlx", "godspeed", "legibility"]
    assert session["questionnaires_answered"] == {"h1": ["nasa_tlx", "godspeed", "legibility"]}
    assert session["questionnaires_end"] == "answered" and session["valid"] and session["end_reason"] == "stopped"
    assert tracebacks("".join(trial.lines)) == []
    assert "haven study: participant p01: all 1 trials done" in "".join(trial.lines)

    report_argv = [*HAVEN, "study", "report", str(tmp_path / "study.yaml"), "--dir", str(tmp_path / "study")]
    report = subprocess.run(report_argv, capture_output=True, text=True)
    assert report.returncode == 0, report.stderr
    with open(tmp_path / "study" / "report" / "study_long.csv") as f:
        rows = {(r["human"], r["measure"]): r for r in csv.DictReader(f)}
    raw = rows[("h1", "nasa_tlx_raw")]
    assert (raw["participant"], raw["condition"], raw["scenario"]) == ("p01", "signals", "head_on")
    assert (
        abs(float(raw["value"]) - (5 + 10 + 15 + 20 + 25 + 5) / 6) < 1e-3
        and float(rows[("h1", "legibility")]["value"]) == 6.0
    )
    assert (tmp_path / "study" / "report" / "summary.png").stat().st_size > 10_000


def test_the_researcher_skips_the_questionnaires_and_the_session_stays_valid(ros, browser, tmp_path):
    """Nobody answers: the console's Skip questionnaires ends the wait; the session is complete and
    valid, session.json says nothing was answered and that the researcher skipped."""
    trial, page, console = stopped_trial(
        ros, browser, tmp_path, ["godspeed", "nasa_tlx"], {"width": 640, "height": 480}
    )
    page.wait_for_function("() => havenState.questionnaire === 'godspeed'", timeout=PAGE_TIMEOUT_MS)
    console.wait_for_function(
        "() => havenState.questionnaires.join() === 'h1: questionnaire 1 of 2'", timeout=PAGE_TIMEOUT_MS
    )
    assert trial.proc.poll() is None  # haven run waits for the answers
    console.click("#skip-questionnaires")
    page.wait_for_function(
        "() => havenState.prompt === 'Trial over' && havenState.questionnaire === null", timeout=PAGE_TIMEOUT_MS
    )
    assert trial.ended() == 0, "".join(trial.lines)[-3000:]
    folder = trial.session()
    session = read_json(os.path.join(folder, "session.json"))
    assert session["questionnaires_answered"] == {"h1": []} and session["questionnaires_end"] == "skipped"
    assert session["valid"] and session["end_reason"] == "stopped" and session["outcome"] == "stopped"
    assert not os.path.exists(os.path.join(folder, "questionnaires.json"))
    events = read_events(os.path.join(folder, "events.jsonl"))
    assert [(e.get("action"), e.get("by")) for e in events if e["type"] == "intervention"] == [
        ("skip_questionnaires", "researcher")
    ]
    assert tracebacks("".join(trial.lines)) == []


def test_ctrl_c_while_waiting_for_answers_keeps_the_session_and_says_what_was_answered(ros, tmp_path):
    """No browser needed: the trial is started and stopped on /haven/trial_control; while haven run
    waits for the answers (the trial's nodes stopped, the recorder and the web node running), Ctrl-C
    ends the wait: the session is complete and valid, session.json says nothing was answered."""
    import signal

    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String

    from haven_sim.nodes import qos

    argv = [
        "run",
        str(head_on_scenario(tmp_path)),
        "--teleop",
        "h1",
        "--web",
        "--port",
        "0",
        "--sessions",
        str(tmp_path / "s"),
    ]
    trial = WebTrial(ros, [*argv, "--questionnaire", "nasa_tlx"])
    trial.urls()
    latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    status = ros.collect(String, "/haven/trial_status", latched)
    assert ros.spin_until(lambda: status and json.loads(status[-1].data)["state"] == "held", timeout_s=90), "".join(
        trial.lines
    )[-3000:]
    control = ros.node.create_publisher(String, "/haven/trial_control", qos.RELIABLE)
    ros.wait_matched(control)
    for command, state in (("start", "running"), ("stop", "ended")):
        control.publish(String(data=command))
        assert ros.spin_until(lambda state=state: json.loads(status[-1].data)["state"] == state, timeout_s=60), "".join(
            trial.lines
        )[-3000:]
    deadline = time.monotonic() + 60
    while not any("waiting for h1 to answer nasa_tlx" in line for line in trial.lines):
        assert time.monotonic() < deadline and trial.proc.poll() is None, "".join(trial.lines)[-3000:]
        time.sleep(0.05)
    trial.proc.send_signal(signal.SIGINT)
    assert trial.ended() == 0, "".join(trial.lines)[-3000:]
    session = read_json(os.path.join(trial.session(), "session.json"))
    assert session["questionnaires"] == ["nasa_tlx"] and session["questionnaires_answered"] == {"h1": []}
    assert session["questionnaires_end"] == "interrupted" and session["valid"] and session["outcome"] == "stopped"
    assert tracebacks("".join(trial.lines)) == []
