"""The visualization node's behaviour without ROS: `VizComponent`.

It keeps the robot's path, pose, battery level, thought and the humans, and at `rate_hz` turns them
into HAVEN's AR cues (`cues.ArCues`) plus the moving bodies, sending only what changed
(/haven/ar_markers) with explicit DELETEs; everything, deletes included, is sent again when a viewer
joins and every `refresh_period_s`, for viewers and bag replays that start late or missed a message.
What is shown goes out as data on /haven/cue_state when it changes. The world (walls, rooms,
gems, base) goes on /haven/world_markers, again when a gem is collected or an obstruction removed.
The cue toggles are the study condition (a cue the robot does not have shows nothing); every change is a `cue_toggled`
event.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace

from haven_sim.common import contain, nodes, topics
from haven_sim.common.component import Handler, Message
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Pose2D
from haven_sim.common.params import POSITIVE, config, group, param
from haven_sim.common.state import HumanPoses, RobotState
from haven_sim.robots.fields import Robot, RobotChoice, from_robot
from haven_sim.sim.battery import BatteryReading
from haven_sim.sim.world import World
from haven_viz.cue_kind import NO_MANOEUVRE, Manoeuvre
from haven_viz.cues import ArCues, CueParams, CueState, CueToggles, Toggles
from haven_viz.markers import MarkerDiff
from haven_viz.wizard_thought import WizardThought
from haven_viz.world_markers import body_markers, world_markers

PASS_SIDES = {"left": 1, "right": -1}  # the navigator's `replanned` event's side


@config
class VizConfig:
    robot: RobotChoice = group(RobotChoice)
    description: Robot = from_robot()  # where the cues sit on it, how the world markers draw it
    toggles: CueToggles = group(Toggles)
    cues: CueParams = group(CueParams)
    world: str = param("", "world file for the world markers (haven sim passes its world)")
    rate_hz: float = param(10.0, "cue update rate (sim time)", POSITIVE)
    refresh_period_s: float = param(
        2.0, "everything is re-sent this often (late viewers, bag replay from the middle)", POSITIVE
    )
    map_frame: str = param("map", "frame of the markers")


class VizComponent:
    name = nodes.VIZ.name
    unread: frozenset[str] = frozenset()

    def __init__(self, config: VizConfig | None = None, world: World | None = None) -> None:
        self.config = config or VizConfig()
        self.world = world
        self.toggles = self.config.toggles
        self.cues = ArCues(self.config.cues, robot=self.config.description)
        self.ar_diff = MarkerDiff()
        self.world_diff = MarkerDiff()
        self.robot: Pose2D | None = None
        self.altitude_m = 0.0  # the robot's height above the floor (/odom; an aerial robot's), where its cues are drawn
        self.humans: HumanPoses = {}
        self.battery: float | None = None
        self.thought = ""
        self.wizard: WizardThought | None = None  # the researcher's text, held over the robot's own
        self.collected: set[str] = set()
        self.removed: set[str] = set()
        self.state: CueState | None = None
        self._last_refresh: float | None = None
        self._refresh_now = False
        self._world_due = world is not None
        self.told: set[str] = set()  # cues whose failure was said
        self.warnings: list[str] = []  # for the node's log

    @property
    def period_s(self) -> float:
        return 1.0 / self.config.rate_hz

    def handlers(self) -> Mapping[str, Handler]:
        return {
            topics.PLAN: self.on_plan,
            topics.ODOM: self.on_odom,
            topics.BATTERY: self.on_battery,
            topics.HUMANS: self.on_humans,
            topics.THOUGHT: self.on_thought,
            topics.WIZARD_THOUGHT: self.on_wizard_thought,
            topics.EVENTS: self.on_event,
        }

    def outputs(self) -> Sequence[str]:
        return (topics.AR_MARKERS, topics.WORLD_MARKERS, topics.CUE_STATE, topics.EVENTS)

    # -- inputs ----------------------------------------------------------------------------------
    def on_plan(self, poses: Sequence[Pose2D], now: float) -> list[Message]:
        self.cues.set_path(poses)
        return []

    def on_odom(self, state: RobotState, now: float) -> list[Message]:
        self.robot, self.altitude_m = state.pose, state.altitude_m
        return []

    def on_battery(self, reading: BatteryReading, now: float) -> list[Message]:
        self.battery = reading.level
        return []

    def on_humans(self, humans: HumanPoses, now: float) -> list[Message]:
        self.humans = dict(humans)
        return []

    def on_thought(self, text: str, now: float) -> list[Message]:
        self.thought = text
        return []

    def on_wizard_thought(self, text: str, now: float) -> list[Message]:
        try:
            self.wizard = WizardThought.from_json(text)
        except ValueError as e:
            self.warnings.append(f"{topics.WIZARD_THOUGHT}: {e}")
        return []

    def on_event(self, e: Event, now: float) -> list[Message]:
        m = self.cues.manoeuvre
        if e.kind is EventKind.REPLANNED and e.get("side") in PASS_SIDES:  # a pass round a person begins
            self.cues.manoeuvre = Manoeuvre(m.count + 1, PASS_SIDES[e["side"]])
            return []
        if e.kind is EventKind.REVERTED:  # ... its way back to the route
            self.cues.manoeuvre = replace(m, returning=True)
            return []
        if e.kind is EventKind.PLAN_MADE:  # a new goal: no pass under way
            self.cues.manoeuvre = NO_MANOEUVRE
            return []
        if e.kind is EventKind.GEM_COLLECTED:
            self.collected.add(e["gem"])
        elif e.kind is EventKind.OBSTRUCTION_REMOVED:
            self.removed.add(e["id"])
        elif e.kind is EventKind.RESET:
            self.collected.clear()
            self.removed.clear()
        else:
            return []
        self._world_due = self.world is not None
        return []

    def set_toggles(self, changes: Mapping[str, bool], now: float) -> list[Message]:
        """Switch cues on or off (the study condition); each change is an event, shown at once."""
        before = self.toggles
        self.toggles = before.replaced(changes)
        out = [
            Message(topics.EVENTS, event(EventKind.CUE_TOGGLED, now, Source.VIZ, cue=name, on=on), now)
            for name, on in changes.items()
            if before.on(name) != on
        ]
        return out + self.tick(now)

    def _failures(self, now: float) -> list[Message]:
        """A `plugin_failed` event (and a warning) for each cue whose code failed since the last tick."""
        out = []
        for cue, error in self.cues.failed.items():
            if cue not in self.told:
                self.told.add(cue)
                self.warnings.append(f"cue {cue} failed and is not shown from now on: {error}")
                out.append(
                    Message(
                        topics.EVENTS,
                        contain.failed_event(contain.PluginFailed("cues", cue, error), now, Source.VIZ),
                        now,
                    )
                )
        return out

    def viewer_joined(self) -> None:
        """A new subscriber: send everything at the next tick."""
        self._refresh_now = True

    # -- outputs ---------------------------------------------------------------------------------
    def _world_messages(self, now: float) -> list[Message]:
        if not self._world_due or self.world is None or topics.WORLD_MARKERS in self.unread:
            return []
        self._world_due = False
        # Latched with depth 1: a late viewer gets only the last message, so it carries everything.
        update = self.world_diff.update(world_markers(self.world, self.collected, self.removed), resend_all=True)
        return [Message(topics.WORLD_MARKERS, update, now)] if update else []

    def tick(self, now: float) -> list[Message]:
        out = self._world_messages(now)
        if self.robot is None:
            return out
        humans_xy = [(h.x, h.y) for h in self.humans.values()]
        shown = topics.AR_MARKERS not in self.unread
        wizard = self.wizard if self.wizard is not None and now < self.wizard.until else None
        thought = wizard.text if wizard is not None else self.thought
        everywhere = wizard is not None and wizard.everywhere
        frame = self.cues.frame(
            self.robot,
            humans_xy,
            self.battery,
            thought,
            self.toggles,
            now,
            markers=shown,
            altitude_m=self.altitude_m,
            thought_everywhere=everywhere,
        )
        out += self._failures(now)
        refresh = (
            self._refresh_now or self._last_refresh is None or now - self._last_refresh >= self.config.refresh_period_s
        )
        if refresh:
            self._last_refresh, self._refresh_now = now, False
        if shown:
            update = self.ar_diff.update(
                frame.markers + body_markers(self.robot, self.humans, self.config.description), resend_all=refresh
            )
            if update:
                out.append(Message(topics.AR_MARKERS, update, now))
        if frame.state != self.state:  # on change only (latched: a late reader gets the last one)
            self.state = frame.state
            out.append(Message(topics.CUE_STATE, frame.state, now))
        return out
