"""Hostile scenario and parameter files, a seeded mutation fuzzer over every shipped world and
scenario, and `haven validate` (issue 14): a file loads or is refused in one short line naming it."""

import copy
import os
import random
import threading
import traceback
from importlib import resources
from pathlib import Path

import pytest
import yaml
from hostile import BOMB, refused

from haven_scenarios.run.suite import load_suite_config
from haven_scenarios.study.scenario import MAX_TIMEOUT_S, ScenarioError, load_scenario
from haven_scenarios.tools.cli import main
from haven_sim.common.params import ParamsError
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_file import load_world

pytestmark = pytest.mark.integration

WORLDS = sorted(Path(str(resources.files("haven_scenarios") / "worlds")).glob("*.yaml")) + sorted(
    Path(str(resources.files("haven_sim") / "worlds")).glob("*.yaml")
)
SCENARIOS = sorted(Path(str(resources.files("haven_scenarios") / "scenarios")).glob("*.yaml"))
# small_test has human h1, rooms west and east, a charging base
SCENARIO = "name: s\nworld: small_test\nkind: retrieval\n"


def scenario_file(tmp_path, extra, name="s.yaml"):
    p = tmp_path / name
    p.write_text(SCENARIO + extra)
    return p


SCENARIO_CASES = [
    ("robot: {battery: [1, 2]}\n", "robot.battery", "must be a mapping"),
    ("humans: [{id: [1, 2]}]\n", "humans[0].id", "names no human"),
    ("humans: [{id: {h: 1}}]\n", "humans[0].id", "got {'h': 1}"),
    ("robot: {route: 5}\n", "robot.route", "must be a list of room names, got 5"),
    ("humans: [{id: h1, route: 7}]\n", "humans[0].route", "must be a list of room names"),
    ("humans: [{id: h1, route: [west, [east]]}]\n", "humans[0].route[1]", "names no room"),
    ("timeout_s: .inf\n", "timeout_s", "must be a positive number, got inf"),
    ("timeout_s: .nan\n", "timeout_s", "must be a positive number"),
    (f"timeout_s: {MAX_TIMEOUT_S * 2:g}\n", "timeout_s", "must be at most"),
    ("timeout_s: 1" + "0" * 400 + "\n", "timeout_s", "must be a positive number"),
    ("humans: [{id: h1, speed_mps: .inf}]\n", "humans[0].speed_mps", "must be a positive number"),
    ('end_on_contact: "no"\n', "end_on_contact", "must be true or false, got 'no'"),
    ("end_on_contact: 1\n", "end_on_contact", "must be true or false"),
    ("humans: [{id: h1}, {id: h1}]\n", "humans[1].id", "duplicate id"),
    ("condition: [[1]]\n", "condition[0]", "unknown cue '[1]'"),
    ("dwell_time_s: true\n", "dwell_time_s", "must be a positive number, got True"),
    ("robot: {order: [nearest]}\n", "robot.order", "must be the name of a mission behaviour (fixed, nearest, random)"),
    ("cues: {steps_ahead: .inf}\n", "cues", "steps_ahead"),
    ("cues: {marker_size_m: 1" + "0" * 400 + "}\n", "cues.marker_size_m", "must be a finite number"),
    ("? [1, 2]\n: x\n", "YAML syntax error at line 4", "unhashable"),
    ("dwell_time_s: 3.0\ndwell_time_s: 1.0\n", "dwell_time_s", "given twice (line 5); YAML would keep only the last"),
    ("robot: {order: nearest, order: random}\n", "robot.order", "given twice (line 4)"),
]


@pytest.mark.parametrize("extra,key,problem", SCENARIO_CASES, ids=[c[0].strip()[:30] for c in SCENARIO_CASES])
def test_bad_scenario_values_are_one_line_naming_the_key(tmp_path, extra, key, problem):
    refused(ScenarioError, scenario_file(tmp_path, extra), load_scenario, key, problem)


def test_scenario_names_and_world_paths_that_are_not_one_line_are_refused(tmp_path):
    p = tmp_path / "s.yaml"
    p.write_text('name: "two\\nlines"\nworld: small_test\nkind: retrieval\n')
    refused(ScenarioError, p, load_scenario, "name", "must be a non-empty line")
    p.write_text('name: s\nworld: "no\\0such"\nkind: retrieval\n')
    refused(ScenarioError, p, load_scenario, "world", "must be a non-empty line")
    with pytest.raises(ScenarioError, match="no such scenario"):
        load_scenario("no\0such")
    p.write_text(f"name: {'n' * 5000}\nworld: small_test\nkind: retrieval\n")
    refused(ScenarioError, p, load_scenario, "name", "at most 64 characters")


