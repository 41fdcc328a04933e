"""What a robot is as a plugin: the kind `haven.robots` (common/plugins.py), and how a name or a
file given anywhere (`--robot`, a scenario's `robot: {model: ...}`, a study's factor, the `robot`
parameter) becomes a description.

A lab's package registers a robot as HAVEN's catalogue does, with a robot file::

    entry_points={"haven.robots": ["my_bot = my_lab.robots:MY_BOT"]}

where `MY_BOT` is the path of a robot YAML file (a str or Path; `robot_file.py` says its keys), or a
`RobotDescription` made in code. A path (anything ending .yaml/.yml, or an existing file) is read
as a robot file instead of being looked up by name.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

from haven_sim.common import plugins
from haven_sim.common.yaml_file import file_label
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.robot_file import RobotError, merged, read_robot_file

DEFAULT_ROBOT = "turtlebot2"


def accept_plugin(name: str, value: Any) -> RobotDescription:
    """A `haven.robots` plugin: a robot file's path, or a RobotDescription; its name must be the
    registered one (so a file can never answer to another name)."""
    if isinstance(value, (str, Path)):
        try:
            value = read_robot_file(value, base=_registered_data)
        except RobotError as e:
            raise ValueError(str(e)) from None
    if not isinstance(value, RobotDescription):
        raise ValueError("is not a robot: the path of a robot YAML file or a RobotDescription")
    if value.name != name:
        raise ValueError(f"its file names it {value.name!r}, not {name!r}")
    return value


def is_file_spec(spec: str) -> bool:
    p = Path(spec)
    return p.suffix in (".yaml", ".yml") or p.is_file()


def resolve_robot(spec: str) -> RobotDescription:
    """The robot named `spec` (registered) or in the file `spec`; RobotError (one line) otherwise."""
    if is_file_spec(spec):
        path = Path(spec).expanduser().resolve()
        try:
            mtime = path.stat().st_mtime_ns
        except OSError:
            raise RobotError(f"{file_label(spec)}: no such robot file") from None
        return _read(str(path), mtime)
    try:
        found: RobotDescription = plugins.registry("robots").get(spec)
    except plugins.PluginError as e:
        raise RobotError(f"{e} (or give a robot file: a path ending .yaml)") from None
    return found


@cache
def _read(path: str, mtime: int) -> RobotDescription:
    return read_robot_file(path, base=_registered_data)


def _registered_data(name: str, where: str) -> dict[str, Any]:
    """The mapping of the registered robot `name` (what a file's `extends` starts from)."""
    try:
        robot: RobotDescription = plugins.registry("robots").get(name)
    except plugins.PluginError as e:
        raise RobotError(f"{where}: {e}") from None
    if not robot.source_file:
        raise RobotError(f"{where}: robot {name!r} was made in code, not from a file: it cannot be extended")
    return merged(Path(robot.source_file), _registered_data, 1)


def robot_names() -> list[str]:
    return plugins.registry("robots").names()
