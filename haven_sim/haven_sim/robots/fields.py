"""The robot in the nodes' configs: one `robot` parameter (a name or a robot file; shared by every
node, like the motion style) and fields filled from its description, never parameters themselves.

A config field made with `from_robot("limits.max_linear_speed_mps")` holds that figure, and one
made with `from_robot()` the whole description; their defaults are the default robot's (TurtleBot2),
so a config made in code is a TurtleBot2's. `with_robot` fills them from another robot:
`build_config` does it for every config read from parameters (nodes and batch mode alike), and
batch mode again when a trial names its own robot.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Annotated, Any, TypeVar

import pydantic

from haven_sim.common.params import Bounds, ParamsError, build, config, internal, is_config, param
from haven_sim.robots.catalogue import path_of
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.robot_file import read_robot_file
from haven_sim.robots.robot_kind import DEFAULT_ROBOT, resolve_robot

T = TypeVar("T")
# A config field holding a whole robot description: taken as it is (it was checked when its robot
# file was read; pydantic would copy it to validate it again).
Robot = Annotated[RobotDescription, pydantic.InstanceOf]

DEFAULT = read_robot_file(path_of(DEFAULT_ROBOT))  # the defaults' robot, read once at import
ROBOT_KEY = "robot"  # field metadata: the figure's path in the description ("" = the whole)


@config
class RobotChoice:
    robot: str = param(DEFAULT_ROBOT, "the robot: a name from `haven robots` or a robot YAML file (haven run --robot)")


def from_robot(path: str = "", bounds: Bounds | None = None) -> Any:
    """A config field set from the robot's description (not a parameter; still checked against
    `bounds`, as for a config made in code)."""
    return internal(DEFAULT if not path else DEFAULT.value_at(path), bounds, **{ROBOT_KEY: path})


def uses_robot(cls: Any) -> bool:
    """Whether a config class (or one of its groups) has fields from the robot."""
    for f in dataclasses.fields(cls):
        if ROBOT_KEY in f.metadata:
            return True
        if is_config(f.default_factory) and uses_robot(f.default_factory):
            return True
    return False


def with_robot(config: T, robot: RobotDescription, choice: str | None = None) -> T:
    """`config` with every robot field from `robot` (through nested configs), and its `robot`
    parameter set to `choice` (default: the robot's name) where it has one."""
    changes: dict[str, Any] = {}
    for f in dataclasses.fields(config):  # type: ignore[arg-type]
        value = getattr(config, f.name)
        if ROBOT_KEY in f.metadata:
            path = f.metadata[ROBOT_KEY]
            changes[f.name] = robot if not path else robot.value_at(path)
        elif isinstance(value, RobotChoice):
            changes[f.name] = RobotChoice(choice or robot.name)
        elif dataclasses.is_dataclass(value) and not isinstance(value, type) and uses_robot(type(value)):
            changes[f.name] = with_robot(value, robot, choice)
    return dataclasses.replace(config, **changes) if changes else config  # type: ignore[type-var]


def robot_choice(config: Any) -> str | None:
    """The `robot` parameter's value in a config (None: it has none)."""
    for f in dataclasses.fields(config):
        value = getattr(config, f.name)
        if isinstance(value, RobotChoice):
            return value.robot
    return None


def apply_chosen_robot(config: T) -> T:
    """`config` with the robot its own `robot` parameter names (RobotError, one line, if unknown)."""
    choice = robot_choice(config)
    if choice is None or not uses_robot(type(config)):
        return config
    return with_robot(config, resolve_robot(choice), choice)


def build_config(cls: type[T], values: Mapping[str, Any], where: str = "") -> T:
    """A config read from parameters (`params.build`), with the fields of the robot its own `robot`
    parameter names: how every node's and batch trial's config is made."""
    made = build(cls, values, where)
    try:
        return apply_chosen_robot(made)
    except ParamsError:
        raise
    except ValueError as e:
        raise ParamsError(f"{where}{e}") from None


def robot_figures() -> dict[str, str]:
    """Each figure a robot file sets, by its last name, as a parameter file's reader says it: a
    figure like `max_linear_speed_mps` is the robot's, not a node parameter."""
    return {
        path.rsplit(".", 1)[-1]: f"it is the robot's, {path} in a robot file (haven run --robot FILE)"
        for path in DEFAULT.sources
    }