def test_hostile_scenario_files_get_the_world_files_reader(tmp_path):
    refused(ScenarioError, scenario_file(tmp_path, BOMB), load_scenario, "more than 100000 values")
    p = tmp_path / "utf16.yaml"
    p.write_bytes(SCENARIO.encode("utf-16"))
    refused(ScenarioError, p, load_scenario, "UTF-16")
    refused(ScenarioError, "/dev/zero", load_scenario, "not a regular file")
    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)
    # unblocks a reader that opened it
    guard = threading.Timer(30.0, lambda: os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)))
    guard.start()
    try:
        refused(ScenarioError, fifo, load_scenario, "not a regular file")
        refused(ParamsError, fifo, load_suite_config, "cannot read parameter file: not a regular file")
    finally:
        guard.cancel()


def test_hostile_parameter_files_get_refused(tmp_path):
    p = tmp_path / "params.yaml"
    p.write_text("controller:\n  ros__parameters: {rate_hz: 10.0}\n" + BOMB)
    refused(ParamsError, p, load_suite_config, "more than 100000 values")
    p.write_bytes("controller:\n  ros__parameters: {rate_hz: 10.0}\n".encode("utf-16"))
    refused(ParamsError, p, load_suite_config, "not UTF-8")
    p.write_text("controller:\n  ros__parameters: " + "[" * 10_000 + "]" * 10_000 + "\n")
    refused(ParamsError, p, load_suite_config, "controller.ros__parameters", "nested deeper")
    p.write_text("controller:\n  ros__parameters: {rate_hz: 1" + "0" * 400 + "}\n")
    refused(ParamsError, p, load_suite_config, "controller: rate_hz: must be a finite number")


# -- the fuzzer -------------------------------------------------------------------------------------
HOSTILE = [
    "",
    "x",
    "../../x",
    "two\nlines",
    "\x00",
    "é" * 3,
    "x" * 3000,
    0,
    -1,
    7,
    0.5,
    1e308,
    -1e308,
    10**30,
    10**400,
    float("inf"),
    float("-inf"),
    float("nan"),
    True,
    False,
    None,
    [],
    {},
    [1, 2],
    [[1, 2], [3, 4]],
    [1e6, 1e6, 0.0],
    {"a": 1},
]


def _nested(depth):
    v = "deep"
    for _ in range(depth):
        v = [v]
    return v


def _slots(tree):
    """(container, key) of every value in the tree."""
    out, todo = [], [tree]
    while todo:
        node = todo.pop()
        items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else []
        for k, v in items:
            out.append((node, k))
            todo.append(v)
    return out


def _tree_mutation(tree, rng):
    """Change one value of the tree in place; returns what it did."""
    container, key = rng.choice(_slots(tree))
    op = rng.choice(["delete", "duplicate", "replace", "replace", "swap", "rename", "deep"])
    if op == "delete":
        del container[key]
    elif op == "duplicate" and isinstance(container, list):
        container.insert(key, copy.deepcopy(container[key]))
    elif op == "rename" and isinstance(container, dict):
        container[rng.choice(["name", "walls", "id", "zz", "robot", "kind", "cues", "battery", 1])] = container.pop(key)
    elif op == "swap":
        v = container[key]
        container[key] = rng.choice([str(v), [v], {"v": v}, v if not isinstance(v, (int, float)) else -v, 0])
    elif op == "deep":
        container[key] = _nested(rng.choice([10, 70, 150]))
    else:
        container[key] = copy.deepcopy(rng.choice(HOSTILE))
    return f"{op} {key!r}"


def _text_mutation(text, rng):
    """Change the YAML text itself; returns (bytes, what it did)."""
    data = bytearray(text.encode())
    op = rng.choice(["flip", "truncate", "bomb", "alias", "line", "tab"])
    if op == "flip":
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] = rng.randrange(256)
    elif op == "truncate":
        data = data[: rng.randrange(len(data))]
    elif op == "bomb":
        data += BOMB.encode()
    elif op == "alias":  # the first list item anchored, a later one (or a new key) its alias
        lines = data.replace(b"- ", b"- &a ", 1).split(b"\n")
        items = [i for i, line in enumerate(lines) if line.lstrip().startswith(b"- ")][1:]
        if items and rng.random() < 0.7:
            i = rng.choice(items)
            lines[i] = lines[i][: lines[i].index(b"- ") + 2] + b"*a"
        data = bytearray(b"\n".join(lines) + (b"" if items else b"zz: [*a, *a]\n"))
    elif op == "line":
        lines = data.split(b"\n")
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i]) if rng.random() < 0.5 else lines.pop(i)
        data = b"\n".join(lines)
    else:
        data = data.replace(b"  ", b"\t", 1)
    return bytes(data), op


