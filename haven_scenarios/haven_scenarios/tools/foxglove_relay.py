"""A Foxglove WebSocket server that relays ROS messages as raw CDR with ros2msg schemas.

Channels are created per topic with the message definition rosbags generates for this ROS
distribution (the same text rosbag2 writes into MCAP files), so Foxglove decodes them like a bag.
The last message of each latched topic (map, plan, world markers, thought) is kept and sent again
when a client subscribes to it, since a late client would otherwise never see it.
"""

from __future__ import annotations

import threading
from typing import Any

import foxglove
from foxglove import Channel, Schema
from foxglove.websocket import ChannelView, Client, ServerListener

from haven_scenarios.record.bag import TYPESTORE


class _Listener(ServerListener):
    def __init__(self, relay: FoxgloveRelay) -> None:
        self.relay = relay

    def on_subscribe(self, client: Client, channel: ChannelView) -> None:
        self.relay.resend_latched(channel.topic)


class FoxgloveRelay:
    def __init__(self, host: str = "127.0.0.1", port: int = 8765) -> None:
        self.channels: dict[str, Channel] = {}
        self.latched: dict[str, tuple[bytes, int] | None] = {}
        self._lock = threading.Lock()
        self.server: Any = foxglove.start_server(name="haven", host=host, port=port, server_listener=_Listener(self))

    @property
    def port(self) -> int:
        return int(self.server.port)

    def add_topic(self, topic: str, msgtype: str, latched: bool) -> bool:
        """Advertise a channel; False for types this distribution's typestore does not know."""
        if topic in self.channels:
            return True
        if msgtype not in TYPESTORE.types:
            return False
        msgdef, _ = TYPESTORE.generate_msgdef(msgtype, ros_version=2)
        schema = Schema(name=msgtype, encoding="ros2msg", data=msgdef.encode())
        self.channels[topic] = Channel(topic, schema=schema, message_encoding="cdr")
        if latched:
            self.latched[topic] = None
        return True

    def publish(self, topic: str, data: bytes, log_time_ns: int) -> None:
        if topic in self.latched:
            with self._lock:
                self.latched[topic] = (bytes(data), log_time_ns)
        self.channels[topic].log(bytes(data), log_time=log_time_ns)

    def resend_latched(self, topic: str) -> None:
        with self._lock:
            last = self.latched.get(topic)
        if last is not None:
            self.channels[topic].log(last[0], log_time=last[1])

    def stop(self) -> None:
        self.server.stop()
