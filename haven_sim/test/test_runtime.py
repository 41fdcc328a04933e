"""The runtime both modes share: when periodic work is due, and the in-process loop's lockstep order."""

from dataclasses import dataclass, field

from helpers import box_world

from haven_sim.common import topics
from haven_sim.common.component import Message, due, period_ns
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import Twist2D
from haven_sim.runtime.lockstep import ParticipantInfo, Schedule, inbox_order
from haven_sim.runtime.loop import InProcessLoop
from haven_sim.sim.simulator import SimulatorComponent, SimulatorConfig

STEP = 20_000_000  # 50 Hz physics


def test_due_on_integers_at_the_first_step_at_or_after_each_period():
    assert [k for k in range(11) if due(k, STEP, period_ns(20.0))] == [0, 3, 5, 8, 10]  # 20 Hz on 50 Hz steps
    assert [k for k in range(11) if due(k, STEP, period_ns(10.0))] == [0, 5, 10]
    assert sum(due(k, STEP, period_ns(20.0)) for k in range(1, 50_001)) == 20_000  # no drift over 1000 s


def test_inbox_order_by_topic_then_events_by_stamp_and_source():
    rank = {topics.PLAN: 0, topics.EVENTS: 1}
    late = Message(topics.EVENTS, event(EventKind.RESUMED, 2.0, Source.PLANNER), 2.0)
    early_b = Message(topics.EVENTS, event(EventKind.GOAL_REACHED, 1.0, Source.CONTROLLER), 1.0)
    early_a = Message(topics.EVENTS, event(EventKind.CMD_SOURCE, 1.0, Source.MUX), 1.0)
    plan = Message(topics.PLAN, [], 2.0)
    assert inbox_order(rank, [late, early_b, plan, early_a]) == [plan, early_b, early_a, late]


@dataclass
class Echo:
    """Drives the robot forward on every /odom it handles; ticks at 10 Hz and says when."""

    name: str = "echo"
    unread: frozenset[str] = frozenset()
    seen: list[float] = field(default_factory=list)
    ticks: list[float] = field(default_factory=list)

    @property
    def period_s(self) -> float:
        return 0.1

    def handlers(self):
        return {topics.ODOM: self.on_odom}

    def outputs(self):
        return (topics.CMD_VEL,)

    def on_odom(self, state, now):
        self.seen.append(now)
        return [Message(topics.CMD_VEL, Twist2D(0.5, 0.0, 0.0), now)]

    def tick(self, now):
        self.ticks.append(now)
        return []


def test_who_acts_due_periods_and_readers_of_last_steps_messages():
    s = Schedule(STEP)
    s.add(ParticipantInfo("ctrl", period_ns(20.0), frozenset({topics.PLAN, topics.ODOM})))
    s.add(ParticipantInfo("mux", None, frozenset({topics.CMD_VEL_NAV})))
    assert s.acting(0) == ["ctrl"] and s.acting(1) == []
    s.published("ctrl", [topics.CMD_VEL_NAV, topics.PLAN])  # not itself: only the mux must act
    assert s.acting(2) == ["mux"] and s.acting(3) == ["ctrl"]


def test_loop_handles_messages_when_the_component_acts_and_commands_reach_the_simulator_at_once():
    sim = SimulatorComponent(box_world(10.0), SimulatorConfig())
    echo = Echo()
    observed = []
    loop = InProcessLoop(sim, [echo], [observed.append], observed=(topics.CMD_VEL,))
    for _ in range(10):
        loop.step()
    # Acting at its ticks only (0 and 0.1 s): of a state stream such as /odom, the newest, handled then.
    assert echo.ticks == [0.0, 0.1] and echo.seen == [0.0, 0.1]
    assert [m.stamp for m in observed] == echo.seen  # each command reached the simulator in its step
    assert sim.sim.robot_twist().vx > 0.0  # and drives the robot
    assert topics.SCAN in sim.unread and topics.CMD_VEL not in echo.unread


def test_lockstep_messages_round_trip_and_refuse_anything_else():
    import pytest

    from haven_sim.runtime.lockstep import Ack, Hello, Tick

    for m in (
        Tick(3, 60_000_000, 20_000_000, {"/odom": ["00ff00ff00ff00ff"]}, ["/odom"]),
        Hello("planner", None, ["/odom"], ["/plan"], True),
        Ack("controller", 3, {"/cmd_vel_nav": ["0123456789abcdef", "0123456789abcdef"]}),
    ):
        assert type(m).from_json(m.to_json()) == m
    hostile = [
        "",
        "{",
        "[1]",
        "[" * 100_000,
        '{"node": ["x"], "ready": true, "inputs": [], "outputs": []}',
        '{"step": 1e308}',
        '{"node": "c", "step": 1, "sent": {"/t": "9"}}',
        '{"node": "c", "step": 1, "sent": {"/t": [9]}}',
        '{"step": 1, "t_ns": 1, "step_ns": 1, "expect": {}, "owned": "/odom"}',
    ]
    for text in hostile:
        for cls in (Tick, Hello, Ack):
            with pytest.raises(ValueError):
                cls.from_json(text)
