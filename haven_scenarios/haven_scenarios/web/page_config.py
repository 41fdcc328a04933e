"""What a page is told when it opens (JSON embedded in it): who it is, the trial, and the view.

The pages read everything that moves from the relayed topics; this is what does not: the role and
its allowed topics with their message definitions (the page encodes its own CDR), the order of the
poses on /humans, the world's extent, the participant's prompts and the questionnaires after the trial.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_scenarios.study.questionnaires import Questionnaire, in_order, item_order, trial_key
from haven_scenarios.study.scenario import Scenario
from haven_scenarios.web.access import ROBOT_MODEL_PATH, Role
from haven_scenarios.web.foxglove_relay import msgdef
from haven_scenarios.web.wizard import MAX_THOUGHT_CHARS
from haven_sim.common.bodies import EYE_HEIGHT_M, HUMAN_BODY
from haven_sim.robots.description import RobotDescription
from haven_viz.world_markers import WALL_HEIGHT_M

VIEW_WALL_HEIGHT_M = 2.4  # walls are drawn this tall in first person (the markers' 0.5 m suits a top-down view)

INSTRUCTIONS = {
    "hallway": (
        "Walk to the rooms in the order shown at the top of the screen. A robot "
        "uses the same hallway; walk as you would around a person."
    ),
    "retrieval": (
        "Collect the red gems: walk into a gem's red circle and stand still "
        "until it is collected. The robot collects the blue gems in the same room."
    ),
}
CONTROLS = (
    "W / S or ↑ / ↓: walk forward and back · A / D or ← / →: turn · "
    "Q / E: step sideways · R / F: look up and down · a gamepad works too"
)


@dataclass(frozen=True)
class PageSettings:
    """The run's choices for the pages (from `haven run --web`)."""

    participant: str = "sim"  # the study's participant id
    session: str = ""  # the session folder's name
    map_inset: bool = True
    questionnaires: tuple[Questionnaire, ...] = ()  # asked after the trial
    teleoperated: tuple[str, ...] = ()  # the humans with a page (who answers them)
    next_url: str = ""  # the page goes here once the trial and its questionnaires are over (`haven serve`)


def robot_view(robot: RobotDescription) -> dict[str, Any]:
    """What the pages draw the robot from: its look (primitives in the base frame: x forward, z up)
    and its footprint at real size; its flight height if it flies."""
    fp = robot.footprint
    return {
        "name": robot.name,
        "title": robot.title,
        "kinematics": robot.kinematics.value,
        "radius_m": robot.radius_m,
        "footprint": {"radius_m": fp.radius_m, "polygon": [list(p) for p in fp.polygon]},
        "height_m": robot.height_m,
        "primitives": [
            {
                "shape": p.shape,
                "size": list(p.size),
                "at": list(p.at),
                "rpy": list(p.rpy),
                "colour": p.colour,
                "spin": p.spin,
            }
            for p in robot.look.primitives
        ],
        "flight_height_m": robot.flight.cruise_height_m if robot.flight is not None else None,
        "model_url": ROBOT_MODEL_PATH + Path(robot.look.model).suffix if robot.look.model else None,
    }


def page_config(role: Role, scenario: Scenario, settings: PageSettings) -> dict[str, Any]:
    world = scenario.world
    speeds: Mapping[str, float] = {h.id: h.speed_mps for h in scenario.humans}
    return {
        "role": role.name,
        "console": role.is_console,
        "publish": dict(role.publish),
        "schemas": {t: msgdef(t) for t in sorted(set(role.publish.values()))},
        "parameters": role.parameters,
        "humans": [h.id for h in world.humans],  # the order of the poses on /humans
        "speed_mps": speeds.get(role.name, 1.0),
        "participant": settings.participant,
        "session": settings.session,
        "scenario": scenario.name,
        "kind": scenario.kind,
        "bounds": list(world.bounds()),
        "eye_height_m": EYE_HEIGHT_M,
        "robot_body": {"radius_m": scenario.robot.radius_m, "height_m": scenario.robot.height_m},
        "robot": robot_view(scenario.robot),
        "human_body": {"radius_m": HUMAN_BODY.radius_m, "height_m": HUMAN_BODY.height_m},
        "view_wall_height_m": VIEW_WALL_HEIGHT_M,
        "marker_wall_height_m": WALL_HEIGHT_M,
        "map_inset": settings.map_inset,
        "instructions": INSTRUCTIONS.get(scenario.kind, ""),
        "controls": CONTROLS,
        "questionnaires": [
            in_order(q, item_order(q, trial_key(settings.session, role.name))).to_dict()
            for q in settings.questionnaires
        ],
        "teleoperated": list(settings.teleoperated),
        "thought_max_chars": MAX_THOUGHT_CHARS,
        "next_url": settings.next_url,
    }
