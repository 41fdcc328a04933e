"""Topic names of the HAVEN graph (relative, so a namespace applies; /clock and TF are absolute).

Core components address their inputs and outputs by these names; the nodes map each name to its
message type and QoS (haven_sim.nodes.wire), batch mode routes them in-process.
"""

from __future__ import annotations

from haven_sim.common.params import config, param

CLOCK = "/clock"
TF = "/tf"
TF_STATIC = "/tf_static"
MAP = "map"
ODOM = "odom"
SCAN = "scan"
BATTERY = "battery_state"
HUMANS = "humans"
CMD_VEL = "cmd_vel"
CMD_VEL_NAV = "cmd_vel_nav"
CMD_VEL_TELEOP = "cmd_vel_teleop"
ESTOP = "haven/estop"
GOAL = "goal_pose"
PLAN = "plan"
WAIT = "haven/wait"
THOUGHT = "haven/thought"
WIZARD_THOUGHT = "haven/wizard_thought"  # the researcher's thought text, held (String: JSON {text, until, everywhere})
EVENTS = "haven/events"
REMOVE_OBSTRUCTION = "haven/remove_obstruction"
CANCEL_GOAL = "haven/cancel_goal"  # (String: who cancels) the planner drops its goal and the robot stops
AR_MARKERS = "haven/ar_markers"
WORLD_MARKERS = "haven/world_markers"
CUE_STATE = "haven/cue_state"
TRIAL_STATUS = "haven/trial_status"
TRIAL_CONTROL = "haven/trial_control"
# (rosgraph_msgs/Clock) the sim time the controller has acted at, after each of its ticks, to the
# velocity mux, which passes it on to the simulator once it has passed on the commands before it:
# on the free-running clock the simulator holds time within reach of it (sim/pacer.ControlPace).
# Hidden (a leading `_`): not recorded, not listed by `ros2 topic list` without --include-hidden-topics.
PACE_NAV = "haven/_pace_nav"
PACE = "haven/_pace"
# said on them while the controller drives nothing (the latest time a Clock holds): hold nothing
PACE_IDLE = float(2**31 - 1)


# The simulator's state streams: a reader needs only the newest message (a node that handles them
# keeps the latest value), so the lockstep clock hands a participant just the last one.
STATE = frozenset({CLOCK, MAP, ODOM, SCAN, BATTERY, HUMANS, TF, TF_STATIC})


def human_cmd_vel(human_id: str) -> str:
    return f"humans/{human_id}/cmd_vel"


def human_pose(human_id: str) -> str:
    """One person's pose by id (geometry_msgs/PoseStamped in map), beside /humans: no consumer has
    to rely on the world file's order of the PoseArray."""
    return f"humans/{human_id}/pose"


def human_of_cmd_vel(topic: str) -> str | None:
    """The human id of a `humans/<id>/cmd_vel` topic, else None."""
    parts = topic.strip("/").split("/")
    return parts[1] if len(parts) == 3 and parts[0] == "humans" and parts[2] == "cmd_vel" else None


ROBOT_CMD_VEL = (CMD_VEL, CMD_VEL_NAV, CMD_VEL_TELEOP)  # the robot's velocity commands


@config
class WireParams:
    """How the topics are typed, for every node (the shared section of haven.yaml)."""

    stamped_cmd_vel: bool = param(
        False,
        "/cmd_vel, /cmd_vel_nav and /cmd_vel_teleop carry "
        "geometry_msgs/TwistStamped (Nav2 Jazzy's enable_stamped_cmd_vel)",
    )
