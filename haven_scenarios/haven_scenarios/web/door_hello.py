"""Only the front door reaches the role servers: what it says first on each connection, and the
connections it did not open cut.

Each role's Foxglove WebSocket server listens on 127.0.0.1, where any process of any user could
connect to it and skip the tokens. So:
- the door opens every connection from a socket bound before it connects (`BackendGuard.socket_for`,
  the door's WebSocket client's socket factory), so the guard knows it by its port;
- right after the WebSocket upgrade, before a message of the page's, the door sends a hello: a client
  channel advertised on DOOR_TOPIC and one message carrying the role's door key (`access.door_key`,
  from the session's secret; a page never sees it). The relay
  (web/foxglove_relay.py) lets a client publish, subscribe or touch parameters only after that
  hello, so a connection that skipped the door can do nothing whatever its timing;
- `BackendGuard.sweep` (on a stranger's first request, and every second) shuts every connection to
  a role server's port whose other end is not one of the door's sockets, so it is refused, not
  merely ignored: the kernel's table of TCP connections names them, and since the servers run in
  this process their sockets are among its own (Linux's /proc, as the suite is).
"""

from __future__ import annotations

import json
import os
import socket
import struct
import sys
import threading
from collections.abc import Iterable
from typing import Any

DOOR_TOPIC = "/haven/front_door"  # (a client channel only: never a ROS topic)
DOOR_SCHEMA = "haven/front_door"
DOOR_CHANNEL = 0xFFFF_FFF0  # a client channel id no page uses (the pages' count up from 1)
MESSAGE_DATA = 0x01  # the Foxglove WebSocket protocol's client opcode for a message (ws-protocol spec)


def hello_messages(key: str) -> list[str | bytes]:
    """The door's hello, as WebSocket messages: advertise DOOR_TOPIC, send the key on it, unadvertise it."""
    channel = {"id": DOOR_CHANNEL, "topic": DOOR_TOPIC, "encoding": "cdr", "schemaName": DOOR_SCHEMA}
    return [
        json.dumps({"op": "advertise", "channels": [channel]}),
        struct.pack("<BI", MESSAGE_DATA, DOOR_CHANNEL) + key.encode(),
        json.dumps({"op": "unadvertise", "channelIds": [DOOR_CHANNEL]}),
    ]


class BackendGuard:
    """The door's own connections to the role servers' `ports`, and a sweep that shuts any other."""

    def __init__(self) -> None:
        self.ports: frozenset[int] = frozenset()
        self._door: set[int] = set()  # local ports of the door's connections
        self._lock = threading.Lock()
        self.cut = 0

    def watch(self, ports: Iterable[int]) -> None:
        """The role servers' ports (known once they listen)."""
        with self._lock:
            self.ports = self.ports | frozenset(ports)

    def socket_for(self, addr_info: tuple[Any, ...]) -> socket.socket:
        """A socket to connect to a role server from, bound to a port the guard knows before it
        connects (the door's client's socket factory: aiohttp's TCPConnector `socket_factory`)."""
        family, kind, proto = addr_info[:3]
        s = socket.socket(family, kind, proto)
        try:
            s.bind(("127.0.0.1", 0))
        except OSError:
            s.close()
            raise
        with self._lock:
            self._door.add(s.getsockname()[1])
        return s

    def release(self, sockname: tuple[Any, ...] | None) -> None:
        """A door's connection (by its local address) has closed."""
        if sockname:
            with self._lock:
                self._door.discard(sockname[1])

    def sweep(self) -> int:
        """Shut every connection to a role server that the door did not open; how many were."""
        with self._lock:
            strangers = self._strangers()
            cut = 0
            if strangers:
                for fd in os.listdir("/proc/self/fd"):
                    try:
                        link = os.readlink(f"/proc/self/fd/{fd}")
                    except OSError:
                        continue
                    if link in strangers and _shut(int(fd)):
                        cut += 1
            self.cut += cut
        if cut:
            print(
                f"web: {cut} connection(s) to the pages' servers did not come through the front door: closed",
                file=sys.stderr,
                flush=True,
            )
        return cut

    def _strangers(self) -> set[str]:
        """The socket names ("socket:[inode]") of established connections to a role server's port
        from a port that is not one of the door's, as the kernel lists them (proc(5), /proc/net/tcp)."""
        try:
            with open("/proc/self/net/tcp") as f:
                rows = f.read().splitlines()[1:]
        except OSError:
            return set()
        found = set()
        for row in rows:
            fields = row.split()
            if len(fields) < 10 or fields[3] != ESTABLISHED:
                continue
            local, remote = int(fields[1].split(":")[1], 16), int(fields[2].split(":")[1], 16)
            if local in self.ports and remote not in self._door:
                found.add(f"socket:[{fields[9]}]")
        return found


ESTABLISHED = "01"  # the state column of /proc/net/tcp (include/net/tcp_states.h: TCP_ESTABLISHED)


def _shut(fd: int) -> bool:
    """Shut down the connection behind `fd` (this process's own socket, held by the server)."""
    try:
        with socket.socket(fileno=os.dup(fd)) as s:
            s.shutdown(socket.SHUT_RDWR)
    except OSError:
        return False
    return True
