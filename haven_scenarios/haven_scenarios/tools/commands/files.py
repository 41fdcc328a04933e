"""`haven validate FILE...`: check world, scenario, study, robot and parameter files without starting
anything; `haven schema KIND`: a file kind's JSON Schema, for editors; `haven plugins`: what is
installed to name in them."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from haven_scenarios.conduct.plugin_package import write_package
from haven_scenarios.run.suite import checked_suite_config
from haven_scenarios.study.names import check_name
from haven_scenarios.study.protocol import StudyError, StudyFile, parse_study
from haven_scenarios.study.questionnaires import LikertFile
from haven_scenarios.study.scenario import ScenarioError, ScenarioFile, parse_scenario
from haven_scenarios.study.schedule import practice_note
from haven_scenarios.tools.commands.common import fail
from haven_sim.common import plugins
from haven_sim.common.params import ParamsError, params_of
from haven_sim.common.yaml_file import YamlFileError, file_label, read_yaml
from haven_sim.nav.planner import check_plannable
from haven_sim.robots.robot_file import RobotError, RobotFileModel
from haven_sim.robots.robot_kind import resolve_robot
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_file import WorldFile, parse_world

# The file kinds whose shape is a model of the schema layer (haven_sim/common/schema.py).
SCHEMAS: dict[str, Any] = {
    "world": WorldFile,
    "scenario": ScenarioFile,
    "study": StudyFile,
    "questionnaire": LikertFile,
    "robot": RobotFileModel,
}


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    validate = sub.add_parser(
        "validate",
        help=(
            "check world, scenario, study, robot and parameter files "
            "(which is which: by their keys) without starting anything"
        ),
    )
    validate.add_argument("files", nargs="+", type=Path, metavar="FILE")
    validate.set_defaults(func=validate_cmd)
    said = "every registered plugin, one per line: KIND NAME PACKAGE; each one left out on stderr, and then exit code 1"
    listing = sub.add_parser(
        "plugins",
        help=said,
        description=f"{said}. This HAVEN's plugin API is version {plugins.PLUGIN_API} (docs: Your own plugins)",
    )
    listing.set_defaults(func=plugins_cmd)
    new = listing.add_subparsers(title="to start a plugin of your own", metavar="new").add_parser(
        "new",
        help="write a plugin package to start from (haven_NAME/ with its test: one batch trial with it)",
        description=(
            "Write haven_NAME/, a package holding a working plugin of KIND named NAME, its entry point, and a test "
            "that loads it as HAVEN does and runs one batch trial with it (haven_scenarios.testing's fixtures)."
        ),
    )
    new.add_argument("kind", metavar="KIND", help=f"{', '.join(plugins.kinds())} (or the singular)")
    new.add_argument("name", metavar="NAME", help="the plugin's name: lower-case letters, digits and _")
    new.add_argument(
        "--into", type=Path, default=Path("."), metavar="DIR", help="where to write haven_NAME/ (default: here)"
    )
    new.set_defaults(func=plugins_new_cmd)
    schema = sub.add_parser(
        "schema",
        help=(
            "a file kind's JSON Schema (for YAML editors: "
            "`# yaml-language-server: $schema=scenario.schema.json` at a file's top)"
        ),
    )
    schema.add_argument("kind", choices=sorted(SCHEMAS))
    schema.set_defaults(func=schema_cmd)


def schema_cmd(args: argparse.Namespace) -> int:
    """The JSON Schema of a world, scenario, study, questionnaire or robot file."""
    from haven_scenarios.tools.commands.robots import file_schema

    model = SCHEMAS[args.kind]
    schema = model.model_json_schema()
    schema = file_schema(schema) if args.kind == "robot" else schema
    out = {"$schema": "https://json-schema.org/draft/2020-12/schema", **schema, "title": f"HAVEN {args.kind} file"}
    print(json.dumps(out, indent=2))
    return 0


def plugins_cmd(args: argparse.Namespace) -> int:
    """KIND NAME PACKAGE per item; one line on stderr per plugin left out (exit 1 if any)."""
    problems = []
    for reg in plugins.every():
        for item in reg:
            print(f"{reg.kind} {item.name} {item.package}")
        problems += reg.problems
    for line in problems:
        print(f"haven: plugin left out: {line}", file=sys.stderr)
    return 1 if problems else 0


def plugins_new_cmd(args: argparse.Namespace) -> int:
    """The package written, and how to install and test it; exit 2 with one line if refused."""
    try:
        folder = write_package(args.kind, args.name, args.into, python=sys.executable)
    except (ValueError, OSError) as e:
        return fail(str(e))
    print(f"haven: wrote {folder}/ (pyproject.toml, README.md, its module and tests/)")
    print(f"next: {sys.executable} -m pip install -e {folder} && {sys.executable} -m pytest {folder}")
    return 0


def validate_cmd(args: argparse.Namespace) -> int:
    """One line per file, "ok: FILE (world NAME)" or the error; exit 0 when every file is valid, else 2."""
    failed = 0
    for path in args.files:
        try:
            print(f"ok: {file_label(path)} ({describe(path)})", flush=True)
        except (YamlFileError, WorldError, ScenarioError, StudyError, ParamsError, RobotError) as e:
            fail(str(e))
            failed += 1
    return 2 if failed else 0


def describe(path: Path) -> str:
    """What a valid file is, "world NAME", "scenario NAME", "study NAME", "robot NAME" or "parameter
    file for NODES": a scenario has `kind` or `world`, a world `walls` or `map`, a study `scenarios`
    and `conditions`, a robot `kinematics` or `extends`, a parameter file `ros__parameters` under each node."""
    data = read_yaml(path, "file")
    if isinstance(data, dict) and ("scenarios" in data or "conditions" in data):
        study = parse_study(data, str(path))
        carry = practice_note(study)
        if carry:
            print(f"haven: warning: {file_label(path)}: {carry}", file=sys.stderr)
        return f"study {study.name}"
    if isinstance(data, dict) and ("kind" in data or "world" in data):
        name = parse_scenario(data, str(path)).name
        try:  # (the rule `haven run` applies before it makes a session folder of the name)
            check_name(name, f"{file_label(path)}: name")
        except ValueError as e:
            raise ScenarioError(str(e)) from None
        return f"scenario {name}"
    if isinstance(data, dict) and ("walls" in data or "map" in data or {"image", "resolution"} <= data.keys()):
        world = parse_world(data, str(path))  # (a map_server map's YAML: the world loader says how to make a world)
        check_plannable(world, file_label(path))
        return f"world {world.name}"
    if isinstance(data, dict) and ("kinematics" in data or "extends" in data):
        return f"robot {resolve_robot(str(path)).name}"
    if isinstance(data, dict) and data and all(isinstance(v, dict) and "ros__parameters" in v for v in data.values()):
        params = params_of(data, file_label(path))
        checked_suite_config(params, file_label(path))
        return f"parameter file for {', '.join(params)}"
    kinds = (
        "neither a scenario (no 'kind' or 'world' key), a world (no 'walls' or 'map' key), a study (no "
        "'scenarios' key), a robot (no 'kinematics' or 'extends' key) nor a parameter file (no 'ros__parameters')"
    )
    raise YamlFileError(f"{file_label(path)}: {kinds}")
