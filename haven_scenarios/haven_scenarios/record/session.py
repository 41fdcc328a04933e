"""Session folders: what one recorded trial leaves behind, self-contained, and how it is read back.

    sessions/<scenario>_<participant>_<YYYYmmdd-HHMMSS>/
        bag/              rosbag2, MCAP storage, metadata version 9: every topic of the trial
                          (bag.mcap.damaged beside it: the file a dead recorder left, the bag rebuilt from it)
        events.jsonl      /haven/events, one JSON object a line, written as they happen
        scenario.yaml     the scenario as run (teleoperated humans marked); its world is world.yaml
        world.yaml        a copy of the world
        robot.yaml        the robot as run: its robot file, what it `extends` merged in (scenario.yaml names it)
        params.yaml       every node's parameters as run (a ROS parameter file)
        session.json      participant, condition, seed, versions, git commit, RMW, clock, outcome
        metrics.json      computed from the bag (so `haven report` gives the same numbers later)
        questionnaires.json  with `haven run --questionnaire`: each participant's answers and scores (record/answers.py)
        trajectory.png    top-down: walls, the tracks, gems, where the robot waited or re-planned

Everything a re-run or a re-scoring needs is inside the folder under relative names, so a study
folder can be moved or archived; `analyse` never fails on a damaged session, it flags it.
"""

from __future__ import annotations

import json
import os
import platform
import subprocess
import sys
import time
from collections.abc import Mapping
from dataclasses import fields
from datetime import UTC, datetime
from importlib import metadata
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from haven_scenarios.record import recorder_stop
from haven_scenarios.record.bag import read_recording, to_wall_time, wall_clock
from haven_scenarios.record.metric_kind import compute
from haven_scenarios.record.outsiders import declared_of
from haven_scenarios.record.timeline import GRID_S, Recording, Timeline
from haven_scenarios.study.conditions import condition_name
from haven_scenarios.study.names import check_name
from haven_scenarios.study.person import PersonParams
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import Scenario, ScenarioError, load_scenario
from haven_sim.common import atomic
from haven_sim.common.events import EventKind
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.fields import DEFAULT
from haven_sim.robots.robot_file import RobotError, merged
from haven_sim.robots.robot_kind import resolve_robot
from haven_sim.sim.world import World, WorldError
from haven_sim.sim.world_file import world_files
from haven_viz.cues import CUES, CueToggles
from haven_viz.world_markers import world_markers

PACKAGES = ("haven_sim", "haven_viz", "haven_scenarios", "ros-jazzy-rclpy", "pymunk", "numpy", "rosbags", "mcap")
SCENARIO_FILE, WORLD_FILE, PARAMS_FILE, SESSION_FILE, METRICS_FILE = (
    "scenario.yaml",
    "world.yaml",
    "params.yaml",
    "session.json",
    "metrics.json",
)
ROBOT_FILE = "robot.yaml"
EVENTS_FILE = "events.jsonl"
# The write end of a pipe on which the recorder says it has the trial's end on every state stream
# (nodes/recorder.py); `haven run` reads the other end (conduct/recorded_trial.py).
END_FD_ENV = "HAVEN_TRIAL_END_FD"


def new_session_dir(root: Path, scenario: str, participant: str) -> Path:
    """A new folder `<scenario>_<participant>_<time>` directly inside `root` (made with its
    parents). ValueError for a name that is not safe, or a folder that would not be inside `root`
    (defence in depth: the names are checked where they are read); OSError if it cannot be made."""
    check_name(scenario, "scenario name")
    check_name(participant, "participant id")
    stamp = time.strftime("%Y%m%d-%H%M%S")
    folder = root / f"{scenario}_{participant}_{stamp}"
    n = 1
    while folder.exists():
        n += 1
        folder = root / f"{scenario}_{participant}_{stamp}-{n}"
    if folder.resolve().parent != root.resolve():
        raise ValueError(f"session folder {folder} would not be inside --sessions {root}")
    folder.mkdir(parents=True)
    return folder


def versions() -> dict[str, str | None]:
    out: dict[str, str | None] = {"python": platform.python_version()}
    for p in PACKAGES:
        try:
            out[p] = metadata.version(p)
        except metadata.PackageNotFoundError:
            out[p] = None
    return out


def git_commit() -> str | None:
    """The commit of the HAVEN checkout these packages run from ("+dirty" with local changes)."""
    here = Path(__file__).resolve().parent
    try:
        head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=here, capture_output=True, text=True, timeout=5)
        if head.returncode != 0:
            return None
        # (no index.lock left if it times out)
        status = ["git", "--no-optional-locks", "status", "--porcelain", "--untracked-files=no"]
        dirty = subprocess.run(status, cwd=here, capture_output=True, text=True, timeout=5)
        return head.stdout.strip() + ("+dirty" if dirty.stdout.strip() else "")
    except (OSError, subprocess.TimeoutExpired):
        return None


def rmw() -> str:
    return os.environ.get("RMW_IMPLEMENTATION", "rmw_fastrtps_cpp")


