"""The web node's side of `study/presence.py`: the door's socket news and the pages' reports in, the
study log's events, the simulator's pause (/haven/pause, std_srvs/SetBool), the console's Abort,
and `/haven/participants` (a JSON table for the pages, every second and on each change) out."""

from __future__ import annotations

import contextlib
import json
import threading
import time
from collections.abc import Callable

from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rclpy.serialization import serialize_message
from std_msgs.msg import String
from std_srvs.srv import SetBool

from haven_scenarios.study.presence import Act, Attendance
from haven_scenarios.study.rules import TrialCommand, TrialState
from haven_scenarios.web.access import PARTICIPANTS
from haven_scenarios.web.foxglove_relay import FoxgloveRelay
from haven_sim.common.events import Event, EventKind

TABLE_PERIOD_S = 1.0


class PresenceDesk:
    def __init__(
        self,
        node: Node,
        attendance: Attendance,
        relay: FoxgloveRelay,
        log: Callable[[list[Event]], None],
        control: Callable[[str], None],
        now: Callable[[], float],
        lock: threading.Lock,
    ) -> None:
        """`log`: events to the study log; `control(command)`: a /haven/trial_control command;
        `now()`: the node's (simulated) time; `lock`: the web node's, held around each change."""
        self.node, self.attendance, self.relay, self.log, self.control, self.now, self.lock = (
            node,
            attendance,
            relay,
            log,
            control,
            now,
            lock,
        )
        self.state = TrialState.WAITING.value
        self.closing = False  # the node stops: the pages' sockets close with it, and that is no drop-out
        self.pause_client = node.create_client(SetBool, "haven/pause")
        relay.add_topic(PARTICIPANTS, "std_msgs/msg/String", latched=True)
        node.create_timer(TABLE_PERIOD_S, self._tick, clock=Clock(clock_type=ClockType.STEADY_TIME))

    @property
    def running(self) -> bool:
        return self.state == TrialState.RUNNING.value

    def socket(self, role: str, opened: bool) -> None:
        """The front door's news of a page's WebSocket (from its threads)."""
        with self.lock:
            if self.closing:
                return
            wall = time.monotonic()
            if opened:
                events, acts = self.attendance.opened(role, wall, self.now())
            else:
                events, acts = self.attendance.closed(role, wall, self.now(), self.running)
            if self.state != TrialState.ENDED.value:  # (after the trial: the console's table only, not the study log)
                self._do(events, acts)
            self._table()

    def report(self, who: str, text: str) -> str | None:
        """A participant page's report; the reason it is refused, or None (caller holds the lock)."""
        return self.attendance.report(who, text, time.monotonic())

    def trial_status(self, data: bytes) -> None:
        """/haven/trial_status as relayed (raw CDR): where the trial is."""
        from rclpy.serialization import deserialize_message

        with contextlib.suppress(ValueError, AttributeError):
            self.state = str(json.loads(deserialize_message(data, String).data).get("state", self.state))

    def ending(self) -> None:
        """The console stops or aborts the trial: a paused one must run again to end (caller holds the lock)."""
        self._do([], self.attendance.release())

    def _tick(self) -> None:
        with self.lock:
            self._do(*self.attendance.tick(time.monotonic(), self.now(), self.running))
            self._table()

    def _do(self, events: list[Event], acts: list[Act]) -> None:
        self.log(events)
        for act in acts:
            if act is Act.ABORT:  # (trial_end says it was the drop-out policy, and whose)
                gone = [
                    e["by"]
                    for e in events
                    if e.kind in (EventKind.PARTICIPANT_LOST, EventKind.PARTICIPANT_DISCONNECTED)
                ]
                self.control(f"{TrialCommand.ABORT} dropout:{gone[0] if gone else 'participant'}")
                continue
            if not self.pause_client.service_is_ready():
                self.node.get_logger().warning(f"cannot {act} the trial: the simulator's /haven/pause is not there")
                continue
            self.pause_client.call_async(SetBool.Request(data=act is Act.PAUSE))

    def _table(self) -> None:
        text = json.dumps(self.attendance.table(time.monotonic()), sort_keys=True)
        self.relay.publish(PARTICIPANTS, serialize_message(String(data=text)), time.time_ns())
