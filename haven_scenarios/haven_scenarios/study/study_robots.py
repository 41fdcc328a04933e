"""The robot as a study's design factor (study files' `robots` and `robot_design`).

```yaml
robots: [turtlebot2, turtlebot4]   # names from `haven robots`, or robot files (relative to the study file)
robot_design: between              # between (default) | within
```

`between`: each participant meets one robot. Participants take the design's sequences in sets of
L (study/schedule.py); the first set gets the first robot, the next set the second, and so on, so
every robot meets every sequence equally often and R x L participants complete the design.
`within`: every participant meets every robot, one robot after the other, each robot a block of
the scenario blocks x conditions (a robot is not swapped between trials); the robots' order is
counterbalanced as the conditions are (`counterbalancing`), its orders combined with the
block and condition orders into the sequences. Without `robots`, every trial runs the
scenario's own robot (its `robot: model`, else TurtleBot2), as before.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_sim.common.yaml_file import file_label, short
from haven_sim.robots.robot_file import RobotError
from haven_sim.robots.robot_kind import is_file_spec, resolve_robot

MAX_ROBOTS = 8  # a study with more robots than this is a typo (and `full` orders would explode)


@dataclass(frozen=True)
class StudyRobot:
    spec: str  # as `haven run --robot` takes it: a registered name, or the file's absolute path
    name: str  # the robot's own name (the report's `robot` column)


def parse_robots(values: list[Any], source: str, error: type[ValueError] = ValueError) -> tuple[StudyRobot, ...]:
    """The study file's `robots`, each checked; `error` naming the file and the key in one line."""
    where = file_label(source)
    if len(values) > MAX_ROBOTS:
        raise error(f"{where}: robots: at most {MAX_ROBOTS} robots, got {len(values)}")
    out: list[StudyRobot] = []
    for i, value in enumerate(values):
        if not isinstance(value, str) or not value:
            raise error(
                f"{where}: robots[{i}]: must be a robot's name (haven robots) or a robot file, got {short(value)}"
            )
        spec = value
        if is_file_spec(value) and not Path(value).is_absolute():
            spec = str((Path(source).parent / value).resolve())
        try:
            robot = resolve_robot(spec)
        except RobotError as e:
            raise error(f"{where}: robots[{i}]: {e}") from None
        if robot.name in (r.name for r in out):
            raise error(f"{where}: robots[{i}]: robot {robot.name!r} is listed twice")
        out.append(StudyRobot(spec, robot.name))
    return tuple(out)