def write_json(path: Path, data: Mapping[str, Any]) -> None:
    """Written whole or not at all (a full disk leaves the old file, never an empty one)."""
    atomic.write_text(path, json.dumps(data, indent=2, sort_keys=True, default=str) + "\n")


def trial_record(participant: str, toggles: CueToggles, seed: int, scenario: Scenario) -> dict[str, Any]:
    """What every session.json says of its trial (`haven run` and a study's batch trials add
    how it ran): who, the condition and its cues, the seed, the scenario, its people, provenance."""
    return {
        "participant": participant,
        "condition": condition_name(toggles),
        "cues": {c: toggles.on(c) for c in CUES},
        "seed": seed,
        "scenario": scenario.name,
        "robot": scenario.robot_model,  # as given: a name or a robot file (robot.yaml: the copy)
        "robot_name": scenario.robot.name,
        "humans": [h.id for h in scenario.world.humans],
        "teleoperated": [h.id for h in scenario.humans if h.teleoperated],
        **provenance(),
    }


def session_info(folder: Path) -> dict[str, Any]:
    path = folder / SESSION_FILE
    try:
        data = json.loads(path.read_text()) if path.exists() else {}
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _params(params: PersonParams) -> dict[str, Any]:
    """A person's `params` as a scenario file sets them (those not at their default): the scenario
    node reads them from the session's copy, so batch and ROS trials have the same people."""
    default = PersonParams()
    changed = {
        f.name: getattr(params, f.name)
        for f in fields(PersonParams)
        if getattr(params, f.name) != getattr(default, f.name)
    }
    return {"params": changed} if changed else {}


def write_inputs(folder: Path, scenario: Scenario, params_yaml: str) -> None:
    """The scenario (with world: world.yaml, robot: robot.yaml), copies of its world and its robot,
    and every node's parameters."""
    data: dict[str, Any] = (
        yaml.safe_load(Path(scenario.source).read_text()) if scenario.source else {"name": scenario.name}
    )
    data["world"] = WORLD_FILE
    robot = robot_file_text(scenario.robot)
    section: dict[str, Any] = dict(data.get("robot") or {})
    # (a robot made in code has no file: its name)
    section["model"] = ROBOT_FILE if robot is not None else scenario.robot_model
    data["robot"] = section
    if robot is not None:
        atomic.write_text(folder / ROBOT_FILE, robot)
    data["humans"] = [
        {"id": h.id, "model": h.model, "route": list(h.route), "speed_mps": h.speed_mps, **_params(h.params)}
        for h in scenario.humans
    ]
    data["robot"].pop("start", None)  # (the starts as run are the world copy's)
    for name, content in world_files(scenario.world, WORLD_FILE).items():  # (a world from a map: its image too)
        atomic.write_bytes(folder / name, content)
    atomic.write_text(folder / SCENARIO_FILE, yaml.safe_dump(data, sort_keys=False))
    atomic.write_text(folder / PARAMS_FILE, params_yaml)


def robot_file_text(robot: RobotDescription) -> str | None:
    """The robot's file as one self-contained robot file (what it extends merged in, its glTF
    model by absolute path); None for a robot made in code."""
    if not robot.source_file:
        return None
    data = merged(Path(robot.source_file), _extended, 0)
    if robot.look.model:
        data["look"] = {**data.get("look", {}), "model": robot.look.model}
    header = f"# The robot as run in this session: {robot.source_file}, with what it extends merged in.\n"
    return header + yaml.safe_dump(data, sort_keys=False)


def _extended(name: str, where: str) -> dict[str, Any]:
    """A registered robot's file data (what `extends: NAME` starts from)."""
    source = resolve_robot(name).source_file
    if not source:
        raise RobotError(f"{where}: robot {name!r} was made in code, not from a file")
    return merged(Path(source), _extended, 1)


def session_scenario(folder: Path) -> tuple[Scenario | None, str]:
    """The session's own copy of its scenario (its world, world.yaml, beside it), or None and why not."""
    missing = [name for name in (SCENARIO_FILE, WORLD_FILE) if not (folder / name).is_file()]
    if missing:
        return None, f"no {' and no '.join(missing)} in the session"
    try:
        return load_scenario(folder / SCENARIO_FILE), ""
    except (ScenarioError, WorldError, OSError) as e:
        return None, f"scenario unreadable: {str(e)[:160]}"


