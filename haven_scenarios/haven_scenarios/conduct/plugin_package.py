"""`haven plugins new KIND NAME`: a lab's plugin package to start from, one per kind. Each is a
working item of its kind (the docs' example, "Your own plugins") registered by its entry point, with
a test that loads it as HAVEN does and runs one batch trial with it (a questionnaire: scores an
answer), through the fixtures of `haven_scenarios.testing`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from haven_sim.common import plugins
from haven_sim.common.contain import singular


@dataclass(frozen=True)
class Template:
    """One kind's package: the plugin module (`{name}`, `{cls}` filled in), what the entry point
    names in it, the test module, and a data file beside the module (a robot file)."""

    module: str
    target: str
    test: str
    data: str = ""


CUE = Template(
    '''"""{name}: an AR cue (docs: Your own plugins, A cue): an arrow on the floor 1 m ahead on the
robot's path."""

import math

from haven_viz.builtin_cues import SCHEMES
from haven_viz.cue_kind import Shown
from haven_viz.markers import MarkerSpec, Shape


class {cls}:
    haven_plugin_api = 1
    # its value on /haven/cue_state, that value while it shows nothing, its exposure column, its order
    key, hidden, exposure, rank = "{name}", 0, "{name}_shown_s", 10

    def __init__(self, params):
        self.params = params  # the viz node's cue parameters (colour scheme, marker size, ...)

    def show(self, ctx, markers):
        ahead = ctx.path.ahead((1.0,))  # (x, y, heading) 1 m along the path ahead, if there is that much
        if not ahead:
            return None  # nothing to show now
        x, y, h = ahead[0]
        arrow = MarkerSpec(
            "{name}",
            0,
            Shape.ARROW,
            (x - 0.175 * math.cos(h), y - 0.175 * math.sin(h), 0.01),  # where its middle is
            h,
            (0.35, 0.15, 0.02),  # length, width, height (m)
            SCHEMES[self.params.scheme],
        )
        return Shown(1, [arrow] if markers else [], way=((x, y),), on_robot=False)
''',
    "{cls}",
    """def test_it_is_a_cue(haven_plugin):
    assert haven_plugin("cue", "{name}").key == "{name}"


def test_a_batch_trial_shows_it(haven_trial):
    row = haven_trial("hallway", seed=0, condition="{name}")
    assert row["valid"], row["invalid_reasons"]
    assert row["{name}_shown_s"] > 0
""",
)

PARTICIPANT = Template(
    '''"""{name}: a simulated participant model (docs: Your own plugins, A participant model): walks as
HAVEN's Walker does, a fifth slower while the robot is in sight."""

from haven_scenarios.study.participants import Walker
from haven_sim.common.geometry import Twist2D


class {cls}(Walker):
    haven_plugin_api = 1

    def command(self, now, me, robot, percept, others=()):
        walking = super().command(now, me, robot, percept, others)  # (keeps Walker's attention and path up to date)
        if percept.robot is None:
            return walking
        return Twist2D(0.8 * walking.vx, 0.8 * walking.vy, walking.wz)
''',
    "{cls}",
    """def test_it_is_a_participant_model(haven_plugin):
    assert haven_plugin("participant", "{name}") is not None


def test_a_batch_trial_runs_with_it(haven_trial):
    row = haven_trial("hallway", seed=0, model="{name}")
    assert row["valid"], row["invalid_reasons"]
    assert (row["model"], row["end_reason"]) == ("{name}", "completed")
""",
)

METRIC = Template(
    '''"""{name}: a metric (docs: Your own plugins, A metric): time any person was within 2 m of the robot."""

import numpy as np


def {name}(d):
    near = np.zeros(len(d.tl.t), dtype=bool)  # d.tl: the trial on one 0.02 s time grid
    for xy in d.tl.humans.values():
        near |= np.hypot(*(xy - d.tl.robot_xy).T) < 2.0
    return {{"{name}_within_2m_s": round(float(d.tl.dt[near].sum()), 2)}}


