"""Scenario node: the mission executive, the study rules and the simulated participants of one trial.

The behaviour is `haven_scenarios.study.director.TrialDirector` (shared with batch mode). The node
holds the start until the nodes in `wait_for` subscribe and its publishers have matched every
reader the graph knows, so the recorder and the planner hear the first event and goal. At the end
it publishes `trial_end`, waits until every reader of /haven/events has acknowledged it, and exits
with code 0, which is how `haven run` knows the trial is over.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from rclpy.duration import Duration

from haven_scenarios.study.director import ScenarioNodeConfig, TrialDirector, any_reader
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common import nodes, topics
from haven_sim.nodes import wire
from haven_sim.nodes.component_node import ComponentNode
from haven_sim.nodes.runner import run_node
from haven_sim.robots.robot_kind import resolve_robot
from haven_viz.nodes.conversions import viz_specs

END_ACK_TIMEOUT_S = 10.0


class ScenarioNode(ComponentNode):
    def __init__(self, cli_args: Sequence[str] | None = None) -> None:
        super().__init__(nodes.SCENARIO.name, cli_args)
        config = self.declare_config(ScenarioNodeConfig)
        c = config.director
        # The robot of the `robot` parameter (params.yaml's "/**": what the whole suite runs).
        scenario = load_scenario(c.scenario).for_robot(resolve_robot(config.robot.robot), config.robot.robot)
        self.director = TrialDirector(scenario, c.seed, c.rate_hz)
        self.wait_for = config.wait_for
        # /haven/cue_state (what the participants can perceive) is haven_viz's topic.
        self.wire(self.director, {**wire.specs(human_ids=[h.id for h in scenario.world.humans]), **viz_specs()})
        # On the lockstep clock the simulator starts stepping only when everyone is there.
        self.director.start_allowed = self.lockstep_mode
        self.director.held = config.hold_start
        self._finished = False
        self.create_timer(self.director.period_s, self._watch)
        self.get_logger().info(f"scenario '{scenario.name}' ({scenario.kind}), seed {c.seed}")

    def _watch(self) -> None:
        if self._finished:
            self._deliver_events()
            raise SystemExit(0)
        if self.director.ended is not None:
            self.get_logger().info(f"trial over: {self.director.ended}")
            self._finished = True
        elif not self.director.start_allowed:
            self.director.start_allowed = self._everyone_listening()
            if not self.director.start_allowed:
                wanted = ", ".join(f"a node reading {w}" if w.startswith("/") else w for w in self.wait_for)
                self.get_logger().info(f"the trial starts when these listen: {wanted}", throttle_duration_sec=10.0)

    def _deliver_events(self) -> None:
        """The events publisher must not go before every reader (the recorder) has trial_end."""
        if not self._pubs[topics.EVENTS].wait_for_all_acked(Duration(seconds=END_ACK_TIMEOUT_S)):
            self.get_logger().warning(f"trial_end not acknowledged by every reader within {END_ACK_TIMEOUT_S:g} s")

    def destroy_node(self) -> None:
        """Stopped mid-trial (Ctrl-C): the recording still gets its end, marked interrupted."""
        ending = self.director.interrupt()
        if ending:
            self.publish(ending)
            self._deliver_events()
        super().destroy_node()

    def _everyone_listening(self) -> bool:
        """The nodes in `wait_for` subscribe (an entry like "/goal_pose": a node that is not one of
        our observers (nodes.OBSERVERS) reads that topic: somebody's own planner), and our publishers have matched every
        subscription the graph knows of (seeing a reader in the graph comes before being able to deliver to it)."""
        listeners: set[str] = set()
        for topic in (topics.EVENTS, topics.GOAL):
            infos = self.get_subscriptions_info_by_topic(self.resolve_topic_name(topic))
            if self._pubs[topic].get_subscription_count() < len(infos):
                return False
            names = {i.node_name for i in infos}
            listeners |= names | ({any_reader(topic)} if names - nodes.OBSERVERS else set())
        return all(name in listeners for name in self.wait_for)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(ScenarioNode, args))


if __name__ == "__main__":
    main()
