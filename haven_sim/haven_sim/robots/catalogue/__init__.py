"""HAVEN's robot catalogue: one robot file per robot in this folder, each figure with its source.

Each is registered in haven_sim's pyproject.toml as a lab's robot is (`turtlebot2 =
haven_sim.robots.catalogue:turtlebot2`): the attribute is the file's path.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path


def path_of(name: str) -> Path:
    return Path(str(resources.files(__name__) / f"{name}.yaml"))


def __getattr__(name: str) -> Path:
    found = path_of(name)
    if not found.is_file():
        raise AttributeError(f"no catalogue robot file {name}.yaml")
    return found