{name}.haven_plugin_api = 1
{name}.columns = [("{name}_within_2m_s", "s", "time a person was within 2 m of the robot", "our lab")]
''',
    "{name}",
    """def test_it_is_a_metric(haven_plugin):
    assert [c[0] for c in haven_plugin("metric", "{name}").columns] == ["{name}_within_2m_s"]


def test_a_batch_trial_has_its_column(haven_trial):
    row = haven_trial("hallway", seed=0)
    assert row["valid"], row["invalid_reasons"]
    assert 0.0 < row["{name}_within_2m_s"] < row["duration_s"]
""",
)

QUESTIONNAIRE = Template(
    '''"""{name}: a questionnaire asked after a trial (docs: Your own plugins, A questionnaire)."""

{upper} = {{
    "title": "Trust in the robot",
    "points": 7,
    "anchors": ["Strongly disagree", "Strongly agree"],
    "items": [
        {{"id": "rely", "text": "I could rely on the robot."}},
        {{"id": "wary", "text": "I was wary of the robot.", "reverse": True}},
    ],
}}
''',
    "{upper}",
    """from haven_scenarios.study.questionnaires import score


def test_it_is_a_questionnaire(haven_plugin):
    q = haven_plugin("questionnaire", "{name}")
    assert (q.name, q.maximum, [i.reverse for i in q.items]) == ("{name}", 7, [False, True])


def test_answers_are_scored_with_the_reverse_item_turned_round(haven_plugin):
    q = haven_plugin("questionnaire", "{name}")
    assert score(q, {{"rely": 6, "wary": 2}}) == {{"{name}": 6.0}}
""",
)

PLANNER = Template(
    '''"""{name}: a path planner (docs: Your own plugins, A path planner). It starts as HAVEN's own
visibility planner: change `plan` (its points are shaped into arcs, straights and rotations)."""

from haven_sim.nav.planner import GridPlanner


class {cls}(GridPlanner):
    haven_plugin_api = 1

    def plan(self, start, goal):
        return super().plan(start, goal)  # a haven_sim.nav.planner.Plan, or raise PlanningError
''',
    "{cls}",
    """def test_it_is_a_planner(haven_plugin):
    assert haven_plugin("planner", "{name}") is not None


def test_a_batch_trial_is_planned_with_it(haven_trial):
    row = haven_trial("hallway", seed=0, params={{"planner": {{"algorithm": "{name}"}}}})
    assert row["valid"], row["invalid_reasons"]
    assert row["end_reason"] == "completed"
""",
)

MISSION = Template(
    '''"""{name}: a mission behaviour (docs: Your own plugins, A mission behaviour): the farthest target next."""


class {cls}:
    haven_plugin_api = 1

    def arrange(self, targets, seed):
        return list(targets)  # the order at the start

    def pick(self, candidates, robot, path_length):
        return max(candidates, key=lambda t: path_length((robot.x, robot.y), t.xy))
''',
    "{cls}",
    """def test_it_is_a_mission_behaviour(haven_plugin):
    assert haven_plugin("mission", "{name}") is not None


def test_a_shared_room_trial_runs_its_mission(haven_trial):
    row = haven_trial("shared_room", seed=0, mission="{name}")
    assert row["valid"], row["invalid_reasons"]
    assert row["end_reason"] == "completed"
""",
)

ROBOT = Template(
    '''"""{name}: a robot (docs: Robots, Registering a robot in a package): the robot file beside this module."""

from pathlib import Path

