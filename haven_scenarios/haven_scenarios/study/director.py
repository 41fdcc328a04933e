"""The trial director: runs one trial of a scenario, shared by batch mode and the scenario node.

`TrialDirector` holds the mission executive, the study rules and the simulated participants. It reads
what any node can read (the map, /odom, /humans, /battery_state, /plan, /haven/wait, /haven/cue_state,
contacts on the study log) and publishes what the scenario node publishes: goals, the thought, the simulated
participants' velocities, obstruction removals (a control topic, not the event log), the study's events.
Each simulated participant gets what they perceive (`perception.perceive`: the robot and the cues they
can see, the projected path's markers laid out from /plan as the viz does), never the plan itself. It
starts the trial once it has what it needs and `start_allowed` is set (the node waits for every
listener first), and ends it by the scenario's rules with a `trial_end` event."""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from typing import Any

from haven_scenarios.study.cast import make_participants, robot_targets
from haven_scenarios.study.mission import Mission, MissionOutput, Phase
from haven_scenarios.study.participants import Participant
from haven_scenarios.study.perception import BY_FIELD, Percept, Sight, cue_ways, perceive
from haven_scenarios.study.rules import (
    EndReason,
    EndRule,
    GemRules,
    ObstructionRules,
    RouteRules,
    TrialCommand,
    TrialState,
)
from haven_scenarios.study.scenario import Scenario
from haven_sim.common import contain, topics
from haven_sim.common.component import Handler, Message
from haven_sim.common.events import GOAL_POSE, Event, EventKind, Source, event
from haven_sim.common.geometry import Point, Pose2D
from haven_sim.common.params import POSITIVE, config, group, param
from haven_sim.common.state import Goal, HumanPoses, RobotState
from haven_sim.nav.planner import GridPlanner, PlanningError
from haven_sim.robots.fields import RobotChoice
from haven_sim.sim.battery import BatteryReading
from haven_sim.sim.flight import clear_height
from haven_sim.sim.occupancy import OccupancyGridData, on_the_floor
from haven_viz.cues import CUES, PATH_NS, ArCues, CueState

STOPPED_MPS = 0.02  # the robot counts as standing still (the battery charges only then)
STRANDED_S = 5.0  # a flat battery off the base for this long ends the trial
RESEND_AFTER_S = 1.0  # standing still short of the base (or off on another node's goal) this long: ask once more
GOAL_MATCH_M = 0.01  # a plan's goal this close to the mission's (events round to 1 mm) is the mission's


def any_reader(topic: str) -> str:
    return "/" + topic.lstrip("/")  # how `wait_for` says "whichever node reads this topic" (somebody's own planner)


@config
class DirectorConfig:
    scenario: str = param("hallway", "a shipped scenario name or a scenario YAML")
    seed: int = param(0, "seed of the simulated participants and the random gem order")
    rate_hz: float = param(10.0, "rules, participants and mission (sim time)", POSITIVE)


@config
class ScenarioNodeConfig:
    robot: RobotChoice = group(RobotChoice)
    director: DirectorConfig = group(DirectorConfig)
    wait_for: tuple[str, ...] = param(
        ("planner",), "nodes that must be listening before the trial starts (/topic: any reader of it)"
    )
    hold_start: bool = param(
        False, "the trial starts only on a `start` on /haven/trial_control (the researcher console's Start)"
    )


