"""A sweep's design: scenarios x grid axes (conditions, participant models, parameters) x seeds.

`--grid condition=all,none --grid model=walker,yielder --grid reaction_s=0.5,1.5 --seeds 0-9`:
every combination, in a fixed order (scenario, then the axes as given, then the seed), each one a
`TrialSpec` with its own seed, so a trial's row depends on nothing but its spec. `condition` takes
the names `haven batch --condition` takes (cues joined by `+`), `model` the simulated models,
`speed_mps` walking speeds, `robot` robots (names or robot files: `--grid robot=turtlebot2,my_bot.yaml`,
which replace the scenario's own); any other key is a field of the simulated participants' perception
parameters (`HumanTask.params`), applied to every simulated (not teleoperated) human.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import Any

from haven_scenarios.study.conditions import check_fit, condition_name, parse_condition
from haven_scenarios.study.participants import in_session
from haven_scenarios.study.person import PersonParams
from haven_scenarios.study.scenario import MAX_WALKING_SPEED_MPS, HumanTask, Scenario
from haven_sim.common import plugins
from haven_sim.robots.robot_file import RobotError
from haven_sim.robots.robot_kind import is_file_spec, resolve_robot
from haven_viz.cues import CueToggles

TASK_KEYS = ("condition", "model", "speed_mps", "robot")  # grid keys that are not perception parameters
MAX_TRIALS = 1_000_000  # a sweep larger than this is a typo, not a study
Point = Mapping[str, Any]  # one combination of the grid: key -> value


def param_keys() -> tuple[str, ...]:
    """The fields of a participant's parameters (`HumanTask.params`: `PersonParams`, floats)."""
    return tuple(f.name for f in fields(PersonParams))


def robot_spec(spec: str, option: str = "--robot") -> str:
    """`spec` checked: a registered robot's name, or a robot file (made absolute: ROS nodes run in
    their session folder); ValueError naming `option`, in one line, otherwise."""
    try:
        resolve_robot(spec)
    except RobotError as e:
        raise ValueError(f"{option}: {e}") from None
    return str(Path(spec).expanduser().resolve()) if is_file_spec(spec) else spec


def for_trial(scenario: Scenario, robot: str | None = None, person: tuple[int, int] | None = None) -> Scenario:
    """`scenario` with `robot` (a registered name or a robot file; None: its own) and its simulated
    people as one study participant (`person`: (person seed, position in the session); None: as
    the file has them), as `haven run --robot`, the API and a study run give them. ValueError (one
    line) for a robot that does not exist or does not fit."""
    if robot is not None:
        spec = robot_spec(robot)
        scenario = scenario.for_robot(resolve_robot(spec), spec)
    return in_session(scenario, *person) if person is not None else scenario


def _number(key: str, text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"--grid {key}: expected numbers, got {text!r}") from None
    if not math.isfinite(value):
        raise ValueError(f"--grid {key}: expected finite numbers, got {text}")
    return value


def _value(key: str, text: str) -> Any:
    if key == "condition":
        try:
            return condition_name(parse_condition(text.split("+")))
        except ValueError as e:
            raise ValueError(f"--grid condition: {e}") from None
    if key == "robot":
        return robot_spec(text, "--grid robot")
    if key == "model":
        models = plugins.registry("participants")
        if text in models.left_out:
            raise ValueError(f"--grid model: {models.unknown(text)}")
        if text not in models:
            raise ValueError(
                f"--grid model: {text!r} is not a simulated participant model ({', '.join(models.names())})"
            )
        return text
    value = _number(key, text)
    if key == "speed_mps" and not 0 < value <= MAX_WALKING_SPEED_MPS:
        raise ValueError(f"--grid speed_mps: must be within (0, {MAX_WALKING_SPEED_MPS:g}] m/s, got {text}")
    return value


