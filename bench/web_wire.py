"""The participant's loop without a browser: a Foxglove WebSocket client of our own (through the
front door, as a page connects) sends the avatar's velocity as CDR and times until the moved pose
comes back on /humans. With bench/web_loop.py this splits the loop into the suite's part and the
browser's (on this machine's software renderer the browser's frames dominate).

usage: python bench/web_wire.py [--presses 20]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import signal
import statistics
import struct
import subprocess
import sys
import time
from pathlib import Path

import websockets

from haven_scenarios.record.bag import TYPESTORE

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
# Messages are built and read with rosbags' CDR codec (no rclpy: this is a client from outside ROS).
Twist, Vector3, String = (
    TYPESTORE.types[t] for t in ("geometry_msgs/msg/Twist", "geometry_msgs/msg/Vector3", "std_msgs/msg/String")
)
CLIENT_DATA = b"\x01"  # the Foxglove protocol's client message opcode
SERVER_DATA = 1


def frame(channel: int, msg: object, msgtype: str) -> bytes:
    return CLIENT_DATA + struct.pack("<I", channel) + bytes(TYPESTORE.serialize_cdr(msg, msgtype))


def twist(wz: float) -> object:
    return Twist(linear=Vector3(0.0, 0.0, 0.0), angular=Vector3(0.0, 0.0, wz))


async def measure(urls: dict[str, str], presses: int) -> list[float]:
    p = urls["participant h1"].replace("http://", "ws://").replace("/participant/", "/ws/participant/")
    c = urls["researcher console"].replace("http://", "ws://").replace("/console", "/ws/console")
    async with (
        websockets.connect(p, subprotocols=["foxglove.sdk.v1"]) as ws,
        websockets.connect(c, subprotocols=["foxglove.sdk.v1"]) as console,
    ):
        adv = {
            "op": "advertise",
            "channels": [
                {
                    "id": 1,
                    "topic": "/humans/h1/cmd_vel",
                    "encoding": "cdr",
                    "schemaName": "geometry_msgs/msg/Twist",
                    "schema": "",
                }
            ],
        }
        await ws.send(json.dumps(adv))
        adv = {
            "op": "advertise",
            "channels": [
                {
                    "id": 1,
                    "topic": "/haven/trial_control",
                    "encoding": "cdr",
                    "schemaName": "std_msgs/msg/String",
                    "schema": "",
                }
            ],
        }
        await console.send(json.dumps(adv))
        await console.send(frame(1, String(data="start"), "std_msgs/msg/String"))
        lat: list[float] = []
        sent_at, yaw, settle_until = None, 0.0, time.monotonic() + 3.0
        async for raw in ws:
            if isinstance(raw, str):
                msg = json.loads(raw)
                for ch in msg.get("channels", []) if msg.get("op") == "advertise" else []:
                    if ch["topic"] == "/humans":
                        await ws.send(
                            json.dumps({"op": "subscribe", "subscriptions": [{"id": 7, "channelId": ch["id"]}]})
                        )
                continue
            if raw[0] != SERVER_DATA:
                continue
            z = TYPESTORE.deserialize_cdr(raw[13:], "geometry_msgs/msg/PoseArray").poses[0].orientation.z
            now = time.monotonic()
            if sent_at is None and now >= settle_until:
                yaw, sent_at = z, time.monotonic()
                # turning on the spot
                await ws.send(frame(1, twist(1.6 if len(lat) % 2 else -1.6), "geometry_msgs/msg/Twist"))
            elif sent_at is not None and abs(z - yaw) > 5e-4:
                lat.append((now - sent_at) * 1000)
                sent_at, settle_until = None, now + 0.8
                await ws.send(frame(1, twist(0.0), "geometry_msgs/msg/Twist"))
                if len(lat) >= presses:
                    return lat
    return lat


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--presses", type=int, default=20)
    a = ap.parse_args()
    env = {**os.environ, "ROS_DOMAIN_ID": "92"}
    argv = [
        *HAVEN,
        "run",
        "shared_room",
        "--teleop",
        "h1",
        "--web",
        "--port",
        "0",
        "--researcher-start",
        "--sessions",
        str(OUT / "web_sessions"),
    ]
    proc = subprocess.Popen(
        argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True
    )
    try:
        urls: dict[str, str] = {}
        while len(urls) < 2:
            m = re.search(
                r"web: (participant h1|researcher console): (\S+)", proc.stdout.readline() if proc.stdout else ""
            )
            if m:
                urls[m.group(1)] = m.group(2)
        lat = asyncio.run(measure(urls, a.presses))
    finally:
        os.killpg(proc.pid, signal.SIGINT)
        proc.communicate(timeout=60)
    q = statistics.quantiles(lat, n=20)
    print(
        "velocity sent -> moved pose back (no browser): "
        f"median {statistics.median(lat):.0f} ms, p95 {q[18]:.0f} ms over {len(lat)}"
    )
    save({"median_ms": statistics.median(lat), "p95_ms": q[18], "latencies_ms": lat}, OUT / "web_wire.json")


if __name__ == "__main__":
    main()