{upper} = Path(__file__).with_name("{name}.yaml")
''',
    "{upper}",
    """def test_it_is_a_robot(haven_plugin):
    assert haven_plugin("robot", "{name}").motion.cruise_speed_mps == 0.3


def test_a_batch_trial_drives_it(haven_trial):
    row = haven_trial("hallway", seed=0, robot="{name}")
    assert row["valid"], row["invalid_reasons"]
    assert (row["robot"], row["end_reason"]) == ("{name}", "completed")
""",
    """# {name}: HAVEN's TurtleBot2, slower (docs: Robots, Your own robot file)
extends: turtlebot2
name: {name}
title: TurtleBot2 at a slower cruise
motion: {{cruise_speed_mps: 0.3}}
sources:
  motion.cruise_speed_mps: "our study's choice"
""",
)

TEMPLATES = {
    "participants": PARTICIPANT,
    "questionnaires": QUESTIONNAIRE,
    "metrics": METRIC,
    "cues": CUE,
    "planners": PLANNER,
    "missions": MISSION,
    "robots": ROBOT,
}

PYPROJECT = """# {name}: a {what} for HAVEN, as a package of its own (made by `haven plugins new {kind} {name}`).
[build-system]
requires = ["setuptools>=64"]
build-backend = "setuptools.build_meta"

[project]
name = "{dist}"
version = "0.1.0"
description = "{what_cap} for HAVEN: {name}"
requires-python = ">=3.11"
dependencies = []  # (and HAVEN itself, haven_scenarios, installed beside it)

[project.entry-points."haven.{kind}"]
{name} = "{package}.{module}:{target}"

[tool.setuptools]
packages = ["{package}"]

[tool.setuptools.package-data]
{package} = ["*.yaml"]
"""

README = """# {dist}

A {what} for HAVEN, registered as `{name}` (entry point group `haven.{kind}`; docs: Your own plugins).

```bash
{python} -m pip install -e {folder}      # into HAVEN's environment
haven plugins                                  # ... {kind} {name} {dist}
{python} -m pytest {folder}              # its tests: one batch trial with it
```
"""

CONFTEST = """# HAVEN's fixtures for a plugin's tests: haven_plugin(kind, name), haven_trial(scenario, seed, ...)
pytest_plugins = ["haven_scenarios.testing"]
"""


def package_files(kind: str, name: str, python: str = "python") -> dict[str, str]:
    """The files of a plugin package for `name` of `kind` (plural or singular), by path under its
    folder; ValueError (one line) for a kind that does not exist, a name a plugin cannot have, or
    a name HAVEN's own items hold."""
    kind = plugins.kind_named(kind)
    if not plugins.NAME.match(name):
        raise ValueError(f"plugin name {name!r}: lower-case letters, digits and _ (at most 40), starting with a letter")
    reg = plugins.registry(kind)
    if name in reg and reg.items[name].package.replace("_", "-").lower() in plugins.OURS:
        ours = [n for n in reg.names() if reg.items[n].package.replace("_", "-").lower() in plugins.OURS]
        raise ValueError(f"{singular(kind)} {name!r} is HAVEN's own (HAVEN's {kind}: {', '.join(ours)})")
    t = TEMPLATES[kind]
    package = f"haven_{name}"
    fill = {"name": name, "cls": "".join(p.capitalize() for p in name.split("_")), "upper": name.upper()}
    what = f"{singular(kind)} plugin"
    meta = {
        **fill,
        "kind": kind,
        "what": what,
        "what_cap": what[0].upper() + what[1:],
        "dist": package.replace("_", "-"),
        "package": package,
        "module": name,
        "target": t.target.format(**fill),
        "folder": package,
        "python": python,
    }
    files = {
        "pyproject.toml": PYPROJECT.format(**meta),
        "README.md": README.format(**meta),
        "conftest.py": CONFTEST,
        f"{package}/__init__.py": f'"""{meta["what_cap"]}: {name} (see {name}.py)."""\n',
        f"{package}/{name}.py": t.module.format(**fill),
        f"tests/test_{name}.py": f'"""{name}: loaded as HAVEN loads it, and used in a trial."""\n\n'
        + t.test.format(**fill),
    }
    if t.data:
        files[f"{package}/{name}.yaml"] = t.data.format(**fill)
    return files


def write_package(kind: str, name: str, into: Path, python: str = "python") -> Path:
    """The package for `name` of `kind` written into a new folder `haven_<name>` under `into`;
    ValueError (one line) if that folder exists or the kind or name is refused."""
    files = package_files(kind, name, python)
    folder = into / f"haven_{name}"
    if folder.exists():
        raise ValueError(f"{folder} exists already: remove it, or write elsewhere (--into)")
    for rel, text in files.items():
        path = folder / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return folder
