"""A node that wires a core component to ROS: declare -> configure -> wire -> translate.

Parameters are declared from the component's config dataclass (names, defaults and descriptions
come from there); each topic the component reads becomes a subscription whose messages are
converted and handed to it, each topic it writes a publisher, its period a sim-time timer. A message
that cannot be converted (a bad event string from another node, say) is refused with a throttled
warning naming the topic, and the node keeps running.
"""

from __future__ import annotations

import os
import time
from collections import deque
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypeVar

from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.clock import Clock, ClockType, JumpThreshold, TimeJump
from rclpy.duration import Duration
from rclpy.event_handler import SubscriptionEventCallbacks
from rclpy.exceptions import InvalidParameterValueException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, ReliabilityPolicy
from rclpy.serialization import serialize_message
from rclpy.subscription import Subscription

from haven_sim.common import contain, nodes, topics
from haven_sim.common.component import Component, Message
from haven_sim.common.events import Event, EventKind, Sequencer, event
from haven_sim.common.params import ParamsError, defaults, leaves, ros_range
from haven_sim.common.topics import WireParams
from haven_sim.nodes import qos, wire
from haven_sim.nodes.lockstep import LockstepParticipant
from haven_sim.nodes.runner import declare, handle, refused, start_up_only
from haven_sim.nodes.wire import TopicSpec, type_name
from haven_sim.robots.fields import build_config
from haven_sim.runtime.lockstep import LockstepParams
from haven_sim.runtime.suite_messages import InputLimit

C = TypeVar("C")
CATCH_UP_S = 10.0  # wall time after start-up in which a latched reader picks up what latched publishers sent
CATCH_UP_POLL_S = 0.2  # how often the graph is read for it
STUCK_DELIVERY_S = 1.0  # wall time a node whose plugin is stuck gives DDS to deliver the event that says so
CLOCK_LEAP_S = 60.0  # a jump of the clock this large either way is no simulator's step
FLOOD_RATE_HZ, FLOOD_BURST = 200.0, 200  # per input topic, sim time: 4x the fastest the suite sends (/odom: 50 Hz)


def declare_config(node: Node, cls: type[C]) -> C:
    """Declare every parameter of a config class on `node` and build the config from their values.
    Each descriptor comes from the field's declaration (`params.param`): its description, its range
    where both ends are bounded, and read-only unless the field is `runtime` (`ros2 param describe`
    shows them). A list is a string array, also when empty (rclpy would type an empty list as a byte array)."""
    values: dict[str, Any] = {}
    own_defaults = defaults(cls)
    for leaf in leaves(cls):
        default = own_defaults[leaf.name]
        descriptor = ParameterDescriptor(description=leaf.doc, read_only=not leaf.runtime)
        span = ros_range(leaf.bounds)
        if span is not None and isinstance(default, float):
            descriptor.floating_point_range = [
                FloatingPointRange(from_value=float(span[0]), to_value=float(span[1]), step=0.0)
            ]
        elif span is not None and isinstance(default, int) and not isinstance(default, bool):
            descriptor.integer_range = [IntegerRange(from_value=int(span[0]), to_value=int(span[1]), step=0)]
        try:
            values[leaf.name] = declare(node, leaf.name, default, descriptor)
        except InvalidParameterValueException:  # (out of its range: said as build_config() says it)
            raise ParamsError(f"{node.get_name()}: parameter {leaf.name}: {leaf.bounds.rule()}") from None  # type: ignore[union-attr]
    return build_config(cls, values, where=f"{node.get_name()}: parameter ")


