"""Cues are plugins (cue_kind.py): HAVEN's four come through the registry as a lab's cue does; a
broken or clashing cue is one line; a lab's cue is drawn, said on /haven/cue_state and read back."""

from __future__ import annotations

import dataclasses

from fake_plugins import Entry

from haven_sim.common import plugins
from haven_sim.common.geometry import Pose2D
from haven_viz.cue_kind import CueContext, Shown, accept_plugin
from haven_viz.cues import CUE_SPECS, CUES, ArCues, CueParams, CueState, CueToggles, cue_specs
from haven_viz.markers import MarkerSpec, Shape


class Beacon:
    """A lab's cue: a light on the robot, on while the robot has a path ahead."""

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        if ctx.path.remaining_m <= 0:
            return None
        light = MarkerSpec(
            "beacon", 0, Shape.SPHERE, (ctx.robot.x, ctx.robot.y, ctx.robot_height_m + 0.1), 0.0, (0.1, 0.1, 0.1)
        )
        return Shown(True, [light] if markers else [])


def test_havens_cues_are_registered_plugins_in_their_order():
    reg = plugins.registry("cues")
    assert CUES[:4] == ("path_projection", "turn_signals", "thought_bubble", "battery_indicator")
    assert all(
        reg.items[c].package == "haven_viz" and reg.items[c].target.startswith("haven_viz.builtin_cues:")
        for c in CUES[:4]
    )


def test_a_broken_or_clashing_cue_is_one_line_and_the_others_stay():
    class Thinks(Beacon):
        key = "thought"  # HAVEN's thought bubble's key

    reg = plugins.load(
        "cues",
        [
            Entry(
                "thought_bubble", "haven_viz.builtin_cues:ThoughtBubble", "haven_viz", CUE_SPECS["thought_bubble"].make
            ),
            Entry("beacon", "lab.cues:Beacon", "lab_cues", Beacon),
            Entry("thinks", "lab.cues:Thinks", "lab_cues", Thinks),
            Entry("text", "lab.cues:TEXT", "lab_cues", "not a class"),
        ],
    )
    specs = cue_specs(reg)
    assert list(specs) == ["thought_bubble", "beacon"]
    beacon = specs["beacon"]
    assert (beacon.key, beacon.hidden, beacon.exposure, beacon.rank, beacon.default_on) == (
        "beacon",
        None,
        "beacon_shown_s",
        100,
        True,
    )  # (the defaults)
    assert not hasattr(Beacon, "key") and beacon.make is Beacon  # (read, never written onto the lab's class)
    said = "\n".join(reg.problems)
    assert len(reg.problems) == 2 and "haven.cues text (lab.cues:TEXT, from lab_cues): is not a cue" in said
    assert (
        "haven.cues thinks (lab.cues:Thinks, from lab_cues): its state key 'thought' is taken by cue thought_bubble"
        in said
    )
    assert "thinks" in reg.left_out and "thinks" not in reg


def test_a_labs_cue_is_drawn_said_and_read_back_like_havens(monkeypatch):
    import haven_viz.cues as cues

    monkeypatch.setitem(cues.CUE_SPECS, "beacon", accept_plugin("beacon", Beacon))  # (as if installed)
    both = dataclasses.make_dataclass(
        "Both", [("path_projection", bool, True), ("beacon", bool, True)], bases=(CueToggles,), frozen=True
    )
    arcues = ArCues(CueParams(), names=["path_projection", "beacon"])
    arcues.set_path([Pose2D(0.0, 0.0, 0.0), Pose2D(2.0, 0.0, 0.0)])
    frame = arcues.frame(Pose2D(0.0, 0.0, 0.0), toggles=both())
    assert {m.ns for m in frame.markers} == {"path_projection", "beacon"}
    assert frame.state.value("beacon") is True and frame.state.shown("beacon")
    stamp, back = CueState.from_json(frame.state.to_json(1.5))
    assert stamp == 1.5 and back.values["beacon"] is True and back.values["path_markers"] == frame.state.path_markers
    off = arcues.frame(Pose2D(2.0, 0.0, 0.0), toggles=both())  # (at the end: nothing ahead)
    assert not off.state.shown("beacon") and "beacon" not in {m.ns for m in off.markers}


class Flaky(Beacon):
    """A lab's cue with a bug: it raises once the robot has moved."""

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        if ctx.robot.x > 0.5:
            raise ValueError("flaky cue broke\nsecond line")
        return super().show(ctx, markers)


def test_a_cue_that_raises_shows_nothing_from_then_on_and_is_said_once(monkeypatch):
    import haven_viz.cues as cues
    from haven_sim.common import topics
    from haven_sim.common.events import EventKind
    from haven_sim.common.state import RobotState
    from haven_viz.viz import VizComponent

    monkeypatch.setitem(cues.CUE_SPECS, "flaky", accept_plugin("flaky", Flaky))
    monkeypatch.setattr(cues, "CUES", (*cues.CUES, "flaky"))
    both = dataclasses.make_dataclass(
        "Both", [("path_projection", bool, True), ("flaky", bool, True)], bases=(CueToggles,), frozen=True
    )
    viz = VizComponent()
    viz.toggles = both()
    viz.on_plan([Pose2D(0.0, 0.0, 0.0), Pose2D(3.0, 0.0, 0.0)], 0.0)
    failed = []
    for k, x in enumerate((0.0, 1.0, 1.5, 2.0)):
        viz.on_odom(RobotState(Pose2D(x, 0.0, 0.0)), 0.1 * k)
        out = viz.tick(0.1 * k)
        failed += [m.data for m in out if m.topic == topics.EVENTS and m.data.kind is EventKind.PLUGIN_FAILED]
        state = [m.data for m in out if m.topic == topics.CUE_STATE]
        if x > 0.5 and state:
            assert not state[-1].shown("flaky") and state[-1].path_markers > 0  # (the others go on)
    assert [(e["kind"], e["name"], e["error"]) for e in failed] == [("cues", "flaky", "ValueError: flaky cue broke")]
    assert viz.warnings == ["cue flaky failed and is not shown from now on: ValueError: flaky cue broke"]
