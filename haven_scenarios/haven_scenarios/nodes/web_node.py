"""Web node: the study in the browser. Participants' first-person pages and the researcher console.

It relays the topics the pages draw (as raw CDR, over one Foxglove WebSocket server per page role,
on 127.0.0.1) and serves the pages and their sockets through one token-checked address
(`haven_scenarios.web.front_door`). What pages send comes back through Foxglove's client-publish
capability and is published only where their role allows (`haven_scenarios.web.access`): a
participant's velocity on /humans/<id>/cmd_vel; the console's robot driving on /cmd_vel_teleop
(the velocity mux's teleop input, so the e-stop still wins), the thought text on /haven/wizard_thought,
trial start / stop / abort on /haven/trial_control, and the cue toggles as the viz node's
parameters. The console's interventions are study events (`haven_scenarios.web.wizard`). After the
trial, participants answer the run's questionnaires in their page (`haven run --questionnaire`):
each is checked and written to the session folder's questionnaires.json, and is a
`questionnaire_answered` event (`haven_scenarios.record.answers`).

The session's secret (each page role's token derives from it) comes from the environment
(HAVEN_WEB_TOKEN, set by `haven run --web`), else a new one.
"""

from __future__ import annotations

import functools
import os
import sys
import threading
import time
from datetime import UTC, datetime
from pathlib import Path

from foxglove.websocket import StatusLevel
from rclpy.node import Node
from rclpy.serialization import deserialize_message
from std_msgs.msg import String

from haven_scenarios.nodes.cue_parameters import CueParameters
from haven_scenarios.nodes.presence_desk import PresenceDesk
from haven_scenarios.nodes.raw_topics import RawTopics
from haven_scenarios.nodes.role_sink import RoleSink, TablePublishers
from haven_scenarios.record.answers import AnswerBook, from_parameter
from haven_scenarios.study.presence import DEFAULT_RECONNECT_TIMEOUT_S, Attendance, OnDisconnect
from haven_scenarios.study.rules import TrialCommand
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.web.access import (
    ANSWERS,
    CONSOLE,
    PAGE_REPORT,
    READY,
    SKIP_QUESTIONNAIRES,
    TOKEN_ENV,
    Role,
    absolute,
    door_key,
    new_token,
    roles,
    urls,
)
from haven_scenarios.web.door_hello import BackendGuard
from haven_scenarios.web.foxglove_relay import DoorCheck, FoxgloveRelay
from haven_scenarios.web.front_door import FrontDoor, address_for_others
from haven_scenarios.web.page_config import PageSettings, page_config
from haven_scenarios.web.tls import address_notes, server_context
from haven_scenarios.web.wizard import StartGate, Wizard
from haven_sim.common import nodes, topics
from haven_sim.common.events import Event, EventKind, Sequencer, Source, event
from haven_sim.nodes import conversions as conv, wire
from haven_sim.nodes.runner import declare, refuse_changes, refused, run_node

STATUS_TOPIC = absolute(topics.TRIAL_STATUS)
EVENTS_KEPT = 2000  # a trial logs a few hundred
RELAYED = tuple(
    absolute(t)
    for t in (
        topics.ODOM,
        topics.HUMANS,
        topics.PLAN,
        topics.THOUGHT,
        topics.EVENTS,
        topics.AR_MARKERS,
        topics.WORLD_MARKERS,
        topics.CUE_STATE,
        topics.TRIAL_STATUS,
    )
)