class ComponentNode(qos.QuietNode):
    def __init__(self, name: str, cli_args: Sequence[str] | None = None) -> None:
        """`cli_args`: this node's own ROS arguments (`--ros-args -p use_sim_time:=true`), beside
        the process's (one process may hold several nodes: nodes/suite_process)."""
        super().__init__(name, cli_args=list(cli_args) if cli_args is not None else None)
        self._pubs: dict[str, Publisher] = {}
        self._subs: dict[str, Subscription] = {}
        self._specs: dict[str, TopicSpec] = {}
        self.lockstep: LockstepParticipant | None = None
        self.deferred: list[Message] = []  # on the lockstep clock: made between ticks, sent with the next (`emit`)
        self.lockstep_mode = False
        # On the free-running clock nothing tells another node's messages from the suite's: a flood on
        # any input (far above any rate the suite sends at) is cut to this, counted and said.
        self.limit = InputLimit(FLOOD_RATE_HZ, FLOOD_BURST)
        self.sequencer = Sequencer()
        self.component: Component | None = None
        self.runtime_parameters: set[str] = set()  # declared `runtime`: they may change while the node runs
        self.add_on_set_parameters_callback(self._check_parameters)
        self.add_pre_set_parameters_callback(self._note_read_only)
        # A /clock message from another node can make time leap far ahead and back: a timer whose
        # next call was computed from the leap would then not fire again for years. Each leap
        # (either way) restarts the timers from the time it landed on.
        leap = JumpThreshold(
            min_forward=Duration(seconds=CLOCK_LEAP_S),
            min_backward=Duration(seconds=-CLOCK_LEAP_S),
            on_clock_change=False,
        )
        self._leap_handle = self.get_clock().create_jump_callback(leap, post_callback=self._restart_timers)

    def _restart_timers(self, jump: TimeJump) -> None:
        for timer in self.timers:
            if timer.clock is self.get_clock():
                timer.reset()

    # -- declare and configure -------------------------------------------------------------------
    def declare_config(self, cls: type[C]) -> C:
        """`declare_config`, noting the parameters that may change while the node runs."""
        self.runtime_parameters |= {leaf.name for leaf in leaves(cls) if leaf.runtime}
        return declare_config(self, cls)

    def _note_read_only(self, params: list[Parameter]) -> list[Parameter]:
        """An attempt to set a read-only parameter (which rclpy then refuses, "Trying to set a
        read-only parameter") is said in the log and in a `request_refused` event, like any refused change."""
        for p in params:
            if self.has_parameter(p.name) and self.describe_parameter(p.name).read_only:
                reason = f"{p.name}: read at start-up only (read-only); restart the node to change it"
                self.get_logger().warning(f"refused to set {reason}", throttle_duration_sec=2.0)
                self.emit([self.refused_request("parameter", p.name, reason)])
        return params

    def _check_parameters(self, params: list[Parameter]) -> SetParametersResult:
        """Only `runtime_parameters` (the cue toggles: the study condition) change while a node runs;
        any other change is refused, said in the log and in a `request_refused` event (the study log
        shows that somebody tried)."""
        refused = start_up_only(self, params, frozenset(self.runtime_parameters))
        if refused is not None:
            self.emit([self.refused_request("parameter", *refused)])
            return SetParametersResult(successful=False, reason=refused[1])
        return SetParametersResult(successful=True)

    def refused_request(self, what: str, name: str, reason: str) -> Message:
        now = self.now()
        return Message(
            topics.EVENTS,
            event(EventKind.REQUEST_REFUSED, now, self.get_name(), request=what, name=name, reason=reason),
            now,
        )

    def emit(self, messages: Sequence[Message]) -> None:
        """What the node makes between its inputs (a toggled cue, a refused request): published now,
        or on the lockstep clock with its next tick, so that it is announced like the rest."""
        if self.lockstep_mode:
            self.deferred += messages
        else:
            self.publish(messages)

    # -- wire ------------------------------------------------------------------------------------
    def wire(self, component: Component, specs: Mapping[str, TopicSpec], participant: bool = True) -> None:
        """Publishers for the component's outputs; its inputs handled as they come and its periodic
        work on a sim-time timer, or, with the `lockstep` parameter, at the lockstep clock's ticks
        (`participant`; the simulator, which runs that clock, passes False)."""
        self.component = component
        self._specs = wire.with_wire_params(dict(specs), self.declare_config(WireParams))
        for topic in component.outputs():
            spec = self._specs.get(topic)
            if spec is not None:  # (no spec: TF where tf2_msgs is not installed)
                self._pubs[topic] = self.create_publisher(spec.msg_type, topic, spec.pub_qos)
        self.lockstep_params = self.declare_config(LockstepParams)
        contain.set_deadlines(self.declare_config(contain.PluginDeadlines))  # (for every plugin call in this process)
        contain.on_stuck = self._plugin_stuck
        self.lockstep_mode = self.lockstep_params.lockstep
        if self.lockstep_mode:  # (the simulator, which runs the clock, reads its inputs itself)
            if participant:
                self.lockstep = LockstepParticipant(
                    self, component, self._specs, self.publish, self._pubs, self.lockstep_params, self.deferred
                )
            return
        for topic, handler in component.handlers().items():
            spec = self._specs[topic]

            def on_message(msg: Any, topic: str = topic, spec: TopicSpec = spec, handler: Any = handler) -> None:
                if not self.limit.admit(topic, (msg,), self.now()):
                    n, name = self.limit.dropped[topic], self.resolve_topic_name(topic)
                    self.get_logger().warning(
                        f"{name}: more than {FLOOD_RATE_HZ:g} messages a second: {n} dropped so far",
                        throttle_duration_sec=5.0,
                    )
                    return
                try:
                    data = spec.decode(msg)
                except ValueError as e:
                    refused(self, topic, e)
                    return
                self.publish(handle(self, topic, handler, data, self.now()))

            self._subs[topic] = self._subscribe(topic, spec, on_message)
        if component.period_s is not None:
            self.create_timer(component.period_s, lambda: self._tick_component(component))
        # The loop that paces the free-running clock (the controller) says after each tick which sim
        # time it has acted at; the velocity mux passes that on once it has passed on the commands
        # that came before it (its readers are served in the order they were made: these last), and
        # the simulator holds time within reach of it (sim/pacer.ControlPace).
        self._pace: Publisher | None = None
        if getattr(component, "paces_clock", False):  # the controller
            said = self._specs[topics.PACE_NAV]
            self._pace = self.create_publisher(said.msg_type, topics.PACE_NAV, said.pub_qos)
        if getattr(component, "relays_pace", False):  # the velocity mux
            heard, said = self._specs[topics.PACE_NAV], self._specs[topics.PACE]
            relay = self.create_publisher(said.msg_type, topics.PACE, said.pub_qos)
            ours = self.sole_writer(topics.PACE_NAV, nodes.CONTROLLER.name)
            self.create_subscription(
                heard.msg_type, topics.PACE_NAV, lambda m: relay.publish(m) if ours() else None, heard.sub_qos
            )
        self._warned: set[tuple[str, str]] = set()
        self.create_timer(2.0, self._check_types, clock=Clock(clock_type=ClockType.STEADY_TIME))

    def _tick_component(self, component: Component) -> None:
        now = self.now()
        self.publish(component.tick(now))
        if self._pace is not None:
            acted_at = now if getattr(component, "pacing", True) else topics.PACE_IDLE
            self._pace.publish(self._specs[topics.PACE_NAV].encode(acted_at, now))

    def _plugin_stuck(self, failed: contain.PluginFailed) -> None:
        """A plugin's call stuck where its deadline cannot interrupt it (common/contain.py; called from
        the watchdog's thread): said on the study log and in the log, then this process ends (the
        suite's supervisor ends the trial; the recording has the reason)."""
        now = self.now()
        self.get_logger().error(f"{failed.reason}: this node ends")
        self.publish(
            [
                Message(
                    topics.EVENTS,
                    contain.failed_event(failed, now, getattr(self.component, "name", self.get_name())),
                    now,
                )
            ]
        )
        time.sleep(STUCK_DELIVERY_S)
        os._exit(contain.STUCK_EXIT)

    def sole_writer(self, topic: str, writer: str) -> Callable[[], bool]:
        """Whether `writer` (a node name) is the only publisher on `topic`, looked at once a second:
        the pace is taken from our own node only, so nobody else can hold (or free) the clock."""
        name, alone = self.resolve_topic_name(topic), [False]

        def look() -> None:
            infos = self.get_publishers_info_by_topic(name)
            alone[0] = bool(infos) and all(i.node_name == writer for i in infos)

        self.create_timer(1.0, look, clock=Clock(clock_type=ClockType.STEADY_TIME))
        return lambda: alone[0]

    def _check_types(self) -> None:
        """A publisher of another type on a topic we read never matches (DDS drops it without a
        word): say so, once, naming the topic and both types."""
        for topic in self._subs:
            ours = type_name(self._specs[topic].msg_type)
            name = self.resolve_topic_name(topic)
            for info in self.get_publishers_info_by_topic(name):
                if info.topic_type != ours and (name, info.topic_type) not in self._warned:
                    self._warned.add((name, info.topic_type))
                    hint = (
                        " (set the stamped_cmd_vel parameter to match)"
                        if "Twist" in ours and "Twist" in info.topic_type
                        else ""
                    )
                    self.get_logger().warning(
                        f"{name}: {info.node_name} publishes {info.topic_type}, this node reads {ours}; ignored{hint}"
                    )

    def _subscribe(self, topic: str, spec: TopicSpec, on_message: Callable[[Any], None]) -> Subscription:
        """A reader with the spec's QoS. With `best_effort_too`, also a best-effort one, which
        matches any publisher (a joystick's best-effort e-stop never matches a reliable reader);
        the reliable reader keeps a reliable publisher's messages reliable. With a `late_qos`, in
        the node's first CATCH_UP_S also a latched one, for what a latched publisher (our planner,
        `haven`'s e-stop) sent before the readers matched. It exists only while a latched
        publisher is there and no volatile one, so a volatile publisher (Nav2's planner_server,
        `ros2 topic pub`) never meets a reader it cannot serve and nobody logs "incompatible QoS".
        A message two readers get is handled once: the publisher's timestamp and sequence number
        say it is the same."""
        if spec.late_qos is None and not spec.best_effort_too:
            return self.create_subscription(spec.msg_type, topic, on_message, spec.sub_qos)
        seen: deque[tuple[int, int]] = deque(maxlen=64)

        def once(msg: Any, info: Any) -> None:
            key = (info["source_timestamp"], info["publication_sequence_number"])
            if key not in seen:
                seen.append(key)
                on_message(msg)

        # A publisher that one of these readers cannot serve is served by another (the best-effort
        # reader; the volatile one for the catch-up reader): they need not say so.
        quiet = SubscriptionEventCallbacks(incompatible_qos=lambda _: None)
        # (rclpy hands a two-argument callback the message info; its type hints do not say so)
        events = quiet if spec.best_effort_too else None
        reader = self.create_subscription(spec.msg_type, topic, once, spec.sub_qos, event_callbacks=events)  # type: ignore[arg-type]
        if spec.best_effort_too:
            self.create_subscription(spec.msg_type, topic, once, qos.best_effort(spec.sub_qos))  # type: ignore[arg-type]
        if spec.late_qos is None:
            return reader
        late_qos = spec.late_qos
        name, started = self.resolve_topic_name(topic), time.monotonic()
        late: list[Subscription] = []  # the latched reader, while there is one

        def catch_up() -> None:
            offered = [
                (i.qos_profile.durability, i.qos_profile.reliability) for i in self.get_publishers_info_by_topic(name)
            ]
            wanted = time.monotonic() - started < CATCH_UP_S and set(offered) == {
                (DurabilityPolicy.TRANSIENT_LOCAL, ReliabilityPolicy.RELIABLE)
            }
            if wanted and not late:
                late.append(self.create_subscription(spec.msg_type, topic, once, late_qos, event_callbacks=quiet))  # type: ignore[arg-type]
            elif not wanted and late:
                self.destroy_subscription(late.pop())
            if time.monotonic() - started >= CATCH_UP_S:
                timer.cancel()

        timer = self.create_timer(CATCH_UP_POLL_S, catch_up, clock=Clock(clock_type=ClockType.STEADY_TIME))
        catch_up()
        return reader

    # -- translate -------------------------------------------------------------------------------
    def now(self) -> float:
        """Sim time: /clock's (use_sim_time), or on the lockstep clock the last tick's (its
        participants run on wall time: the ticks carry the time)."""
        if self.lockstep is not None:
            return self.lockstep.time
        return self.get_clock().now().nanoseconds * 1e-9

    def publish(self, messages: Sequence[Message], serialized: bool = False) -> list[tuple[str, bytes]]:
        """Publish; with `serialized`, each message is serialized here and published as bytes, which
        are returned per topic (the lockstep clock names each message by a digest of them)."""
        sent: list[tuple[str, bytes]] = []
        for m in messages:
            pub = self._pubs.get(m.topic)
            if pub is not None:
                data = self.sequencer.number(m.data) if isinstance(m.data, Event) else m.data
                msg = self._specs[m.topic].encode(data, m.stamp)
                if serialized:
                    raw = serialize_message(msg)
                    pub.publish(raw)
                    sent.append((m.topic, raw))
                else:
                    pub.publish(msg)
        # Components may keep lists of what to log (`notes`: info, `warnings`): drained here.
        for attr, log in (("notes", self.get_logger().info), ("warnings", self.get_logger().warning)):
            lines: list[str] = getattr(self.component, attr, [])
            for line in lines:
                log(line, throttle_duration_sec=2.0) if attr == "warnings" else log(line)
            lines.clear()
        return sent
