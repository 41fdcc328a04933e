"""Session folders: what one recorded trial leaves behind, and how it is read back.

    sessions/<scenario>_<participant>_<YYYYmmdd-HHMMSS>/
        bag/              rosbag2, MCAP storage, metadata version 9: every topic of the trial
        events.jsonl      /haven/events, one JSON object a line, written as they happen
        session.json      participant, condition, seed, scenario, versions, parameters, outcome
        metrics.json      computed from the bag (so `haven report` gives the same numbers later)
        trajectory.png    top-down: walls, both tracks, gems, where the robot waited or re-planned
"""

from __future__ import annotations

import csv
import json
import platform
import time
from collections.abc import Sequence
from importlib import metadata
from pathlib import Path
from typing import Any

import numpy as np

from haven_scenarios.record.bag import read_log
from haven_scenarios.record.metrics import compute
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.events import EventKind
from haven_sim.sim.world import World
from haven_sim.sim.world_file import load_world
from haven_viz.render import render_scene
from haven_viz.world_markers import world_markers

PACKAGES = ("haven_sim", "haven_viz", "haven_scenarios", "rclpy", "ros-jazzy-rclpy", "pymunk", "numpy", "rosbags")


def new_session_dir(root: Path, scenario: str, participant: str) -> Path:
    stamp = time.strftime("%Y%m%d-%H%M%S")
    folder = root / f"{scenario}_{participant}_{stamp}"
    n = 1
    while folder.exists():
        n += 1
        folder = root / f"{scenario}_{participant}_{stamp}-{n}"
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


def write_json(path: Path, data: dict[str, Any]) -> None:
    path.write_text(json.dumps(data, indent=2, sort_keys=True, default=str) + "\n")


def session_info(folder: Path) -> dict[str, Any]:
    path = folder / "session.json"
    return json.loads(path.read_text()) if path.exists() else {}


def analyse(folder_or_bag: Path) -> tuple[dict[str, Any], World | None]:
    """Metrics of a session folder (or a bare bag folder) from its bag alone."""
    folder = folder_or_bag if (folder_or_bag / "bag").is_dir() else folder_or_bag.parent
    bag = folder_or_bag / "bag" if (folder_or_bag / "bag").is_dir() else folder_or_bag
    info = session_info(folder)
    world = None
    human_ids: list[str] = []
    if info.get("scenario_file"):
        scenario = load_scenario(info["scenario_file"])
        world = scenario.world
        human_ids = [h.id for h in world.humans]
    elif info.get("world_file"):
        world = load_world(info["world_file"])
        human_ids = [h.id for h in world.humans]
    log = read_log(bag, human_ids)
    ends = [e for e in log.events if e.kind is EventKind.TRIAL_END]
    metrics = compute(log, str(info.get("scenario", "")), ends[-1]["reason"] if ends else EndReason.INTERRUPTED)
    for key in ("participant", "condition", "seed"):
        if key in info:
            metrics[key] = info[key]
    metrics["session"] = folder.name
    return metrics, world


def trajectory_picture(folder: Path, world: World, title: str) -> Path:
    """Both tracks, the gems still there at the end, and marks where the robot waited or re-planned."""
    info = session_info(folder)
    log = read_log(folder / "bag", [h.id for h in world.humans])
    robot = np.asarray(log.robot, dtype=float).reshape(-1, 4)[:, :2]
    trails = {"robot": (robot, "black")}
    colors = ["tab:red", "tab:orange", "tab:purple", "tab:brown"]
    for i, (hid, xy) in enumerate(log.humans.items()):
        trails[hid] = (np.asarray(xy, dtype=float), colors[i % len(colors)])
    marks = []
    t = np.asarray(log.t)
    labels = {EventKind.WAITING: "wait", EventKind.REPLANNED: "detour", EventKind.CONTACT_BEGIN: "contact", EventKind.CHARGE_TRIP: "to charge"}
    for e in log.events:
        if e.kind in labels and len(t):
            i = min(int(np.searchsorted(t, e.stamp)), len(t) - 1)
            label = f"detour {e.get('side', '')}" if e.kind is EventKind.REPLANNED else labels[e.kind]
            marks.append((float(robot[i, 0]), float(robot[i, 1]), label, "red" if e.kind is EventKind.CONTACT_BEGIN else "tab:blue"))
    collected = {str(e["gem"]) for e in log.events if e.kind is EventKind.GEM_COLLECTED}
    removed = {str(e["id"]) for e in log.events if e.kind is EventKind.OBSTRUCTION_REMOVED}
    markers = [m for m in world_markers(world, collected, removed) if m.ns in ("gems", "gem_areas", "charging_base", "rooms")]
    subtitle = f"participant {info.get('participant', '?')}, condition {info.get('condition', '?')}"
    return render_scene(world, markers, folder / "trajectory.png", title=f"{title}\n{subtitle}", trails=trails, points=marks, removed=sorted(removed))


def report_csv(paths: Sequence[Path], out: Path) -> list[dict[str, Any]]:
    rows = []
    for p in paths:
        metrics, _ = analyse(p)
        rows.append(metrics)
    keys: list[str] = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    out.parent.mkdir(parents=True, exist_ok=True)
    with out.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(rows)
    return rows