class WebNode(Node):
    def __init__(self) -> None:
        super().__init__(nodes.WEB.name)
        host = str(declare(self, "host", "127.0.0.1"))
        port = int(declare(self, "port", 8088))
        humans = [h for h in declare(self, "humans", []) if h]
        scenario = load_scenario(str(declare(self, "scenario", "hallway")))
        researcher_start = bool(declare(self, "researcher_start", False))
        tls_cert = str(declare(self, "tls_cert", ""))  # with tls_key: HTTPS (web/tls.py)
        tls_key = str(declare(self, "tls_key", ""))
        on_disconnect = OnDisconnect(str(declare(self, "on_disconnect", OnDisconnect.KEEP.value)))
        reconnect_timeout_s = float(declare(self, "reconnect_timeout_s", DEFAULT_RECONNECT_TIMEOUT_S))
        questionnaires = from_parameter(str(declare(self, "questionnaires", "[]")))
        settings = PageSettings(
            participant=str(declare(self, "participant", "sim")),
            session=str(declare(self, "session", "")),
            map_inset=bool(declare(self, "map_inset", True)),
            questionnaires=questionnaires,
            teleoperated=tuple(humans),
            next_url=str(declare(self, "next_url", "")),
        )
        self.roles = roles(humans)
        self.secret = os.environ.get(TOKEN_ENV) or new_token()
        self.table = wire.specs(human_ids=[h.id for h in scenario.world.humans])
        self._publisher = TablePublishers(self, self.table)
        self.sequencer, self.wizard, self._lock = Sequencer(), Wizard(), threading.Lock()
        self.gate = StartGate(humans, researcher_start)
        self.answers = AnswerBook(Path.cwd(), humans, questionnaires)  # (its cwd is the session folder)
        self.events = self._publisher(absolute(topics.EVENTS))
        self.cues = CueParameters(self)
        self.relay = FoxgloveRelay()
        self.relay.keep(absolute(topics.EVENTS), EVENTS_KEPT)  # a console opened mid-trial shows the whole log
        attendance = Attendance(humans, on_disconnect, reconnect_timeout_s)
        self.presence = PresenceDesk(self, attendance, self.relay, self._log, self._control, self.now, self._lock)
        self.servers = {}
        guard = BackendGuard()  # only the front door reaches the role servers (web/door_hello.py)
        for name, role in self.roles.items():
            sink = RoleSink(self, role, functools.partial(self.forward, role), self.cues, f"page {name}")
            door = DoorCheck(door_key(self.secret, name), guard.sweep)
            self.servers[name] = self.relay.serve(
                "127.0.0.1", 0, f"haven {name}", sink, parameters=role.parameters, door=door
            )
        ports = {name: int(server.port) for name, server in self.servers.items()}
        self.topics = RawTopics(self, self.relay.add_topic, self._relay, list(RELAYED))
        refuse_changes(self, self._refused)
        configs = {name: page_config(role, scenario, settings) for name, role in self.roles.items()}
        tls = server_context(tls_cert, tls_key) if tls_cert else None
        self.door = FrontDoor(
            host,
            port,
            self.secret,
            ports,
            configs.__getitem__,
            robot_model=scenario.robot.look.model,
            tls=tls,
            guard=guard,
            on_socket=self.presence.socket,
        )
        self.door.start()
        self._say_addresses(host, humans, researcher_start, tls_cert)

    def _say_addresses(self, host: str, humans: list[str], researcher_start: bool, tls_cert: str) -> None:
        """Each page's address, what would keep a headset from using it, and when the trial starts."""
        for name, url in urls(self.door.base_url(host), self.secret, humans).items():
            print(f"web: {'researcher console' if name == CONSOLE else 'participant ' + name}: {url}", flush=True)
        for note in address_notes(address_for_others(host), tls_cert):
            print(f"web: {note}", flush=True)
        when = (
            "on the console's Start"
            if researcher_start or not humans
            else f"when {', '.join(humans)} pressed Start (or on the console's)"
        )
        print(f"web: the trial starts {when}", flush=True)

    def _relay(self, topic: str, msgtype: str, data: bytes) -> None:
        if topic == STATUS_TOPIC:
            self.presence.trial_status(data)
        self.relay.publish(topic, data, time.time_ns())

    def _control(self, command: str) -> None:
        self._publisher(absolute(topics.TRIAL_CONTROL)).publish(String(data=command))

    def now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _refused(self, name: str, reason: str) -> None:
        with self._lock:
            self._log(
                [
                    event(
                        EventKind.REQUEST_REFUSED, self.now(), Source.WEB, request="parameter", name=name, reason=reason
                    )
                ]
            )

    def _log(self, events: list[Event]) -> None:
        for e in events:
            self.events.publish(conv.event_msg(self.sequencer.number(e)))

    def forward(self, role: Role, topic: str, data: bytes) -> None:
        """A page's message (its role allowed the topic and type when it advertised)."""
        with self._lock:
            if topic == READY:  # a participant pressed Start: not a ROS topic, the gate decides
                events, start = self.gate.ready(role.name, self.now())
                self._log(events)
                if start:
                    self._control(TrialCommand.START)
                return
            if topic == PAGE_REPORT:  # not a ROS topic: the console's table of who is connected
                refused_because = self.presence.report(role.name, _text(data))
                if refused_because:
                    refused(self, topic, refused_because)
                return
            if topic in (ANSWERS, SKIP_QUESTIONNAIRES):
                self._after_trial(role, topic, data)
                return
            pub = self._publisher(topic)
            if role.is_console:
                try:
                    msg = deserialize_message(data, pub.msg_type)
                except Exception:
                    self.get_logger().warning(f"console: undecodable message on {topic}", throttle_duration_sec=5.0)
                    return
                if topic == absolute(topics.TRIAL_CONTROL) and str(msg.data) in (TrialCommand.STOP, TrialCommand.ABORT):
                    self.presence.ending()
                if topic == absolute(topics.CMD_VEL_TELEOP):
                    self._log(self.wizard.drive(conv.twist_from_msg(msg), self.now()))
                # the page's {text, hold_s, everywhere}: the viz's held thought
                elif topic == absolute(topics.WIZARD_THOUGHT):
                    try:
                        held, events = self.wizard.thought(str(msg.data), self.now())
                    except ValueError as e:  # (said on the console too: the page shows the server's status)
                        refused(self, topic, e)
                        self.servers[role.name].publish_status(f"refused: {e}", StatusLevel.Warning)
                        return
                    self._log(events)
                    pub.publish(String(data=held.to_json()))
                    return
            pub.publish(data)

    def _after_trial(self, role: Role, topic: str, data: bytes) -> None:
        """A participant's answers to one questionnaire (checked, written), or the console's skip."""
        try:
            text = str(deserialize_message(data, String).data)
        except Exception:
            refused(self, topic, f"undecodable message from page {role.name}")
            return
        if topic == SKIP_QUESTIONNAIRES:
            self._log(self.wizard.skip_questionnaires(self.now()))
            return
        try:
            self._log([self.answers.take(role.name, text, self.now(), datetime.now(UTC).isoformat(timespec="seconds"))])
        except ValueError as e:
            refused(self, topic, e)
        except OSError as e:  # (a full disk: the page's answers stay unsent, it can send them again)
            refused(self, topic, f"cannot write {e.filename}: {e.strerror or e}")

    def destroy_node(self) -> None:
        with self._lock:
            self.presence.closing = True
        self.door.stop()
        self.relay.stop()
        super().destroy_node()


def _text(data: bytes) -> str:
    """A page's std_msgs/String as text ('' if it is not one)."""
    try:
        return str(deserialize_message(data, String).data)
    except Exception:
        return ""


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(WebNode, args))


if __name__ == "__main__":
    main()
