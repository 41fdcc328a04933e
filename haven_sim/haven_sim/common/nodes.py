"""The suite's nodes, named once: each node's short name (the one `--without planner` takes and the
supervisor shows), its ROS node name, the module `python -m` runs, and what it is to the others.
Every node, component, process list and graph check reads its names here."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SuiteNode:
    key: str  # short name: `--without KEY`, the supervisor's process name
    name: str  # ROS node name
    module: str  # `python -m MODULE` runs it
    replaceable: bool = False  # may be left out for the user's own (`--without`)
    observer: bool = False  # reads what the suite publishes, acts on none of it
    node_class: str = ""  # its class in `module`, for the nodes one suite process holds together (SUITE_PROCESS)


SIM = SuiteNode("sim", "sim_node", "haven_sim.nodes.sim_node", node_class="SimNode")
MUX = SuiteNode("mux", "velocity_mux", "haven_sim.nodes.mux_node", replaceable=True, node_class="MuxNode")
PLANNER = SuiteNode("planner", "planner", "haven_sim.nodes.planner_node", replaceable=True, node_class="PlannerNode")
CONTROLLER = SuiteNode(
    "controller", "controller", "haven_sim.nodes.controller_node", replaceable=True, node_class="ControllerNode"
)
VIZ = SuiteNode("viz", "viz", "haven_viz.nodes.viz_node", replaceable=True, observer=True, node_class="VizNode")
SCENARIO = SuiteNode("scenario", "scenario", "haven_scenarios.nodes.scenario_node", node_class="ScenarioNode")
RECORDER = SuiteNode("recorder", "recorder", "haven_scenarios.nodes.recorder", observer=True)
WEB = SuiteNode("web", "web", "haven_scenarios.nodes.web_node", observer=True)
BRIDGE = SuiteNode("bridge", "haven_bridge", "haven_scenarios.nodes.bridge", observer=True)
# Nav2's action servers over the planner and controller (its process also holds planner_server,
# controller_server, waypoint_follower and amcl): `haven sim` starts it where nav2_msgs is installed.
NAV2 = SuiteNode("nav2", "bt_navigator", "haven_sim.nodes.nav2_node", replaceable=True)

COMPONENTS = (SIM, MUX, PLANNER, CONTROLLER, VIZ)  # what `haven sim` starts, in this order
TRIAL = (RECORDER, *COMPONENTS, SCENARIO)  # what `haven run` starts (and WEB with --web)
LOCKSTEP_PARTICIPANTS = (MUX, PLANNER, CONTROLLER, VIZ, SCENARIO)  # on the lockstep clock, each takes every tick
REPLACEABLE = tuple(n.key for n in COMPONENTS if n.replaceable)  # `haven run --without`
SIM_REPLACEABLE = (*REPLACEABLE, NAV2.key)  # `haven sim --without`
OBSERVERS = frozenset(n.name for n in (VIZ, RECORDER, WEB, BRIDGE))
# One process that holds the suite's nodes (those with a node_class), each with its own arguments.
SUITE_PROCESS = SuiteNode("suite", "", "haven_scenarios.nodes.suite_process")
PROCESS_LAYOUTS = ("one", "separate")  # `--processes`: the suite's nodes in one process (default) or one each
ENDS_TRIAL = frozenset({SCENARIO.key, SUITE_PROCESS.key})  # the process whose clean exit is the trial's end
BY_KEY = {n.key: n for n in (*TRIAL, WEB, BRIDGE, NAV2)}
UNNAMED = "_NODE_NAME_UNKNOWN_"  # rmw's name for a node whose name discovery has not brought yet
