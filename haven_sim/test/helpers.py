"""Small worlds built in code for the core tests."""

from __future__ import annotations

from typing import Any

from haven_sim.sim.world import World
from haven_sim.sim.world_file import parse_world


def box_world(size: float = 10.0, thickness: float = 0.1, **extra: Any) -> World:
    """An empty square room [0, size]^2 whose wall centre lines run on its border."""
    s = size
    data: dict[str, Any] = {
        "name": "box",
        "walls": [
            {"segment": [[0, 0], [s, 0]], "thickness": thickness},
            {"segment": [[s, 0], [s, s]], "thickness": thickness},
            {"segment": [[s, s], [0, s]], "thickness": thickness},
            {"segment": [[0, s], [0, 0]], "thickness": thickness},
        ],
        "robot": {"start": [s / 2, s / 2, 0.0]},
    }
    data.update(extra)
    return parse_world(data, source="box.yaml")


def corridor(length: float = 12.0, width: float = 3.0, humans: list[dict[str, Any]] | None = None) -> World:
    """A closed corridor along x, robot at its west end facing east."""
    walls = [
        {"segment": [[0, 0], [length, 0]], "thickness": 0.1},
        {"segment": [[length, 0], [length, width]], "thickness": 0.1},
        {"segment": [[length, width], [0, width]], "thickness": 0.1},
        {"segment": [[0, width], [0, 0]], "thickness": 0.1},
    ]
    data = {"name": "corridor", "walls": walls, "robot": {"start": [1.0, width / 2, 0.0]}, "humans": humans or []}
    return parse_world(data, source="corridor.yaml")


def drive_closed_loop(
    sim: Any, follower: Any, seconds: float, navigator: Any = None, on_tick: Any = None
) -> list[dict[str, Any]]:
    """Run follower (20 Hz) and navigator (5 Hz) on the simulator core; returns navigator events
    (stamped with sim time). Stops early when the follower arrives."""
    from haven_sim.nav.follower import Status

    events: list[Any] = []
    ticks = int(seconds * 20)
    for k in range(ticks):
        if on_tick is not None:
            on_tick(sim, k / 20.0)
        if navigator is not None and k % 4 == 0:
            out = navigator.update(sim.robot_pose(), [(p.x, p.y) for p in sim.human_poses().values()], sim.time)
            if out.path is not None:
                follower.set_path(out.path)
            if out.waiting is not None:
                follower.waiting = out.waiting
            events += out.events
        cmd = follower.command(sim.robot_pose())
        sim.command_robot(cmd)
        sim.step()
        sim.step()
        if follower.status is Status.ARRIVED:
            break
    return events


def robot_with(**limits: float):
    """The default robot (TurtleBot2) with other velocity limits."""
    from dataclasses import replace

    from haven_sim.robots.fields import DEFAULT

    return replace(DEFAULT, limits=replace(DEFAULT.limits, **limits))
