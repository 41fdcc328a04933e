"""`haven edit [WORLD] [--out DIR] [--host H] [--port P]`: the world editor in the browser
(web/editor_server.py, web/src/editor.js), for researchers who do not write YAML: draw walls and
furniture, place rooms, hallways, gems, the charging base and the starts, see the loader's
verdict as you go, save a world and a scenario from a template. Runs until Ctrl-C or SIGTERM;
every save is written whole, so stopping never loses a saved file.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from haven_scenarios.study.scenario import resolve_world
from haven_scenarios.tools.commands.common import add_tls_options, bounded_int, fail
from haven_sim.common.yaml_file import YamlFileError, file_label, read_yaml
from haven_sim.runtime.process import interrupted, on_stop_signals
from haven_sim.sim.world import WorldError

DEFAULT_HOST, DEFAULT_PORT = "127.0.0.1", 8090  # beside the study pages' 8088 (web/front_door.py), so both can run
NEW_WORLD: dict[str, Any] = {"name": "my_world", "walls": [], "robot": {"start": [1.0, 1.0, 0.0]}}


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    edit = sub.add_parser("edit", help="the world editor in the browser: draw a world, save it with a scenario")
    edit.add_argument(
        "world",
        metavar="WORLD",
        nargs="?",
        default=None,
        help="a world file or a shipped world's name (default: a new, empty world)",
    )
    edit.add_argument(
        "--out", type=Path, default=Path("."), help="the folder saved worlds and scenarios go to (default: here)"
    )
    edit.add_argument(
        "--host",
        default=DEFAULT_HOST,
        help="the address to serve on (0.0.0.0: every interface; default this machine only)",
    )
    edit.add_argument(
        "--port",
        type=bounded_int(0, 65535),
        default=DEFAULT_PORT,
        help=f"the port (default {DEFAULT_PORT}; 0: any free one)",
    )
    add_tls_options(edit)
    edit.set_defaults(func=edit_cmd)


def world_tree(spec: str | None) -> dict[str, Any]:
    """The world to start from, as its YAML tree; WorldError (one line) when it cannot be edited."""
    if spec is None:
        return dict(NEW_WORLD)
    path = resolve_world(spec)
    data = read_yaml(path, "world file", WorldError)
    if not isinstance(data, dict):
        raise WorldError(f"{file_label(path)}: name: must be a mapping of the world's keys")
    if data.get("map") is not None:
        raise WorldError(
            f"{file_label(path)}: map: the editor draws walls itself: "
            "start a new world and import the map image as walls"
        )
    return data


def edit_cmd(args: argparse.Namespace) -> int:
    from haven_scenarios.web.editor_server import EditorServer  # (the server loads only for this command)
    from haven_scenarios.web.tls import server_context, tls_files

    try:
        files = tls_files(args.tls_cert, args.tls_key)
        server = EditorServer(
            args.host, args.port, world_tree(args.world), args.out, server_context(*files) if files else None
        )
    except (WorldError, YamlFileError, ValueError) as e:
        return fail(str(e))
    server.start()
    try:
        with on_stop_signals(interrupted):
            print(f"edit: the world editor (saves into {args.out}): {server.url}", flush=True)
            server.server.wait()
    except KeyboardInterrupt:
        print("edit: stopped", flush=True)
    finally:
        server.stop()
    return 0
