"""Scenario node: the mission executive, the study rules and the simulated participants of one trial.

Wraps `ScenarioCore` (shared with batch mode). Once /map, /odom and /battery_state have arrived it
starts the trial: goals go to /goal_pose, the robot's thoughts to /haven/thought, simulated
participants' velocities to /humans/<id>/cmd_vel, every rule firing to /haven/events (with
`obstruction_cleared` the simulator removes an obstruction). At the end it publishes `trial_end`
and exits with code 0, which is how `haven run` knows the trial is over.
"""

from __future__ import annotations

import sys

from geometry_msgs.msg import PoseArray, PoseStamped, Twist
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rclpy.node import Node
from sensor_msgs.msg import BatteryState
from std_msgs.msg import String

from haven_scenarios.study.director import CoreOutput, ScenarioCore
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.geometry import Pose2D
from haven_sim.nodes import conversions as conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node

OWN_SOURCES = {"scenario", "mission"}


class ScenarioNode(Node):
    def __init__(self) -> None:
        super().__init__("scenario")
        self.scenario = load_scenario(self.declare_parameter("scenario", "hallway").value)
        self.seed = self.declare_parameter("seed", 0).value
        rate = self.declare_parameter("rate_hz", 10.0).value
        # Nodes that must be listening before the trial starts (e.g. the recorder, the planner).
        self.wait_for = list(self.declare_parameter("wait_for", ["planner"]).value)
        if not rate > 0:
            raise ValueError(f"rate_hz must be positive, got {rate}")
        self.human_ids = [h.id for h in self.scenario.world.humans]
        self.core: ScenarioCore | None = None
        self.robot: Pose2D | None = None
        self.humans: dict[str, Pose2D] = {}
        self.level: float | None = None
        self.path: list[Pose2D] = []
        self.finished = False
        self.goal_pub = self.create_publisher(PoseStamped, "goal_pose", qos.RELIABLE)
        self.thought_pub = self.create_publisher(String, "haven/thought", qos.LATCHED)
        self.events_pub = self.create_publisher(String, "haven/events", qos.EVENTS_PUB)
        self.human_pubs = {
            h.id: self.create_publisher(Twist, f"humans/{h.id}/cmd_vel", qos.RELIABLE) for h in self.scenario.humans if h.model != "teleop"
        }
        self.create_subscription(OccupancyGrid, "map", self._on_map, qos.LATCHED)
        self.create_subscription(Odometry, "odom", self._on_odom, qos.LATEST)
        self.create_subscription(PoseArray, "humans", self._on_humans, qos.LATEST)
        self.create_subscription(BatteryState, "battery_state", self._on_battery, qos.LATEST)
        self.create_subscription(Path, "plan", self._on_plan, qos.LATCHED)
        self.create_subscription(String, "haven/events", self._on_event, qos.EVENTS)
        self.create_timer(1.0 / rate, self._tick)
        self.get_logger().info(f"scenario '{self.scenario.name}' ({self.scenario.kind}), seed {self.seed}")

    def _now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _on_map(self, msg: OccupancyGrid) -> None:
        grid = conv.occupancy_from_msg(msg)
        if self.core is None:
            self.core = ScenarioCore(self.scenario, grid, self.seed)
        else:
            self.core.set_map(grid)

    def _on_odom(self, msg: Odometry) -> None:
        self.robot = conv.pose_from_msg(msg.pose.pose)

    def _on_humans(self, msg: PoseArray) -> None:
        poses = conv.humans_from_msg(msg)
        self.humans = {hid: p for hid, p in zip(self.human_ids, poses)}

    def _on_battery(self, msg: BatteryState) -> None:
        self.level = msg.percentage

    def _on_plan(self, msg: Path) -> None:
        self.path = conv.path_from_msg(msg)

    def _on_event(self, msg: String) -> None:
        event = conv.event_from_msg(msg)
        if self.core is None or self.robot is None or event.get("source") in OWN_SOURCES:
            return
        self._apply(self.core.on_event(event, self.robot))

    def _tick(self) -> None:
        if self.finished:
            raise SystemExit(0)  # one tick after trial_end, so the event is out
        if self.core is None or self.robot is None or self.level is None or not self.humans and self.human_ids:
            return
        if self.core.start_time is None:
            if not self._everyone_listening():
                return
            self._apply(self.core.start(self._now(), self.robot, self.level))
            return
        out = self.core.tick(self._now(), self.robot, self.humans, self.level, self.path)
        self._apply(out)
        if out.end is not None:
            self.get_logger().info(f"trial over: {out.end}")
            self.finished = True

    def _everyone_listening(self) -> bool:
        """The nodes in `wait_for` subscribe, and our publishers have matched every subscription the
        graph knows of (seeing a reader in the graph comes before being able to deliver to it)."""
        listeners: set[str] = set()
        for topic, pub in (("/haven/events", self.events_pub), ("/goal_pose", self.goal_pub)):
            infos = self.get_subscriptions_info_by_topic(topic)
            if pub.get_subscription_count() < len(infos):
                return False
            listeners |= {i.node_name for i in infos}
        return all(name in listeners for name in self.wait_for)

    def _apply(self, out: CoreOutput) -> None:
        now = self._now()
        for hid, cmd in out.human_cmds.items():
            if hid in self.human_pubs:
                self.human_pubs[hid].publish(conv.twist_msg(cmd))
        if out.thought is not None:
            self.thought_pub.publish(String(data=out.thought))
        for e in out.events:
            self.events_pub.publish(conv.event_msg({"stamp": round(now, 4), **e}))
        if out.goal is not None:
            msg = PoseStamped()
            msg.header.frame_id = "map"
            msg.header.stamp = conv.time_msg(now)
            msg.pose = conv.pose_msg(out.goal)
            self.goal_pub.publish(msg)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(ScenarioNode, args))


if __name__ == "__main__":
    main()
