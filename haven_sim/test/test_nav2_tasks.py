"""Nav2 tasks on HAVEN's planner and controller, without ROS: what goes out, which events end a
task and how, the feedback; and the planner's cancel."""

from haven_sim.common import topics
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.state import Goal, RobotState
from haven_sim.nav.nav2_tasks import VIAPOINT_RADIUS_M, NavTask, Outcome, TaskKind
from haven_sim.nav.planner import PlanFailure
from haven_sim.nav.planning import PlannerComponent
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world

A, B = Pose2D(2.0, 1.0, 0.0), Pose2D(3.0, 1.0, 0.0)


def made(p: Pose2D):
    return event(EventKind.PLAN_MADE, 1.0, Source.PLANNER, goal=[p.x, p.y])


def reached(p: Pose2D):
    return event(EventKind.GOAL_REACHED, 5.0, Source.CONTROLLER, goal=[p.x, p.y], pose=[p.x, p.y, 0.0])


def test_waypoints_go_out_one_at_a_time_and_the_task_succeeds_at_the_last():
    task = NavTask(TaskKind.FOLLOW_WAYPOINTS, [A, B], 0.0)
    (first,) = task.start(0.0)
    assert first.topic == topics.GOAL and first.data == Goal(A)
    assert task.on_event(reached(A), 1.0) == []  # (not planned yet: an earlier goal's arrival)
    task.on_event(made(A), 1.0)
    (second,) = task.on_event(reached(A), 2.0)
    assert second.data == Goal(B) and task.outcome is None and task.progress(2.0).index == 1
    task.on_event(made(B), 2.1)
    task.on_event(event(EventKind.WAITING, 3.0, Source.PLANNER, reason="person"), 3.0)
    task.on_event(event(EventKind.REPLANNED, 3.5, Source.PLANNER, side="left"), 3.5)
    assert task.on_event(reached(B), 4.0) == [] and task.outcome is Outcome.SUCCEEDED and task.recoveries == 2


def test_a_refused_plan_fails_the_task_with_the_planners_reason_and_a_missed_waypoint():
    task = NavTask(TaskKind.FOLLOW_WAYPOINTS, [A, B], 0.0)
    task.start(0.0)
    refused = event(
        EventKind.PLAN_REFUSED,
        0.1,
        Source.PLANNER,
        goal=[A.x, A.y],
        reason="goal (2.00, 1.00) is outside the map",
        failure="goal_outside_map",
    )
    task.on_event(refused, 0.1)
    assert (
        task.outcome is Outcome.ABORTED
        and task.failure is PlanFailure.GOAL_OUTSIDE_MAP
        and task.missed == [(0, PlanFailure.GOAL_OUTSIDE_MAP)]
    )
    assert "outside the map" in task.reason


def test_another_goal_preempts_a_planned_task_but_an_earlier_plan_does_not():
    task = NavTask(TaskKind.NAVIGATE_TO_POSE, [A], 0.0)
    task.start(0.0)
    task.on_event(made(Pose2D(7.0, 4.0, 0.0)), 0.1)  # planned before ours came
    assert task.outcome is None
    task.on_event(made(A), 0.2)
    task.on_event(made(Pose2D(7.0, 4.0, 0.0)), 0.3)  # somebody else's goal after ours
    assert task.outcome is Outcome.ABORTED and "another goal" in task.reason


def test_cancel_drops_the_goal_on_the_planner_and_follow_path_clears_the_plan():
    task = NavTask(TaskKind.NAVIGATE_TO_POSE, [A], 0.0, by="bt_navigator")
    task.start(0.0)
    (out,) = task.cancel(1.0)
    assert out.topic == topics.CANCEL_GOAL and out.data == "bt_navigator" and task.outcome is Outcome.CANCELED
    path = NavTask(TaskKind.FOLLOW_PATH, [Pose2D(0.0, 0.0, 0.0), A], 0.0)
    (plan,) = path.start(0.0)
    assert plan.topic == topics.PLAN and plan.data == [Pose2D(0.0, 0.0, 0.0), A]
    assert path.cancel(1.0)[0].data == [] and path.outcome is Outcome.CANCELED