def analyse(folder: Path) -> tuple[dict[str, Any], World | None, Recording]:
    """Metrics of a session folder from its bag alone; a damaged or incomplete session gives a
    row flagged not valid, never an exception."""
    info = session_info(folder)
    scenario, problem = session_scenario(folder)
    world = scenario.world if scenario is not None else None
    # Without the world, the people's ids as session.json lists them (columns named as in every row).
    ids = [h.id for h in world.humans] if world is not None else [str(i) for i in info.get("humans", [])]
    try:
        rec, note = read_recording(folder / "bag", ids)
    except Exception as e:
        rec, note = Recording(), f"bag unreadable: {str(e)[:120]}"
    end = rec.first(EventKind.TRIAL_END)
    name, reason = (
        str(info.get("scenario", scenario.name if scenario else "")),
        end["reason"] if end else EndReason.INTERRUPTED,
    )
    problems = [p for p in (note, problem, recorder_stop.problem(info, folder / "bag", rec)) if p]
    try:
        metrics = compute(
            rec, name, reason, world, declared_of(info), scenario.robot if scenario is not None else DEFAULT
        )
    except Exception as e:
        metrics = {"scenario": name, "end_reason": reason, "duration_s": None, "valid": False, "invalid_reasons": []}
        problems.append(f"metrics could not be computed: {type(e).__name__}: {str(e)[:120]}")
    if problems:
        metrics["valid"] = False
        metrics["invalid_reasons"] = [*problems, *metrics.get("invalid_reasons", [])]
    for key in ("participant", "condition", "seed"):
        if key in info:
            metrics[key] = info[key]
    if scenario is not None or "robot_name" in info:  # (its name: the design column)
        metrics["robot"] = scenario.robot.name if scenario is not None else info["robot_name"]
    metrics["session"] = folder.name
    return metrics, world, rec


def trajectory_picture(folder: Path, world: World, rec: Recording, title: str) -> Path:
    """The tracks from their starts, the gems still there at the end and where and when the others
    were collected, and marks where the robot waited, detoured, went to charge or touched someone."""
    from haven_viz.render import PERSON_TRAILS, render_scene  # matplotlib: imported when a picture is drawn

    info = session_info(folder)
    window = rec.window()
    trails: dict[str, tuple[Any, str]] = {}
    marks: list[tuple[float, float, str, str]] = []
    happened: list[tuple[float, float, str]] = []
    if window is not None:
        tl = Timeline.of(rec, *window, step=5 * GRID_S)
        trails["robot"] = (tl.robot_xy, "black")
        for i, (hid, xy) in enumerate(tl.humans.items()):
            trails[hid] = (xy, PERSON_TRAILS[i % len(PERSON_TRAILS)])
        labels = {
            EventKind.WAITING: "wait",
            EventKind.REPLANNED: "detour",
            EventKind.CONTACT_BEGIN: "contact",
            EventKind.CHARGE_TRIP: "to charge",
        }
        for e in rec.events:
            if e.kind in labels and window[0] <= e.stamp <= window[1]:
                i = min(int(np.searchsorted(tl.t, e.stamp - window[0])), len(tl.t) - 1)
                label = f"detour {e.get('side', '')}" if e.kind is EventKind.REPLANNED else labels[e.kind]
                happened.append((float(tl.robot_xy[i, 0]), float(tl.robot_xy[i, 1]), label))
        # Where each track starts, and every collected gem: which, by whom, when.
        for label, (xy, color) in trails.items():
            marks.append((float(xy[0, 0]), float(xy[0, 1]), f"{label} start", color))
        gems = {g.id: g.position for g in world.gems}
        for e in rec.events:
            if e.kind is EventKind.GEM_COLLECTED and str(e["gem"]) in gems and window[0] <= e.stamp <= window[1]:
                x, y = gems[str(e["gem"])]
                marks.append((x, y, f"{e['gem']}: {e['by']}, {e.stamp - window[0]:.0f} s", "tab:green"))
    collected = {str(e["gem"]) for e in rec.events if e.kind is EventKind.GEM_COLLECTED}
    removed = {str(e["id"]) for e in rec.events if e.kind is EventKind.OBSTRUCTION_REMOVED}
    markers = [
        m for m in world_markers(world, collected, removed) if m.ns in ("gems", "gem_areas", "charging_base", "rooms")
    ]
    subtitle = f"participant {info.get('participant', '?')}, condition {info.get('condition', '?')}"

    out = folder / "trajectory.png"
    return render_scene(
        world,
        markers,
        out,
        title=f"{title}\n{subtitle}",
        trails=trails,
        points=marks,
        removed=sorted(removed),
        events=happened,
    )


def provenance() -> dict[str, Any]:
    """What a session folder's session.json says about how it was made: when, with which
    versions, commit, RMW and command line."""
    return {
        "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
        "versions": versions(),
        "git_commit": git_commit(),
        "rmw": rmw(),
        "command": sys.argv,
    }


def trial_wall_clock(folder: Path) -> dict[str, str]:
    """When the trial started and ended by the wall clock (ISO 8601, UTC, ms), from the recorder's
    clock pairs and the trial's events: to align the session with other recordings of the study."""
    pairs = wall_clock(folder / "bag")
    out: dict[str, str] = {}
    try:
        lines = (folder / EVENTS_FILE).read_text(encoding="utf-8").splitlines()
    except OSError:
        return out
    kinds = (EventKind.TRIAL_START.value, EventKind.TRIAL_END.value)
    for line in lines:
        try:
            e = json.loads(line)
        except ValueError:
            continue
        if isinstance(e, dict) and e.get("type") in kinds and isinstance(e.get("stamp"), (int, float)):
            t = to_wall_time(pairs, float(e["stamp"]))
            if t is not None:
                out[e["type"]] = datetime.fromtimestamp(t, tz=UTC).isoformat(timespec="milliseconds")
    return out
