"""The example plugins on their own: each is what its kind needs, and each does what it says."""

from types import SimpleNamespace

from haven_lab_example.floor_arrows import AHEAD_M, FloorArrows
from haven_lab_example.near import seconds_near
from haven_lab_example.people import HURRY, Hurried
from haven_lab_example.trust import TRUST

from haven_scenarios.record.metric_kind import accept_plugin as accept_metric
from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.participant_kind import accept_plugin as accept_participant
from haven_scenarios.study.participants import Walker
from haven_scenarios.study.questionnaires import accept_plugin as accept_questionnaire
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.geometry import Pose2D
from haven_viz.cue_kind import CueContext, TrackedPath, accept_plugin as accept_cue
from haven_viz.cues import CueParams


def test_each_item_is_what_its_plugin_kind_needs():
    assert accept_participant("hurried", Hurried) is Hurried
    near = accept_metric("near", seconds_near)
    assert near.compute is seconds_near and [c[0] for c in near.columns] == ["seconds_within_2m"]
    q = accept_questionnaire("trust", TRUST)
    assert (q.name, q.maximum, [i.reverse for i in q.items]) == ("trust", 7, [False, False, True])
    arrows = accept_cue("floor_arrows", FloorArrows)
    assert arrows.make is FloorArrows and (arrows.key, arrows.rank, arrows.default_on) == ("floor_arrows", 10, True)


def test_the_floor_arrows_lie_ahead_on_the_path_pointing_along_it():
    path = TrackedPath([Pose2D(0.0, 0.0, 0.0), Pose2D(1.0, 0.0, 0.0), Pose2D(1.0, 3.0, 0.0)], 0.4)
    shown = FloorArrows(CueParams()).show(CueContext(Pose2D(0.0, 0.0, 0.0), path), markers=True)
    assert shown.value == len(AHEAD_M) and not shown.on_robot
    assert [(round(x, 2), round(y, 2)) for x, y in shown.way] == [(0.6, 0.0), (1.0, 0.2), (1.0, 0.8)]
    assert [round(m.yaw, 2) for m in shown.markers] == [0.0, 1.57, 1.57] and all(
        m.position[2] < 0.05 for m in shown.markers
    )
    end = TrackedPath([Pose2D(0.0, 0.0, 0.0), Pose2D(0.5, 0.0, 0.0)], 0.4)
    # (nothing ahead)
    assert FloorArrows(CueParams()).show(CueContext(Pose2D(0.5, 0.0, 0.0), end), markers=True) is None


def test_a_hurried_person_is_faster_than_a_walker():
    planner = SimpleNamespace(free_run=lambda *args: 1.0)  # (no walls to mind here)
    assert Hurried("h1", [], planner, 1.0, 0).speed == HURRY * Walker("h1", [], planner, 1.0, 0).speed


def test_the_metric_counts_time_near_the_robot_in_a_real_trial():
    r = run_trial(load_scenario("hallway"), 0)
    near = seconds_near_of(r)
    assert 0.0 < near["seconds_within_2m"] < r.metrics["duration_s"]


def seconds_near_of(result):
    from haven_scenarios.record.metric_kind import TrialData
    from haven_scenarios.record.timeline import Timeline

    t0, t1 = result.recording.window()
    return seconds_near(TrialData(Timeline.of(result.recording, t0, t1), [], result.recording, t0, t1, None))
