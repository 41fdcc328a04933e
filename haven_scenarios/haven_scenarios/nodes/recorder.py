"""Session recorder: every topic of the graph into a rosbag2 bag (MCAP, metadata version 9), and
/haven/events also line by line into events.jsonl, so nothing is lost if the run is cut short.

Messages are subscribed raw (CDR bytes, no Python conversion) with readers that drop nothing, and
written with the receive time in sim time (rosbag2's convention); each topic is recorded with the
QoS its publishers offer, so `ros2 bag play` re-latches the latched ones. Messages DDS reports lost
on the way (a reader too far behind) are counted per topic into the bag's metadata. On Ctrl-C,
SIGTERM or SIGHUP the recorder first writes whatever its readers still hold, then closes the bag.
Once a second the messages held in memory are written out as a complete MCAP chunk, so a recorder
killed outright (SIGKILL) loses at most the last second; `haven repair` (record/repair.py) rebuilds
such a bag. A full disk (ENOSPC, or EFBIG over a file size limit) stops the recorder with one line
naming the file and the reason, and exit code 1; what it had written stays as it was, for the repair.

The recorder subscribes /haven/events and /goal_pose only once /odom and /humans reach it: the
director starts the trial when the recorder listens to either (the topics it watches), so the state
streams are recorded from the start (with /goal_pose subscribed early, a busy machine once started
the trial 2.3 s of sim time before /odom reached the recorder)
(DDS matches each topic on its own; on a busy machine at 10x the streams matched 7 s of sim time
after the events once). Its publishers keep the last 1000 events for it, so none are lost by waiting.
Without a simulator (nobody publishes the streams) it subscribes after STREAMS_WAIT_S all the same;
a simulator that is still starting up (a busy machine) is waited for. On the lockstep clock
(`suite_lockstep`) nothing is held: the simulator takes its first step only once the recorder reads
every topic the suite publishes without a history to catch up on, and every publisher has matched it.

Log times are sim time (rosbag2's convention on /clock). To align a session with other recordings of
the study (video, eye tracking, questionnaires), the recorder pairs sim time with the wall clock once
a second and keeps the pairs in the bag's metadata (custom_data `haven.wall_clock`;
`record.bag.wall_clock` reads them, `record.bag.to_wall_time` converts).

Every publisher of the topics a trial rests on is noted with when it was seen (looked for twice a
second and whenever a publisher matches one of the readers, so a short-lived one is caught too),
into the bag's metadata (custom_data `haven.publishers`); one from outside the suite (its
`suite_nodes` and `open_topics` parameters say what is the run's own) is said in the log at once.
/plan's history is caught up on where its publisher latches (`RawTopics`' catch-up readers).

Once it has the `trial_end` event and, on every state stream, a message stamped at or after it,
the recorder says so on the pipe `haven run` gives it (`END_FD_ENV`): `haven run` stops the nodes
then, not after a guessed delay, so a busy machine cannot cut the last moments of a trial (and a
recorder that dies closes the pipe, which `haven run` sees at once).
"""

from __future__ import annotations

import contextlib
import os
import struct
import sys
import time
from pathlib import Path

import rclpy
from rclpy.clock import Clock, ClockType
from rclpy.qos import QoSProfile
from rclpy.serialization import deserialize_message
from rosbags.interfaces import Qos, QosDurability, QosHistory, QosLiveliness, QosReliability, QosTime
from std_msgs.msg import String

from haven_scenarios.nodes.raw_topics import RawTopics
from haven_scenarios.record.bag import BagWriter
from haven_scenarios.record.outsiders import Declared, PublisherLog, describe, outsiders, watched
from haven_scenarios.record.session import END_FD_ENV, EVENTS_FILE
from haven_sim.common import nodes, topics
from haven_sim.common.events import EventKind
from haven_sim.common.params import build, defaults
from haven_sim.common.topics import WireParams
from haven_sim.nodes import conversions as conv, qos
from haven_sim.nodes.runner import declare, refuse_changes, run_node

