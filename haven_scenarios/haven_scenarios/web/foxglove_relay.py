"""Foxglove WebSocket servers that relay ROS messages as raw CDR with ros2msg schemas.

Channels are created per topic with the message definition rosbags generates for this ROS
distribution (the same text rosbag2 writes into MCAP files), so Foxglove decodes them like a bag.
The last message of each latched topic (map, plan, world markers, thought), or the last `keep` of
one (the study log), is kept and sent again when a client subscribes to it, since a late client
would otherwise never see it (clients already there get it again: latched state is idempotent, and
events carry a per-source `seq` to drop repeats by).

One relay can serve several servers (the channels are shared): `haven bridge` runs one that only
sends; the study's web pages each get one whose clients may also publish (Foxglove's client-publish
capability) and, for the researcher console, set parameters, as a `ClientSink` allows.
"""

from __future__ import annotations

import hmac
import logging
import threading
from collections import Counter, deque
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

import foxglove
from foxglove import Channel, Parameter, Schema
from foxglove.websocket import Capability, ChannelView, Client, ClientChannel, ServerListener, StatusLevel

from haven_scenarios.record.bag import TYPESTORE
from haven_scenarios.web.door_hello import DOOR_TOPIC


def msgdef(msgtype: str) -> str:
    """The ros2msg definition of a type, as rosbag2 writes it (for schemas on both sides)."""
    text, _ = TYPESTORE.generate_msgdef(msgtype, ros_version=2)
    return str(text)


MAX_CHANNELS_PER_CLIENT = 16  # a page advertises at most 4

# foxglove-sdk logs (through Python's logging) every client that leaves without a WebSocket close
# frame: each closed tab, lost network and connection the front door's guard cuts. Those are the
# participants' business, said by the web node where it matters (study/presence.py), not an error.
logging.getLogger("foxglove.websocket.connected_client.poller").setLevel(logging.CRITICAL)


class ClientSink(Protocol):
    """What a server's clients may send, and where it goes."""

    def advertised(self, topic: str, schema_name: str) -> str | None:
        """None to accept a client's channel, else the reason it is refused."""

    def refused_client(self, why: str) -> None:
        """A client is ignored from now on (one line to say so)."""

    def message(self, topic: str, schema_name: str, data: bytes) -> None: ...

    def get_parameters(self, names: list[str]) -> list[Parameter]: ...

    def set_parameters(self, parameters: list[Parameter]) -> list[Parameter]: ...


@dataclass(frozen=True)
class DoorCheck:
    """A server behind the front door (web/door_hello.py): a client is served only once it has sent
    `key` on DOOR_TOPIC; the first request of one that has not calls `on_stranger` (the guard's sweep)."""

    key: str
    on_stranger: Callable[[], object]


class _Listener(ServerListener):
    def __init__(self, relay: FoxgloveRelay, sink: ClientSink | None, door: DoorCheck | None = None) -> None:
        self.relay, self.sink, self.door = relay, sink, door
        self.vouched: set[int] = set()  # clients that said the door's hello
        self.hello: set[tuple[int, int]] = set()  # (client, its channel) the hello comes on
        self.strangers: set[int] = set()
        self.accepted: dict[tuple[int, int], tuple[str, str]] = {}  # (client, its channel) -> topic, type
        self.advertised: Counter[int] = Counter()  # client -> channels it has advertised
        self.server: Any = None

    def _stranger(self, client: Client) -> bool:
        """True for a client of a server behind the door that has not said its hello: refused (said
        once per client, and the guard shuts its connection)."""
        if self.door is None or client.id in self.vouched:
            return False
        if client.id not in self.strangers:
            self.strangers.add(client.id)
            if self.sink is not None:
                self.sink.refused_client(f"client {client.id} did not come through the front door: refused")
            self.door.on_stranger()
        return True

    def on_subscribe(self, client: Client, channel: ChannelView) -> None:
        if not self._stranger(client):
            self.relay.resend_latched(channel.topic)

    def on_client_advertise(self, client: Client, channel: ClientChannel) -> None:
        """A client's channel: accepted or refused as the sink says; beyond MAX_CHANNELS_PER_CLIENT a
        client's advertisements are ignored at once (said once), so one client's flood of them
        costs the others nothing; a refusal is said to the clients once per client."""
        if self.door is not None and channel.topic == DOOR_TOPIC and client.id not in self.vouched:
            self.hello.add((client.id, channel.id))
            return
        if self._stranger(client):
            return
        self.advertised[client.id] += 1
        if self.advertised[client.id] > MAX_CHANNELS_PER_CLIENT:
            if self.advertised[client.id] == MAX_CHANNELS_PER_CLIENT + 1 and self.sink is not None:
                self.sink.refused_client(
                    f"client {client.id} advertised more than {MAX_CHANNELS_PER_CLIENT} channels; ignoring the rest"
                )
            return
        refused = (
            "this server takes no messages"
            if self.sink is None
            else self.sink.advertised(channel.topic, channel.schema_name)
        )
        if refused is None:
            self.accepted[(client.id, channel.id)] = (channel.topic, channel.schema_name)
        elif self.server is not None and (client.id, -1) not in self.accepted:
            self.accepted[(client.id, -1)] = ("", "")  # (told once: the status goes to every client)
            self.server.publish_status(f"refused: {refused}", StatusLevel.Error)

    def on_client_unadvertise(self, client: Client, client_channel_id: int) -> None:
        self.accepted.pop((client.id, client_channel_id), None)
        self.hello.discard((client.id, client_channel_id))

    def on_message_data(self, client: Client, client_channel_id: int, data: bytes) -> None:
        if (client.id, client_channel_id) in self.hello and self.door is not None:
            if hmac.compare_digest(bytes(data), self.door.key.encode()):
                self.vouched.add(client.id)
            return
        if self._stranger(client):
            return
        accepted = self.accepted.get((client.id, client_channel_id))
        if accepted is not None and self.sink is not None:
            self.sink.message(accepted[0], accepted[1], bytes(data))

    def on_get_parameters(
        self, client: Client, param_names: list[str], request_id: str | None = None
    ) -> list[Parameter]:
        return self.sink.get_parameters(param_names) if self.sink is not None and not self._stranger(client) else []

    def on_set_parameters(
        self, client: Client, parameters: list[Parameter], request_id: str | None = None
    ) -> list[Parameter]:
        return self.sink.set_parameters(parameters) if self.sink is not None and not self._stranger(client) else []