class TrialDirector:
    name = "scenario"
    unread: frozenset[str] = frozenset()

    def __init__(self, scenario: Scenario, seed: int = 0, rate_hz: float = 10.0) -> None:
        self.scenario = scenario
        self.seed = seed
        self.rate_hz = rate_hz
        self.start_allowed = True  # the scenario node holds the start until every listener is there
        self.held = False  # ... and, when told to, until the researcher says start (TrialCommand.START)
        self._status = ""
        self.planner: GridPlanner | None = None
        self.participants: dict[str, Participant] = {}
        self.models = {h.id: h.model for h in scenario.humans}  # (each one's plugin, named when it fails)
        w = scenario.world
        self.gems = GemRules(w.gems, scenario.dwell_time_s)
        routes: dict[str, Sequence[str]] = {}
        if scenario.kind == "hallway":
            routes = {"robot": scenario.robot_route, **{h.id: h.route for h in scenario.humans}}
        self.routes = RouteRules(w, routes)
        self.obstructions = ObstructionRules(w)
        self.end_rule = EndRule(scenario.timeout_s, scenario.end_on_contact)
        self.mission: Mission | None = None
        self.humans_done: set[str] = set()
        self.contact = False
        self.robot: RobotState | None = None
        self.humans: HumanPoses = {}
        self.level: float | None = None
        self.path: list[Pose2D] = []
        self.cue_state: CueState | None = None  # what the AR cues show (None until the viz says)
        # The projected path's markers, and what the other cues show, as the viz lays them out.
        self.projection = ArCues(scenario.cues, names=[c for c in CUES if c not in BY_FIELD], robot=scenario.robot)
        self.sight: Sight | None = None
        self.percepts: dict[str, Percept] = {}  # what each simulated participant perceived at the last tick
        self.waiting = False
        self.empty_since: float | None = None  # when the battery ran out (the robot cannot drive)
        self.still_since: float | None = None  # when the robot last stopped moving
        self.sent_goal: Pose2D | None = None  # the mission's last goal
        self.diverted = False  # the planner's last plan was for another node's goal
        self.start_time: float | None = None
        self.last_tick: float | None = None
        self.ended: EndReason | None = None

    @property
    def period_s(self) -> float:
        return 1.0 / self.rate_hz

    def handlers(self) -> Mapping[str, Handler]:
        return {
            topics.MAP: self.on_map,
            topics.ODOM: self.on_odom,
            topics.HUMANS: self.on_humans,
            topics.BATTERY: self.on_battery,
            topics.PLAN: self.on_plan,
            topics.CUE_STATE: self.on_cue_state,
            topics.WAIT: self.on_wait,
            topics.EVENTS: self.on_event,
            topics.TRIAL_CONTROL: self.on_control,
        }

    def outputs(self) -> Sequence[str]:
        simulated = [topics.human_cmd_vel(h.id) for h in self.scenario.humans if not h.teleoperated]
        return (topics.GOAL, topics.THOUGHT, topics.EVENTS, topics.REMOVE_OBSTRUCTION, topics.TRIAL_STATUS, *simulated)

    # -- inputs ----------------------------------------------------------------------------------
    def on_map(self, grid: OccupancyGridData, now: float) -> list[Message]:
        # people walk round what a drone flies over
        grid = on_the_floor(grid, self.scenario.world, clear_height(self.scenario.robot))
        first = self.planner is None
        self.planner = GridPlanner(grid)
        self.sight = Sight(grid)
        try:
            if first:
                self.participants = make_participants(self.scenario, grid, self.seed)
                kind = self.scenario
                self.mission = Mission(
                    robot_targets(kind),
                    self.path_length,
                    "fixed" if kind.kind == "hallway" else kind.robot_order,
                    kind.battery,
                    kind.world.charging_base.position if kind.world.charging_base else None,
                    self.seed,
                )
                return []
            # The world changed (an obstruction went away): plan the current goal again.
            return self._mission_messages(self.mission.resend() if self.mission else MissionOutput(), now)
        except contain.PluginFailed as e:
            return self._failed(e, now)

    def on_odom(self, state: RobotState, now: float) -> list[Message]:
        self.robot = state
        return []

    def on_humans(self, humans: HumanPoses, now: float) -> list[Message]:
        self.humans = dict(humans)
        return []

    def on_battery(self, reading: BatteryReading, now: float) -> list[Message]:
        self.level = reading.level
        return []

    def on_plan(self, poses: Sequence[Pose2D], now: float) -> list[Message]:
        self.path = list(poses)
        self.projection.set_path(self.path)
        return []

    def on_cue_state(self, state: CueState, now: float) -> list[Message]:
        self.cue_state = state
        return []

    def on_wait(self, waiting: bool, now: float) -> list[Message]:
        self.waiting = waiting
        return []

    def on_event(self, e: Event, now: float) -> list[Message]:
        """The study log is read for two things: a robot-human contact can end a trial, and a plan
        for a goal the mission did not send (another node's: RViz, `haven goto`) means the robot is
        away on someone else's errand (`diverted`: the mission asks again once it stands still)."""
        if e.kind is EventKind.CONTACT_BEGIN and str(e["other"]).startswith("human"):
            self.contact = True
        # (another node's plugin: the trial ends)
        if e.kind in (EventKind.PLUGIN_FAILED, EventKind.CUE_FAILED) and self.ended is None:
            self.ended = EndReason.PLUGIN_FAILED
            return [self._event(EventKind.TRIAL_END, now, reason=self.ended), *self._status_messages(now)]
        goal = e.get("goal")
        if (
            e.kind in (EventKind.PLAN_MADE, EventKind.PLAN_REFUSED)
            and self.sent_goal is not None
            and isinstance(goal, list)
            and len(goal) == 2
        ):
            self.diverted = math.dist(goal, (self.sent_goal.x, self.sent_goal.y)) > GOAL_MATCH_M
        return []

    def on_control(self, text: str, now: float) -> list[Message]:
        """The researcher's start, stop or abort, optionally followed by who asked (`abort
        dropout:h1`: the web node's drop-out policy; default `researcher`); anything else is refused
        with a ValueError."""
        command, by = TrialCommand.parse(text)
        if command is TrialCommand.START:
            self.held = False
            return []
        if self.ended is not None:
            return []
        started = self.start_time is not None
        self.ended = EndReason.STOPPED if command is TrialCommand.STOP and started else EndReason.ABORTED
        return [self._event(EventKind.TRIAL_END, now, reason=self.ended, by=by), *self._status_messages(now)]

    def status(self, now: float) -> dict[str, Any]:
        """The trial as a participant's page and the researcher console show it (data, not text):
        its state, how it ended, and each person's task progress."""
        if self.ended is not None:
            state = TrialState.ENDED
        elif self.start_time is not None:
            state = TrialState.RUNNING
        else:
            state = TrialState.HELD if self.held else TrialState.WAITING
        people: dict[str, dict[str, Any]] = {}
        for h in self.scenario.humans:
            if self.scenario.kind == "hallway":
                route = list(h.route)
                done = self.routes.progress.get(h.id, 0)
                people[h.id] = {"rooms": route, "rooms_done": done, "next_room": self.routes.next_room(h.id)}
            else:
                total = sum(1 for g in self.gems.gems.values() if g.owner == "human")
                dwell = self.gems.dwell_progress(h.id, now)
                done = total - len(self.gems.remaining("human"))
                people[h.id] = {
                    "gems_total": total,
                    "gems_done": done,
                    "dwell": None if dwell is None else round(dwell, 1),
                }
            people[h.id]["done"] = h.id in self.humans_done
        return {
            "scenario": self.scenario.name,
            "kind": self.scenario.kind,
            "state": state,
            "end_reason": self.ended,
            "humans": people,
        }

    def _status_messages(self, now: float) -> list[Message]:
        """/haven/trial_status when it changed (latched: a page that opens late still learns it);
        nothing when no one reads it (batch mode)."""
        if topics.TRIAL_STATUS in self.unread:
            return []
        text = json.dumps(self.status(now), sort_keys=True)
        if text == self._status:
            return []
        self._status = text
        return [Message(topics.TRIAL_STATUS, text, now)]

    # -- the trial ---------------------------------------------------------------------------------
    def path_length(self, a: Point, b: Point) -> float:
        if self.planner is None:
            return math.inf
        try:
            return self.planner.plan(a, b).length_m
        except PlanningError:
            return math.inf

    def _ready(self) -> bool:
        have_humans = bool(self.humans) or not self.scenario.world.humans
        return self.mission is not None and self.robot is not None and self.level is not None and have_humans

    def _event(self, kind: EventKind, now: float, **data: Any) -> Message:
        return Message(topics.EVENTS, event(kind, now, Source.SCENARIO, **data), now)

    def _mission_messages(self, m: MissionOutput, now: float) -> list[Message]:
        out = [Message(topics.EVENTS, e, now) for e in m.events]
        if m.thought is not None:
            out.append(Message(topics.THOUGHT, m.thought, now))
        if m.goal is not None:
            mission = self.mission
            assert mission is not None
            self.still_since, self.sent_goal, self.diverted = None, m.goal, False
            if mission.current is not None and mission.phase is Phase.GOING and self.scenario.kind == "retrieval":
                self.gems.robot_target = mission.current.id
            out.append(Message(topics.GOAL, Goal(m.goal), now))
            # (the study log names every goal: the validity check finds each in a recording by it)
            out.append(self._event(EventKind.GOAL_SENT, now, **{GOAL_POSE: [round(m.goal.x, 3), round(m.goal.y, 3)]}))
        return out

    def interrupt(self) -> list[Message]:
        """The trial stopped from outside (Ctrl-C): its end, at the last time the director acted,
        if it had begun and not ended."""
        if self.start_time is None or self.ended is not None or self.last_tick is None:
            return []
        self.ended = EndReason.INTERRUPTED
        return [
            self._event(EventKind.TRIAL_END, self.last_tick, reason=self.ended),
            *self._status_messages(self.last_tick),
        ]

    def tick(self, now: float) -> list[Message]:
        self.last_tick = now
        try:
            out = self._tick(now) if self.ended is None and self._ready() else []
        except contain.PluginFailed as e:
            # (a participant model or the mission behaviour: what this tick made is dropped)
            return self._failed(e, now)
        return out + self._status_messages(now)

    def _failed(self, e: contain.PluginFailed, now: float) -> list[Message]:
        """A plugin of this node failed (raised or overran its deadline): the trial ends, not valid."""
        self.ended = EndReason.PLUGIN_FAILED
        failed = Message(topics.EVENTS, contain.failed_event(e, now, Source.SCENARIO), now)
        return [failed, self._event(EventKind.TRIAL_END, now, reason=self.ended), *self._status_messages(now)]

    def _tick(self, now: float) -> list[Message]:
        mission, robot, level = self.mission, self.robot, self.level
        assert mission is not None and robot is not None and level is not None
        self._observe(now, robot, level)
        if self.start_time is None:
            if not self.start_allowed or self.held:
                return []
            self.start_time = now
            return [
                self._event(EventKind.TRIAL_START, now, scenario=self.scenario.name),
                *self._mission_messages(mission.start(now, robot.pose, level), now),
            ]
        return self._step(now, mission, robot.pose, level)

    def _observe(self, now: float, state: RobotState, level: float) -> None:
        """Since when the robot stands still, and since when its battery is flat (state topics'
        handlers only keep the latest value: what changed is judged here, at the tick)."""
        moving = abs(state.twist.vx) > STOPPED_MPS or abs(state.twist.wz) > 0.05
        if moving:
            self.still_since = None
        elif self.still_since is None:
            self.still_since = now
        if level > 0.0:
            self.empty_since = None
        elif self.empty_since is None:
            self.empty_since = now

    def _step(self, now: float, mission: Mission, robot: Pose2D, level: float) -> list[Message]:
        """The 10 Hz step: participants move, rules fire, the mission decides, the end is checked."""
        out: list[Message] = []
        cues, sight = self.cue_state, self.sight
        assert sight is not None
        shows_path = cues is not None and cues.toggles.on(PATH_NS) and cues.path_markers > 0
        markers = self.projection.shown_points(robot) if shows_path else []
        thought = self.mission.thought if self.mission is not None else ""
        ways = cue_ways(
            self.projection, cues, robot, [(h.x, h.y) for h in self.humans.values()], self.level, thought, now
        )
        for hid, walker in self.participants.items():
            if hid in self.humans:
                me = self.humans[hid]
                others = [pose for other, pose in self.humans.items() if other != hid]
                self.percepts[hid] = seen = perceive(
                    walker.params, sight, now, me, robot, cues, markers, ways, self.scenario.robot.radius_m
                )
                cmd = contain.call("participants", self.models[hid], walker.command, now, me, robot, seen, others)
                out.append(Message(topics.human_cmd_vel(hid), cmd, now))
        fired = self.gems.update(now, robot, self.humans) + self.routes.update(now, {"robot": robot, **self.humans})
        fired += self.obstructions.update(now, self.humans)
        out += [Message(topics.EVENTS, e, now) for e in fired]
        for e in fired:
            if e.kind is EventKind.OBSTRUCTION_CLEARED:
                out.append(Message(topics.REMOVE_OBSTRUCTION, e["id"], now))
            elif e.kind is EventKind.GEM_COLLECTED and e["by"] == "robot":
                out += self._mission_messages(mission.target_done(now, e["gem"], robot, level), now)
            elif (
                e.kind is EventKind.ROOM_REACHED
                and e["by"] == "robot"
                and mission.current is not None
                and e["room"] == mission.current.id
            ):
                out += self._mission_messages(mission.target_done(now, e["room"], robot, level), now)
        # Every person's task counts, simulated or teleoperated: a trial with a person ends when
        # they are done too (their TASK_DONE tells their client).
        people = {h.id for h in self.scenario.humans}
        for hid in sorted(people - self.humans_done):
            if self._human_finished(hid):
                self.humans_done.add(hid)
                out.append(self._event(EventKind.TASK_DONE, now, by=hid))
        out += self._charging(now, mission, robot, level)
        all_done = mission.phase is Phase.DONE and self.humans_done >= people
        elapsed = now - (self.start_time if self.start_time is not None else now)
        stranded = self.empty_since is not None and now - self.empty_since > STRANDED_S
        self.ended = (
            EndReason.BATTERY_EMPTY
            if stranded and not all_done
            else self.end_rule.reason(elapsed, all_done, self.contact)
        )
        if self.ended is not None:
            out.append(self._event(EventKind.TRIAL_END, now, reason=self.ended))
        return out

    def _charging(self, now: float, mission: Mission, robot: Pose2D, level: float) -> list[Message]:
        """Tell the mission when the robot stands on the base; send it there again if it stopped short."""
        base = self.scenario.world.charging_base
        still = self.still_since is not None
        at_base = base is not None and still and robot.distance_to(base.position) <= base.radius
        out: list[Message] = []
        stuck = self.still_since is not None and now - self.still_since >= RESEND_AFTER_S and not self.waiting
        if base is not None and stuck and not at_base and mission.phase is Phase.TO_BASE:
            out += self._mission_messages(mission.resend(), now)  # stopped short of (or past) the base
        elif stuck and self.diverted:
            out += self._mission_messages(mission.resend(), now)  # back from someone else's errand
        return out + self._mission_messages(mission.tick(now, robot, level, at_base, self.waiting), now)

    def _human_finished(self, hid: str) -> bool:
        if self.scenario.kind == "hallway":
            return self.routes.done(hid)
        return not self.gems.remaining("human")
