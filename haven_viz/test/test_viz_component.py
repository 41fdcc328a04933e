"""The viz node's behaviour without ROS: cue state as data, toggles as events, refresh with deletes."""

from haven_sim.common import topics
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import Pose2D
from haven_sim.common.state import RobotState
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world
from haven_viz.cues import CueState, Toggles
from haven_viz.markers import MarkerDiff, MarkerSpec, Shape
from haven_viz.viz import VizComponent, VizConfig

STRAIGHT = [Pose2D(x * 0.4, 0.0, 0.0) for x in range(11)]


def by_topic(messages, topic):
    return [m.data for m in messages if m.topic == topic]


def test_refresh_resends_every_marker_and_repairs_a_lost_delete():
    diff = MarkerDiff()
    a, b = MarkerSpec("n", 0, Shape.CUBE), MarkerSpec("n", 1, Shape.CUBE)
    assert [m.key for m in diff.update([a, b]).upsert] == [("n", 0), ("n", 1)]
    gone = diff.update([a])
    assert gone.upsert == [] and gone.delete == [("n", 1)]  # only the change ... which a viewer may miss
    assert diff.update([a]).delete == []
    refresh = diff.update([a], resend_all=True)
    assert [m.key for m in refresh.upsert] == [("n", 0)] and refresh.delete == [("n", 1)]  # ... so refreshes repeat it


def test_cue_state_is_published_as_data_and_changes_with_the_condition():
    viz = VizComponent(VizConfig(toggles=Toggles(thought_bubble=False)), load_world(packaged_world("small_test")))
    viz.on_plan(STRAIGHT, 0.0)
    viz.on_odom(RobotState(Pose2D(0.0, 0.0, 0.3)), 0.0)  # the path ahead is to the right
    viz.on_humans({"h1": Pose2D(1.0, 0.0, 0.0)}, 0.0)
    viz.on_thought("Going to room B", 0.0)
    first = viz.tick(0.0)
    assert by_topic(first, topics.WORLD_MARKERS)  # the world goes out with the first tick
    (state,) = by_topic(first, topics.CUE_STATE)
    assert (
        state.turn_signal == -1
        and state.path_markers == 10
        and state.thought == ""
        and state.toggles.thought_bubble is False
    )
    assert by_topic(viz.tick(0.1), topics.CUE_STATE) == []  # unchanged: not sent again
    out = viz.set_toggles({"thought_bubble": True, "path_projection": True}, 0.2)
    toggled = by_topic(out, topics.EVENTS)
    # only real changes
    assert [(e.kind, e["cue"], e["on"]) for e in toggled] == [(EventKind.CUE_TOGGLED, "thought_bubble", True)]
    (shown,) = by_topic(out, topics.CUE_STATE)
    assert shown.thought == "Going to room B"
    assert CueState.from_json(shown.to_json(0.2)) == (0.2, shown)


def test_world_markers_follow_gems_and_a_viewer_joining_gets_everything():
    viz = VizComponent(VizConfig(), load_world(packaged_world("small_test")))
    viz.on_odom(RobotState(Pose2D(1.0, 2.5, 0.0)), 0.0)
    viz.tick(0.0)
    assert by_topic(viz.tick(0.1), topics.AR_MARKERS) == []  # nothing changed
    viz.viewer_joined()
    (full,) = by_topic(viz.tick(0.2), topics.AR_MARKERS)
    # no path, person or battery yet: the body
    assert sorted(m.key for m in full.upsert) == [("robot", 0), ("robot", 1)]
    gem = viz.world.gems[0].id
    viz.on_event(event(EventKind.GEM_COLLECTED, 0.3, Source.SCENARIO, gem=gem, by="robot"), 0.3)
    (world,) = by_topic(viz.tick(0.3), topics.WORLD_MARKERS)
    assert ("gems", 0) in world.delete


def test_the_researchers_thought_is_held_over_the_robots_own_and_shown_at_any_distance_when_asked():
    from haven_viz.wizard_thought import WizardThought

    viz = VizComponent(VizConfig(), load_world(packaged_world("small_test")))
    viz.on_odom(RobotState(Pose2D(1.0, 2.5, 0.0)), 0.0)
    viz.on_humans({"h1": Pose2D(7.0, 2.5, 0.0)}, 0.0)  # 6 m away: beyond the bubble's 3 m
    viz.on_thought("Going to room B", 0.0)
    assert by_topic(viz.tick(0.0), topics.CUE_STATE)[0].thought == ""  # nobody near
    viz.on_wizard_thought(WizardThought("Please keep to your right", until=10.0, everywhere=True).to_json(), 1.0)
    viz.on_thought("Waiting for you to pass", 2.0)  # the robot's own thought meanwhile does not overwrite it
    assert by_topic(viz.tick(2.0), topics.CUE_STATE)[0].thought == "Please keep to your right"
    (after,) = by_topic(viz.tick(10.0), topics.CUE_STATE)  # the hold is over: the robot's own, and only near
    assert after.thought == ""
    viz.on_humans({"h1": Pose2D(2.0, 2.5, 0.0)}, 10.1)
    assert by_topic(viz.tick(10.1), topics.CUE_STATE)[0].thought == "Waiting for you to pass"
    viz.on_wizard_thought("not json", 11.0)
    assert viz.warnings[-1] == "haven/wizard_thought: not JSON"
