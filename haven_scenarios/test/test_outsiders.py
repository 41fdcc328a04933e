"""The table of who in the suite writes what (record/outsiders.py) against the components' own
outputs and the web pages' allow-lists, and the publisher log the recorder keeps."""

from haven_scenarios.record.outsiders import (
    ALWAYS_OPEN,
    UNNAMED,
    WEB,
    WRITERS,
    Declared,
    PublisherLog,
    judge,
    open_topics,
    outsiders,
    watched,
    writers,
)
from haven_scenarios.record.timeline import Recording
from haven_scenarios.record.validity import check
from haven_scenarios.run.trial import Trial
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.web.access import CONSOLE_ROLE, NOT_ROS, participant_role
from haven_sim.common.events import PLAN_POSES, EventKind, Source, event
from haven_sim.common.geometry import Pose2D
from haven_sim.common.state import RobotState


def absolute(topic: str) -> str:
    return "/" + topic.lstrip("/")


def test_every_topic_a_component_writes_names_it_as_a_writer_and_nothing_else_does():
    trial = Trial(load_scenario("hallway"), 0)
    components = [trial.sim, *trial.loop.components]
    written: dict[str, set[str]] = {}
    for c in components:
        for topic in c.outputs():
            if watched(absolute(topic)):
                written.setdefault(absolute(topic), set()).add(c.name)
    pages = {t for t in [*CONSOLE_ROLE.publish, *participant_role("h1").publish] if t not in NOT_ROS}
    for topic in pages:
        written.setdefault(topic, set()).add(WEB)
    written.setdefault("/haven/events", set()).add(WEB)  # (the web node logs the console's interventions)
    for topic, nodes in written.items():
        assert nodes <= writers(topic), topic
    for pattern, nodes in WRITERS.items():  # no stale entry: each writer named writes a matching topic
        concrete = pattern.replace("*", "h1")
        assert nodes <= written.get(concrete, set()), pattern
    assert not watched("/scan") and not watched("/tf") and watched("/humans/h7/cmd_vel")


def test_the_log_names_a_publisher_once_its_node_is_known_and_reads_back():
    log = PublisherLog()
    assert log.observe("/goal_pose", [(UNNAMED, "g1")], 1.0) == []  # (its node's name comes later)
    (seen,) = log.observe("/goal_pose", [("rviz", "g1")], 2.0)
    assert (seen.node, seen.first_s, seen.last_s) == ("rviz", 1.0, 2.0)
    assert log.observe("/goal_pose", [("rviz", "g1")], 9.0) == [] and seen.last_s == 9.0
    again = PublisherLog.from_json(log.to_json())
    assert again.seen == log.seen
    assert PublisherLog.from_json("[{broken").seen == {} and PublisherLog.from_json('[{"topic": 1}]').seen == {}


def test_outsiders_are_publishers_not_of_the_suite_and_second_ones_under_our_names():
    log = PublisherLog()
    log.observe("/odom", [("sim_node", "a")], 0.0)
    log.observe("/odom", [("sim_node", "b")], 1.0)  # another suite's simulator
    log.observe("/plan", [("planner_server", "c")], 0.5)  # Nav2's, with `--without planner`
    log.observe("/haven/estop", [("teleop", "d")], 0.5)
    nodes = frozenset({"sim_node", "planner", "scenario"})
    found = outsiders(log, Declared(nodes, open_topics(without=["planner"])))
    assert [(s.topic, s.gid) for s in found] == [("/odom", "b")]
    assert "/plan" in open_topics(without=["planner"]) and set(ALWAYS_OPEN) <= set(open_topics())
    assert "/humans/h1/cmd_vel" in open_topics(teleop=["h1"])


def test_an_outsider_gone_before_the_start_and_its_early_plans_still_count():
    """A goal flood over before trial_start can have moved the robot the trial starts from: its
    publisher counts (the recorder saw it at 1-2 s, the trial ran 5-9 s), and so do the plans the
    planner made before the start, even with no publisher seen at all (gone before the recorder
    looked). With /goal_pose opened both are notes; after the end nothing counts."""
    log = PublisherLog()
    log.observe("/goal_pose", [("goal_flood", "f")], 1.0)
    log.observe("/goal_pose", [("goal_flood", "f")], 2.0)
    nodes = frozenset({"sim_node", "planner", "scenario"})
    reasons, notes = judge(log, Declared(nodes), (5.0, 9.0))
    assert reasons == ["/goal_pose: published by goal_flood from outside the suite"] and notes == []
    assert judge(log, Declared(nodes), (0.0, 0.5)) == ([], [])  # (came after the end)
    rec = Recording(odom=[(t / 10, RobotState(Pose2D(0.0, 0.0, 0.0))) for t in range(50, 91)])
    rec.events = [
        event(EventKind.PLAN_MADE, 2.0, Source.PLANNER, **{PLAN_POSES: 3}),
        event(EventKind.TRIAL_START, 5.0, Source.SCENARIO, scenario="x"),
        event(EventKind.TRIAL_END, 9.0, Source.SCENARIO, reason="timeout"),
    ]
    early = "/plan: 1 plan(s) made before the trial began, for goals from outside the suite"
    closed = check(rec, rec.window(), Declared(nodes))
    assert not closed["valid"] and closed["invalid_reasons"] == [early]
    opened = check(rec, rec.window(), Declared(nodes, open_topics(allow=["/goal_pose"])))
    assert opened["valid"] and opened["outside_publishers"] == early