class FoxgloveRelay:
    def __init__(self) -> None:
        self.channels: dict[str, Channel] = {}
        self.latched: dict[str, deque[tuple[bytes, int]]] = {}
        self._lock = threading.Lock()
        self.servers: list[Any] = []

    def serve(
        self,
        host: str = "127.0.0.1",
        port: int = 8765,
        name: str = "haven",
        sink: ClientSink | None = None,
        parameters: bool = False,
        time: bool = False,
        door: DoorCheck | None = None,
    ) -> Any:
        """Start one more server on these channels (port 0: any free port; see `.port`). With a
        `sink`, its clients may publish (and set parameters, if `parameters`); with `time`, it
        tells its clients the time (`broadcast_time`); with `door`, only clients that came through
        the front door are served (web/door_hello.py)."""
        caps: list[Capability] = []
        if sink is not None:
            caps = [Capability.ClientPublish, *([Capability.Parameters] if parameters else [])]
        if time:
            caps.append(Capability.Time)
        listener = _Listener(self, sink, door)
        server = foxglove.start_server(
            name=name,
            host=host,
            port=port,
            capabilities=list(caps),
            supported_encodings=["cdr"],
            server_listener=listener,
        )
        listener.server = server
        self.servers.append(server)
        return server

    def broadcast_time(self, ns: int) -> None:
        """The current time (sim time) to every server's clients."""
        for server in self.servers:
            server.broadcast_time(ns)

    @property
    def port(self) -> int:
        return int(self.servers[0].port)

    def add_topic(self, topic: str, msgtype: str, latched: bool) -> bool:
        """Advertise a channel; False for types this distribution's typestore does not know."""
        if topic in self.channels:
            return True
        if msgtype not in TYPESTORE.types:
            return False
        schema = Schema(name=msgtype, encoding="ros2msg", data=msgdef(msgtype).encode())
        self.channels[topic] = Channel(topic, schema=schema, message_encoding="cdr")
        if latched:
            self.latched.setdefault(topic, deque(maxlen=1))
        return True

    def keep(self, topic: str, count: int) -> None:
        """Send the last `count` messages of a topic to a client that subscribes late."""
        with self._lock:
            self.latched[topic] = deque(self.latched.get(topic, ()), maxlen=count)

    def publish(self, topic: str, data: bytes, log_time_ns: int) -> None:
        if topic in self.latched:
            with self._lock:
                self.latched[topic].append((bytes(data), log_time_ns))
        self.channels[topic].log(bytes(data), log_time=log_time_ns)

    def resend_latched(self, topic: str) -> None:
        with self._lock:
            kept = list(self.latched.get(topic, ()))
        for data, log_time in kept:
            self.channels[topic].log(data, log_time=log_time)

    def stop(self) -> None:
        for server in self.servers:
            server.stop()
