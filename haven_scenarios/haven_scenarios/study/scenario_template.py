"""A scenario from a template, for a world someone has just drawn (`haven edit`): the study's
task in a word, the world's own rooms, gems and people filled in, so a new study on a new world
is a file, not code.

Tasks:
- `visit_rooms`: kind hallway; the robot visits the world's rooms in the order they were placed
  (after the first, where it starts, and back to the first), each person a walker on the same
  rooms the other way round, so they meet head-on (as the shipped `hallway` scenario does);
- `collect_gems`: kind retrieval; the robot collects its gems nearest first, each person walks
  to theirs (as the shipped `shared_room` scenario does).

The output is a plain scenario tree (what `parse_scenario` reads); it names the world by path.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

TASKS = ("visit_rooms", "collect_gems")
TIMEOUT_S = 480.0  # the shipped hallway scenario's limit (scenarios/hallway.yaml): room for slow robots
WALKING_SPEED_MPS = 1.0  # the shipped hallway scenario's walker speed (scenarios/hallway.yaml)


class TemplateError(ValueError):
    """A task the world cannot carry (one line, naming what the world lacks)."""


def scenario_template(name: str, world: str, world_data: Mapping[str, Any], task: str) -> dict[str, Any]:
    """The scenario `task` makes of `world_data` (a world file's tree), naming the world as `world`."""
    if task not in TASKS:
        raise TemplateError(f"task: must be one of {', '.join(TASKS)}, got {task!r}")
    rooms = [r["name"] for r in world_data.get("rooms") or ()]
    people = [h["id"] for h in world_data.get("humans") or ()]
    scenario: dict[str, Any] = {"name": name, "world": world, "timeout_s": TIMEOUT_S}
    if task == "visit_rooms":
        if len(rooms) < 2:
            raise TemplateError(f"task visit_rooms: needs at least 2 rooms in the world, it has {len(rooms)}")
        route = [*rooms[1:], rooms[0]]
        scenario["kind"] = "hallway"
        scenario["robot"] = {"route": route}
        scenario["humans"] = [
            {"id": h, "model": "walker", "route": route[::-1], "speed_mps": WALKING_SPEED_MPS} for h in people
        ]
        return scenario
    if not [g for g in world_data.get("gems") or () if g.get("owner") == "robot"]:
        raise TemplateError("task collect_gems: needs at least one gem for the robot in the world")
    scenario["kind"] = "retrieval"
    scenario["robot"] = {"order": "nearest"}
    scenario["humans"] = [{"id": h, "model": "walker", "speed_mps": WALKING_SPEED_MPS} for h in people]
    return scenario