EVENTS = "/" + topics.EVENTS
GATED = (EVENTS, "/" + topics.GOAL)  # what the scenario node's start waits for the recorder to read
STREAMS = ("/" + topics.ODOM, "/" + topics.HUMANS)  # header-first messages the metrics need to the end
STREAMS_WAIT_S = 5.0  # wall time
CLOCK_PAIR_PERIOD_S = 1.0  # wall time between (sim, wall) clock pairs
PUBLISHERS_PERIOD_S = 0.5  # wall time between looks at who publishes (and whenever a publisher matches a reader)


def header_stamp(cdr: bytes) -> float:
    """The header stamp of a CDR message that starts with a std_msgs/Header (after the 4-byte
    encapsulation header), without deserialising the rest."""
    sec, nanosec = struct.unpack_from("<iI" if cdr[1] == 1 else ">iI", cdr, 4)
    return sec + nanosec * 1e-9


def bag_qos(p: QoSProfile) -> Qos:
    """An rclpy QoS profile as rosbags records it (the offered_qos_profiles of metadata.yaml)."""

    def duration(d: object) -> QosTime:
        ns = int(getattr(d, "nanoseconds", 0))
        return QosTime(ns // 1_000_000_000, ns % 1_000_000_000)

    return Qos(
        history=QosHistory(int(p.history)),
        depth=int(p.depth),
        reliability=QosReliability(int(p.reliability)),
        durability=QosDurability(int(p.durability)),
        deadline=duration(p.deadline),
        lifespan=duration(p.lifespan),
        liveliness=QosLiveliness(int(p.liveliness)),
        liveliness_lease_duration=duration(p.liveliness_lease_duration),
        avoid_ros_namespace_conventions=bool(p.avoid_ros_namespace_conventions),
    )


class Recorder(qos.QuietNode):
    def __init__(self) -> None:
        super().__init__(nodes.RECORDER.name)
        folder = Path(declare(self, "session_dir", "session"))
        try:
            folder.mkdir(parents=True, exist_ok=True)
            self.bag = BagWriter(folder / "bag")
            self.bag.__enter__()
            self.events = (folder / EVENTS_FILE).open("a", encoding="utf-8")
        except OSError as e:  # (run_node says it in one line, exit code 2)
            raise ValueError(f"cannot record into {folder.resolve()}: {e.strerror or e}") from None
        self.failed = False  # a write failed (disk full): nothing more is written
        self.mcap = self.bag.path / f"{self.bag.path.name}.mcap"  # (the file rosbags writes)
        self.lost: dict[str, int] = {}
        self.lost_at: list[tuple[str, int, float]] = []  # (topic, messages, sim time DDS reported it)
        self.start_stamp: float | None = None
        # (haven run's pipe)
        self.end_fd = int(os.environ[END_FD_ENV]) if os.environ.get(END_FD_ENV, "").isdigit() else None
        self.end_stamp: float | None = None
        self.reached: set[str] = set()  # streams recorded up to the end
        self.flowing: set[str] = set()  # streams that have reached the recorder
        self.publisher_log = PublisherLog()
        self.said_not_recorded: set[str] = set()
        names, opened = (declare(self, n, []) for n in ("suite_nodes", "open_topics"))
        lockstep = bool(declare(self, "suite_lockstep", False))
        # (`haven sim --record`: no trial to judge)
        self.declared = Declared(frozenset(names), tuple(opened), lockstep) if names else None
        self.topics = RawTopics(
            self,
            lambda topic, msgtype, latched: True,
            self._on_message,
            keep_all=True,
            on_lost=self._on_lost,
            batched=True,
            # (on the lockstep clock the simulator waits for the recorder to read everything)
            held=() if lockstep else GATED,
            params=self._declare_wire_params(),
            on_matched=self._watch_publishers,
            catch_up=True,
            on_unreadable=self._not_recorded,
        )
        self.create_timer(PUBLISHERS_PERIOD_S, self._watch_publishers, clock=Clock(clock_type=ClockType.STEADY_TIME))
        self._give_up = self.create_timer(
            STREAMS_WAIT_S, self._streams_missing, clock=Clock(clock_type=ClockType.STEADY_TIME)
        )
        self.clock_pairs: list[tuple[int, int]] = []  # (sim ns, wall ns)
        self.create_timer(CLOCK_PAIR_PERIOD_S, self._pair_clocks, clock=Clock(clock_type=ClockType.STEADY_TIME))
        refuse_changes(self)  # (use_sim_time switched mid-trial would turn the bag's times into wall time)
        # (what is published before this line is recorded only if latched: say when recording starts)
        self.get_logger().info(f"recording every topic into {folder / 'bag'}")

    def _pair_clocks(self) -> None:
        sim = self.get_clock().now().nanoseconds
        if sim > 0 and (not self.clock_pairs or sim > self.clock_pairs[-1][0]):
            self.clock_pairs.append((sim, time.time_ns()))
        if not self.failed:
            try:
                self.bag.flush()  # (once a second: what a SIGKILL would lose)
            except OSError as e:
                self._write_failed(self.mcap, e)

    def _watch_publishers(self, topic: str | None = None) -> None:
        """Who publishes each topic the trial rests on (`record/outsiders.py`), kept for the bag's
        metadata; a publisher from outside the suite is said at once, so the researcher knows while
        the trial runs that the session will not be valid."""
        now = self.get_clock().now().nanoseconds * 1e-9
        names = [topic] if topic is not None else [t for t, _ in self.get_topic_names_and_types()]
        for name in names:
            if not watched(name):
                continue
            publishers = [(i.node_name, bytes(i.endpoint_gid).hex()) for i in self.get_publishers_info_by_topic(name)]
            new = self.publisher_log.observe(name, publishers, now)
            if new and self.declared is not None:
                outside = {s.gid for s in outsiders(self.publisher_log, self.declared)}
                for s in new:
                    if s.gid in outside:
                        ignored = self.declared.ignores(name)
                        then = (
                            "ignored on the lockstep clock (noted in the session)"
                            if ignored
                            else "the session will not be valid"
                        )
                        self.get_logger().warning(f"{describe(s, self.declared)}: {then}")

    def _write_failed(self, path: Path, e: OSError) -> None:
        """A full disk: one line naming the file and the reason, the bag left as far as it was
        written (its footer and metadata.yaml would not fit either), and the process ends (code 1)."""
        self.failed = True
        print(
            f"recorder: error: cannot write {path.resolve()}: {e.strerror or e}; recording stopped "
            "(what was written is kept: `haven repair` rebuilds the bag)",
            file=sys.stderr,
            flush=True,
        )
        self.bag.abort()
        raise SystemExit(1)  # (out of the executor's spin: run_node's cleanup still runs)

    def _declare_wire_params(self) -> WireParams:
        """The topic table's parameters (stamped velocity commands), as the other nodes have them."""
        values = {name: declare(self, name, default) for name, default in defaults(WireParams).items()}
        return build(WireParams, values, where="recorder: parameter ")

    def _streams_missing(self) -> None:
        """Without a simulator (nobody publishes a missing stream) /haven/events is recorded
        without them; while a publisher exists (a simulator still starting up), keep waiting."""
        if not self.topics.held:
            self._give_up.cancel()
            return
        missing = sorted(set(STREAMS) - self.flowing)
        if any(self.count_publishers(t) > 0 for t in missing):
            return
        self._give_up.cancel()
        self.get_logger().info(f"nobody publishes {', '.join(missing)}: recording {' and '.join(GATED)} without")
        self.topics.release()

    def _on_lost(self, topic: str, n: int, best_effort: bool) -> None:
        """Counted for the bag's metadata; a warning unless the publisher sends best effort (a
        laser scan), where dropping what a reader cannot take is the contract."""
        self.lost[topic] = self.lost.get(topic, 0) + n
        self.lost_at.append((topic, n, self.get_clock().now().nanoseconds * 1e-9))
        # (rclpy refuses one call site logging at two severities: two calls)
        text = f"{topic}: {n} message(s) lost before the recorder could read them"
        if best_effort:
            self.get_logger().info(text, throttle_duration_sec=5.0)
        else:
            self.get_logger().warning(text, throttle_duration_sec=5.0)

    def _on_message(self, topic: str, msgtype: str, data: bytes) -> None:
        if self.failed:
            return
        try:
            if not self._record(topic, msgtype, data):
                return
        except OSError as e:
            self._write_failed(self.mcap, e)
        self._follow_streams(topic, data)
        if topic == EVENTS:
            self._event(data)

    def _not_recorded(self, topic: str, msgtype: str, why: str) -> None:
        """A topic that cannot be recorded: said once, and noted in the bag's metadata (so in session.json)."""
        if topic in self.said_not_recorded:
            return
        self.said_not_recorded.add(topic)
        self.bag.not_recorded.setdefault(topic, f"{msgtype}: {why}")
        self.get_logger().warning(f"not recording {topic} ({msgtype}): {why}")

    def _record(self, topic: str, msgtype: str, data: bytes) -> bool:
        """Into the bag; False for a type rosbags does not know (not recorded)."""
        if not self.bag.has_topic(topic):
            offered = [bag_qos(i.qos_profile) for i in self.get_publishers_info_by_topic(topic)]
            if not self.bag.add_topic(topic, msgtype, offered):
                self._not_recorded(topic, msgtype, self.bag.not_recorded[topic])
                return False
        self.bag.write(topic, self.get_clock().now().nanoseconds, data)
        return True

    def _follow_streams(self, topic: str, data: bytes) -> None:
        """/haven/events released once the streams flow; the end said once they reach the trial's end."""
        if topic in STREAMS and self.topics.held:
            self.flowing.add(topic)
            if self.flowing >= set(STREAMS):
                self.topics.release()
        if (
            self.end_stamp is not None
            and topic in STREAMS
            and topic not in self.reached
            and header_stamp(data) >= self.end_stamp - 1e-6
        ):
            self.reached.add(topic)
            if self.reached >= set(STREAMS) and self.end_fd is not None:
                with contextlib.suppress(OSError):  # (nobody reads any more: haven run is gone)
                    os.write(self.end_fd, f"{self.end_stamp}\n".encode())
                    os.close(self.end_fd)
                self.end_fd = None

    def _event(self, data: bytes) -> None:
        try:
            event = conv.event_from_msg(deserialize_message(data, String))
        except ValueError as e:  # kept in the bag as received; left out of events.jsonl
            self.get_logger().warning(f"not an event on /haven/events: {e}", throttle_duration_sec=5.0)
            return
        try:
            self.events.write(event.to_json() + "\n")
            self.events.flush()
        except OSError as e:
            self._write_failed(Path(self.events.name), e)
        if event.kind is EventKind.TRIAL_END:
            self.end_stamp = event.stamp
        elif event.kind is EventKind.TRIAL_START:
            self.start_stamp = event.stamp

    def _lost_in_trial(self) -> dict[str, int]:
        """The losses DDS reported once the trial had begun (a message lost during the trial cannot
        be reported before it was sent; those before are the log's, not the trial's: said only)."""
        if self.start_stamp is None:
            return self.lost
        out: dict[str, int] = {}
        for topic, n, when in self.lost_at:
            if when >= self.start_stamp - 1e-6:
                out[topic] = out.get(topic, 0) + n
        before = {t: n - out.get(t, 0) for t, n in self.lost.items() if n > out.get(t, 0)}
        if before:
            self.get_logger().info(f"lost before the trial began (not the trial's): {before}")
        return out

    def destroy_node(self) -> None:
        """What the readers still hold into the bag, then the bag closed (its footer and
        metadata.yaml); a write failing now (disk full) is said in one line and ends with code 1."""
        failed_before = self.failed
        if not self.failed:
            try:
                self.topics.drain()
                self._pair_clocks()
                self._watch_publishers()
                self.bag.close(
                    lost=self._lost_in_trial(), wall_clock=self.clock_pairs, publishers=self.publisher_log.to_json()
                )
            except SystemExit:
                pass  # a write failed: said in one line, the bag left as written for the repair
            except OSError as e:
                with contextlib.suppress(SystemExit):
                    self._write_failed(self.mcap, e)
        with contextlib.suppress(OSError):
            self.events.close()  # (every event was flushed as it came)
        super().destroy_node()
        if self.failed and not failed_before:
            rclpy.try_shutdown()  # (run_node's own shutdown is skipped by the exit)
            raise SystemExit(1)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Recorder, args))


if __name__ == "__main__":
    main()