def parse_grid(texts: Sequence[str]) -> dict[str, tuple[Any, ...]]:
    """`key=v1,v2,...` options into the grid's axes, in the order given; one-line errors."""
    valid = (*TASK_KEYS, *param_keys())
    axes: dict[str, tuple[Any, ...]] = {}
    for text in texts:
        key, sep, values = text.partition("=")
        key = key.strip()
        if not sep or not key:
            raise ValueError(f"--grid: expected KEY=V1,V2,..., got {text!r}")
        if key not in valid:
            raise ValueError(f"--grid: unknown key {key!r} (valid: {', '.join(valid)})")
        if key in axes:
            raise ValueError(f"--grid: {key} given twice")
        items = [v.strip() for v in values.split(",")]
        if not all(items):
            raise ValueError(f"--grid {key}: expected comma-separated values, got {values!r}")
        axes[key] = tuple(dict.fromkeys(_value(key, v) for v in items))  # (a value given twice runs once)
    return axes


def parse_seeds(text: str) -> tuple[int, ...]:
    """`0-9`, `3,5,8` or both (`0-4,10`): the seeds in the order given, each once."""
    seeds: list[int] = []
    for part in text.split(","):
        lo, dash, hi = part.strip().partition("-")
        try:
            first, last = int(lo), int(hi if dash else lo)
        except ValueError:
            raise ValueError(f"--seeds: expected seeds like 0-9 or 1,4,7, got {text!r}") from None
        if first < 0 or last < first:
            raise ValueError(f"--seeds: {part.strip()} is not a range of seeds (0 or more, low-high)")
        if last - first >= MAX_TRIALS:
            raise ValueError(f"--seeds: {part.strip()} holds more than {MAX_TRIALS} seeds")
        seeds += range(first, last + 1)
    return tuple(dict.fromkeys(seeds))


@dataclass(frozen=True)
class TrialSpec:
    """One trial of a sweep: everything its row depends on (it travels to the worker that runs it)."""

    index: int  # the row's place in the CSV
    scenario: Scenario  # with the grid's participant settings applied
    toggles: CueToggles
    design: tuple[tuple[str, Any], ...]  # the grid point, for the row's design columns
    seed: int

    def columns(self) -> dict[str, Any]:
        """The design columns: trial, scenario, condition, model, robot (its name), each grid
        parameter, seed."""
        models = "+".join(dict.fromkeys(h.model for h in self.scenario.humans if not h.teleoperated))
        own = {k: v for k, v in self.design if k not in ("condition", "model", "robot")}
        condition, robot = condition_name(self.toggles), self.scenario.robot.name
        return {
            "trial": self.index,
            "scenario": self.scenario.name,
            "condition": condition,
            "model": models,
            "robot": robot,
            **own,
            "seed": self.seed,
        }


def _human(task: HumanTask, point: Point) -> HumanTask:
    if task.teleoperated:
        return task
    task = replace(task, **{k: v for k, v in point.items() if k in ("model", "speed_mps")})
    params = {k: v for k, v in point.items() if k not in TASK_KEYS}
    try:
        return replace(task, params=replace(task.params, **params)) if params else task
    except ValueError as e:  # PersonParams says which value is out of its range
        raise ValueError(f"--grid: {e}") from None


def apply(scenario: Scenario, point: Point) -> tuple[Scenario, CueToggles]:
    """The scenario with the grid point's participant settings, and the condition to show."""
    toggles = parse_condition(point["condition"].split("+") if "condition" in point else scenario.condition)
    if "robot" in point:
        scenario = scenario.for_robot(resolve_robot(point["robot"]), point["robot"])
    check_fit(toggles, scenario.robot)
    return replace(scenario, humans=tuple(_human(h, point) for h in scenario.humans)), toggles


def plan_sweep(
    scenarios: Sequence[Scenario], axes: Mapping[str, Sequence[Any]], seeds: Sequence[int]
) -> list[TrialSpec]:
    """Every combination, scenario outermost and seed innermost; refused beyond `MAX_TRIALS`."""
    total = len(scenarios) * math.prod(len(v) for v in axes.values()) * len(seeds)
    if total > MAX_TRIALS:
        raise ValueError(f"the sweep has {total} trials, more than {MAX_TRIALS}")
    specs: list[TrialSpec] = []
    combos = list(itertools.product(*axes.values()))
    for scenario, combo, seed in itertools.product(scenarios, combos, seeds):
        point = dict(zip(axes, combo, strict=True))
        applied, toggles = apply(scenario, point)
        specs.append(TrialSpec(len(specs), applied, toggles, tuple(point.items()), seed))
    return specs