def test_feedback_distance_follows_the_plan_and_on_through_later_poses_with_bt_navigators_estimate():
    task = NavTask(TaskKind.NAVIGATE_THROUGH_POSES, [A, B], 0.0)
    task.start(0.0)
    task.on_odom(RobotState(Pose2D(0.0, 1.0, 0.0), Twist2D(0.5, 0.0, 0.0)), 1.0)
    assert task.progress(1.0).distance_remaining_m == 3.0  # as the crow flies until a plan comes: 2 to A, 1 on to B
    task.on_event(made(A), 1.0)
    task.on_plan([Pose2D(0.0, 1.0, 0.0), Pose2D(0.0, 2.0, 0.0), Pose2D(2.0, 2.0, 0.0), A])  # a detour: 4 m to A
    p = task.progress(2.0)
    assert (
        abs(p.distance_remaining_m - 5.0) < 1e-9
        and abs(p.eta_s - 10.0) < 1e-9
        and p.elapsed_s == 2.0
        and p.remaining_poses == 2
    )


def test_through_poses_passes_a_pose_on_the_way_without_stopping_and_ends_at_rest_at_the_last():
    task = NavTask(TaskKind.NAVIGATE_THROUGH_POSES, [A, B], 0.0)
    task.start(0.0)
    near_a = RobotState(Pose2D(A.x - VIAPOINT_RADIUS_M + 0.05, A.y, 0.0), Twist2D(0.5, 0.0, 0.0))
    assert task.on_odom(near_a, 1.0) == []  # (the plan to A not made yet: nothing to pass)
    task.on_event(made(A), 1.0)
    assert task.on_odom(RobotState(Pose2D(0.0, 1.0, 0.0), Twist2D(0.5, 0.0, 0.0)), 1.5) == []  # still far from A
    (goal,) = task.on_odom(near_a, 2.0)  # within the radius, moving: on to B, no goal_reached at A
    assert goal.topic == topics.GOAL and goal.data == Goal(B) and task.index == 1 and task.outcome is None
    task.on_event(made(B), 2.1)
    # the last pose: at rest only
    assert task.on_odom(RobotState(B, Twist2D(0.5, 0.0, 0.0)), 3.0) == [] and task.outcome is None
    task.on_event(reached(B), 4.0)
    assert task.outcome is Outcome.SUCCEEDED
    waypoints = NavTask(TaskKind.FOLLOW_WAYPOINTS, [A, B], 0.0)  # (follow_waypoints stops at every waypoint, as Nav2's)
    waypoints.start(0.0)
    waypoints.on_event(made(A), 1.0)
    assert waypoints.on_odom(RobotState(A), 2.0) == [] and waypoints.index == 0


def test_the_planner_drops_its_goal_on_cancel_and_says_so():
    planner = PlannerComponent()
    world = load_world(packaged_world("small_test"))
    planner.on_map(rasterise(world), 0.0)
    planner.on_odom(RobotState(Pose2D(*world.robot_start)), 0.0)
    out = planner.on_goal(Goal(Pose2D(2.2, 4.2, 0.0)), 0.0)
    assert any(m.topic == topics.PLAN and m.data for m in out)
    cancelled = planner.on_cancel("bt_navigator", 1.0)
    assert [m.data for m in cancelled if m.topic == topics.PLAN] == [[]]  # an empty plan: the controller stops at once
    (e,) = [m.data for m in cancelled if m.topic == topics.EVENTS and m.data.kind is EventKind.GOAL_CANCELLED]
    assert e.data["by"] == "bt_navigator" and planner.nav is not None and planner.nav.goal is None
    assert planner.on_cancel("again", 2.0) == [] and planner.tick(2.0) == []  # nothing to cancel: nothing said


def test_a_robot_that_makes_no_progress_fails_its_task_and_is_stopped():
    task = NavTask(TaskKind.NAVIGATE_TO_POSE, [A], 0.0, by="bt_navigator")
    task.start(0.0)
    task.on_odom(RobotState(Pose2D(0.0, 0.0, 0.0)), 0.0)
    assert task.check_progress(0.0, 30.0) == []
    task.on_odom(RobotState(Pose2D(0.6, 0.0, 0.0)), 20.0)
    assert task.check_progress(20.0, 30.0) == []  # moved 0.6 m: progress made at 20 s
    task.on_odom(RobotState(Pose2D(0.9, 0.0, 0.0)), 21.0)  # 0.3 m more: not enough to count
    assert task.check_progress(49.0, 30.0) == [] and task.outcome is None
    (stop,) = task.check_progress(50.5, 30.0)
    assert (
        stop.topic == topics.CANCEL_GOAL
        and task.stalled
        and task.outcome is Outcome.ABORTED
        and "no progress" in task.reason
    )
