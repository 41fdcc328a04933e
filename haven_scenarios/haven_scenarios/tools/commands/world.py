"""`haven world show WORLD [--out PNG]`: check a world file and draw it from above (walls,
obstacles, rooms, hallway centre lines, gems, the charging base and the starts), the quick look
a researcher wants before a trial runs on a world they wrote.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from haven_scenarios.study.scenario import resolve_world
from haven_scenarios.tools.commands.common import fail
from haven_sim.common.yaml_file import YamlFileError, file_label
from haven_sim.nav.planner import check_plannable
from haven_sim.sim.world import World, WorldError, summary
from haven_sim.sim.world_file import load_world

# one each
HALLWAY_COLOURS = (
    "tab:purple",
    "tab:green",
    "tab:orange",
    "tab:pink",
    "tab:olive",
    "tab:cyan",
    "tab:brown",
    "tab:gray",
)
ROBOT_COLOUR, PERSON_COLOUR = "tab:blue", "tab:red"


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    world = sub.add_parser("world", help="a world file: `show` checks it and draws it from above as a PNG")
    verbs = world.add_subparsers(dest="verb", required=True)
    show = verbs.add_parser(
        "show", help="check a world file and write a PNG of it (walls, rooms, hallway centre lines, gems, starts)"
    )
    show.add_argument(
        "world", metavar="WORLD", help="a world file, or a shipped world's name (hallway, shared_room, ...)"
    )
    show.add_argument("--out", type=Path, default=None, help="the PNG to write (default: WORLD's name + .png, here)")
    show.set_defaults(func=show_cmd)


def show_cmd(args: argparse.Namespace) -> int:
    try:
        path = resolve_world(args.world)
        world = load_world(path)
        check_plannable(world, file_label(path))
    except (YamlFileError, WorldError) as e:
        return fail(str(e))
    out = draw(world, args.out or Path(f"{world.name}.png"))
    print(f"ok: {file_label(path)} (world {world.name}: {summary(world)}) -> {out}")
    return 0


def draw(world: World, out: Path) -> Path:
    """The world as the session pictures draw it (haven_viz.render), with the hallways' centre
    lines and the robot's and each person's start labelled."""
    import numpy as np  # (matplotlib and the renderer load only when a picture is drawn)

    from haven_viz.render import render_scene
    from haven_viz.world_markers import world_markers

    lines = {
        f"hallway {h.name}": (np.array(h.centreline, dtype=float), HALLWAY_COLOURS[i % len(HALLWAY_COLOURS)])
        for i, h in enumerate(world.hallways)
    }
    starts = [(world.robot_start.x, world.robot_start.y, "robot start", ROBOT_COLOUR)]
    starts += [(h.start.x, h.start.y, f"{h.id} start", PERSON_COLOUR) for h in world.humans]
    return render_scene(
        world,
        world_markers(world),
        out,
        title=f"world {world.name} ({file_label(Path(world.source).name)})",
        trails=lines,
        points=starts,
    )
