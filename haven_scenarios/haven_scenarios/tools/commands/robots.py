"""`haven robots`: the robots to choose from (`--robot NAME`), one line each with its key figures;
`haven robots NAME|FILE`: one robot's figures, each with where it comes from."""

from __future__ import annotations

import argparse
import dataclasses
import sys
from collections.abc import Iterator
from typing import Any

from haven_scenarios.tools.commands.common import fail
from haven_sim.common import plugins
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.robot_file import RobotError
from haven_sim.robots.robot_kind import resolve_robot

# The description's parts that are figures (dotted paths under these are listed with `haven robots NAME`).
FIGURES = (
    "kinematics",
    "footprint",
    "height_m",
    "mass_kg",
    "limits",
    "motion",
    "battery",
    "lidar",
    "flight",
    "cues",
    "frames",
    "drive",
)


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    said = (
        "the robots to choose from (--robot NAME): one per line, "
        "its name then its key figures; with NAME or FILE, its figures and sources"
    )
    robots = sub.add_parser("robots", help=said, description=said + " (docs: Robots)")
    robots.add_argument(
        "robot", nargs="?", metavar="NAME|FILE", help="a registered robot's name or a robot file (.yaml)"
    )
    robots.set_defaults(func=robots_cmd)


def robots_cmd(args: argparse.Namespace) -> int:
    if args.robot is not None:
        try:
            robot = resolve_robot(args.robot)
        except RobotError as e:
            return fail(str(e))
        for line in figure_lines(robot):
            print(line)
        return 0
    reg = plugins.registry("robots")
    width = max((len(item.name) for item in reg), default=0)
    for item in reg:
        print(f"{item.name:<{width}}  {item.value.key_figures()}")
    for line in reg.problems:
        print(f"haven: plugin left out: {line}", file=sys.stderr)
    return 1 if reg.problems else 0


def figure_lines(robot: RobotDescription) -> list[str]:
    """The robot's title, then `path = value  (source)` per figure; a figure the file left to the
    suite's default (or to what follows from the body) says so."""
    lines = [f"{robot.name}: {robot.title}", f"  {robot.key_figures()}"]
    if robot.source_file:
        lines.append(f"  file: {robot.source_file}")
    for path, value in leaves(robot):
        lines.append(f"  {path} = {shown(value)}  ({source_of(robot, path)})")
    return lines


def leaves(robot: RobotDescription) -> Iterator[tuple[str, Any]]:
    for name in FIGURES:
        for path, value in _leaves(name, getattr(robot, name)):
            if path != "footprint.radius_m" or not robot.footprint.polygon:  # (a polygon's radius is 0)
                yield path, value


def _leaves(path: str, value: Any) -> Iterator[tuple[str, Any]]:
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        for f in dataclasses.fields(value):
            yield from _leaves(f"{path}.{f.name}", getattr(value, f.name))
    elif value is not None and value != ():
        yield path, value


def source_of(robot: RobotDescription, path: str) -> str:
    """The source under the longest key that is `path` or a prefix of it."""
    parts = path.split(".")
    for n in range(len(parts), 0, -1):
        found = robot.sources.get(".".join(parts[:n]))
        if found:
            return found
    return "no source given: the file's own figure, the suite's default or what follows from the body"


def shown(value: Any) -> str:
    if hasattr(value, "value"):  # an Enum
        return str(value.value)
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, tuple):
        return "[" + ", ".join(shown(v) for v in value) + "]"
    return str(value)


def file_schema(schema: dict[str, Any]) -> dict[str, Any]:
    """The robot file's JSON Schema as `haven schema robot` prints it: `extends` allowed, and a file
    that extends another need not repeat the top-level keys it inherits."""
    out = dict(schema)
    out["properties"] = {
        "extends": {"type": "string", "description": "a catalogue robot's name or a robot file beside this one"},
        **schema.get("properties", {}),
    }
    required = out.pop("required", [])
    if required:
        out["if"] = {"not": {"required": ["extends"]}}
        out["then"] = {"required": required}
    return out