def _dump(tree, **options):
    return yaml.dump(tree, Dumper=getattr(yaml, "CSafeDumper", yaml.SafeDumper), **options)


def _fuzz(files, load, error, seeds, tmp_path):
    failures = []
    parsed = {f: yaml.safe_load(f.read_text()) for f in files}
    for seed in seeds:
        rng = random.Random(seed)
        source = rng.choice(files)
        tree = copy.deepcopy(parsed[source])
        what = [source.name]
        # (in turn: each mutates the tree)
        what.extend(_tree_mutation(tree, rng) if _slots(tree) else "nothing" for _ in range(rng.randint(1, 3)))
        data, op = (
            (_dump(tree, allow_unicode=True).encode(), "") if rng.random() < 0.6 else _text_mutation(_dump(tree), rng)
        )
        what.append(op)
        path = tmp_path / f"case{seed}.yaml"
        path.write_bytes(data)
        try:
            load(path)
        except error as e:
            msg = str(e)
            if "\n" in msg or len(msg) >= 300 or not msg.startswith(f"{path}: "):
                failures.append(f"seed {seed} {what}: not one short line: {msg[:500]!r}")
        except Exception as e:
            tb = traceback.format_exception(e)[-3:]
            failures.append(f"seed {seed} {what}: {type(e).__name__}: {str(e)[:200]} {''.join(tb)[-600:]}")
        path.unlink()
    assert failures == [], (
        f"{len(failures)} of {len(seeds)} mutated files neither loaded nor got one line:\n" + "\n".join(failures[:10])
    )


def test_fuzzed_worlds_load_or_are_refused_in_refused(tmp_path):
    _fuzz(WORLDS, load_world, WorldError, range(1000, 1300), tmp_path)


def test_fuzzed_scenarios_load_or_are_refused_in_refused(tmp_path):
    _fuzz(SCENARIOS, load_scenario, ScenarioError, range(2000, 2300), tmp_path)


# -- haven validate --------------------------------------------------------------------------------
def test_validate_checks_worlds_and_scenarios_without_starting_anything(tmp_path, capsys):
    world, scenario = WORLDS[0], SCENARIOS[0]
    assert main(["validate", str(world), str(scenario)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out == [
        f"ok: {world} (world {load_world(world).name})",
        f"ok: {scenario} (scenario {load_scenario(scenario).name})",
    ]
    bad = scenario_file(tmp_path, "timeout_s: .inf\n")
    neither = tmp_path / "neither.yaml"
    neither.write_text("colour: red\n")
    assert main(["validate", str(world), str(bad), str(neither), "/dev/zero"]) == 2
    captured = capsys.readouterr()
    assert captured.out.splitlines() == [f"ok: {world} (world {load_world(world).name})"]
    assert captured.err.splitlines() == [
        f"haven: error: {bad}: timeout_s: must be a positive number, got inf",
        f"haven: error: {neither}: neither a scenario (no 'kind' or 'world' key), "
        "a world (no 'walls' or 'map' key), a study (no 'scenarios' key), "
        "a robot (no 'kinematics' or 'extends' key) nor a parameter file (no 'ros__parameters')",
        "haven: error: /dev/zero: cannot read file: not a regular file",
    ]


def test_validate_checks_parameter_files(tmp_path, capsys):
    from haven_scenarios.run.suite import packaged_params_file

    typo = tmp_path / "typo.yaml"
    typo.write_text("controller:\n  ros__parameters:\n    rate_hx: 10.0\n")
    assert main(["validate", str(packaged_params_file()), str(typo)]) == 2
    captured = capsys.readouterr()
    assert captured.out.startswith(
        f"ok: {packaged_params_file()} (parameter file for /**, sim_node, velocity_mux, planner"
    )
    assert captured.err == f"haven: error: {typo}: controller: rate_hx: no such parameter (did you mean rate_hz?)\n"


def test_validate_checks_study_files(tmp_path, capsys):
    from haven_scenarios.study.protocol import study_path

    shipped = study_path("haven_paper")
    typo = tmp_path / "typo.yaml"
    typo.write_text(shipped.read_text().replace("counterbalancing:", "counterbalancng:"))
    assert main(["validate", str(shipped), str(typo)]) == 2
    captured = capsys.readouterr()
    assert captured.out.splitlines() == [f"ok: {shipped} (study haven_paper)"]
    assert len(captured.err.splitlines()) == 1 and f"{typo}: counterbalancng: unknown key" in captured.err


def test_validate_applies_the_session_name_rule_haven_run_applies(tmp_path, capsys):
    p = scenario_file(tmp_path, "").with_name("esc.yaml")
    p.write_text(SCENARIO.replace("name: s", "name: ../../escape"))
    assert main(["validate", str(p)]) == 2
    assert "name: must be" in capsys.readouterr().err
