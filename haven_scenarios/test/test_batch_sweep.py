"""`haven batch` sweeps: the grid (conditions x participant models x parameters x seeds), and rows that
do not depend on where the trials ran: this process, fresh worker processes, a Dask LocalCluster."""

import csv
import json
from dataclasses import replace

import pytest

from haven_scenarios.run.batch import journal_path, run_batch
from haven_scenarios.run.grid import TASK_KEYS, param_keys, parse_grid, parse_seeds, plan_sweep
from haven_scenarios.study.scenario import HumanTask, load_scenario
from haven_scenarios.tools.cli import main
from haven_sim.common import plugins

pytestmark = pytest.mark.integration


def test_grid_axes_and_seeds_parse_in_the_order_given():
    axes = parse_grid(["model=yielder,walker", "condition=none,path_projection+turn_signals,all", "speed_mps=0.6,1.4"])
    assert list(axes) == ["model", "condition", "speed_mps"]
    assert axes["condition"] == ("none", "path_projection+turn_signals", "all")
    assert axes["speed_mps"] == (0.6, 1.4)
    assert parse_seeds("0-3,7,2") == (0, 1, 2, 3, 7)


@pytest.mark.parametrize(
    "grid, says",
    [
        (["mood=happy"], "--grid: unknown key 'mood' (valid: " + ", ".join((*TASK_KEYS, *param_keys())) + ")"),
        (
            ["model=teleop"],
            "--grid model: 'teleop' is not a simulated participant model "
            f"({', '.join(plugins.registry('participants').names())})",
        ),
        (["speed_mps=fast"], "--grid speed_mps: expected numbers, got 'fast'"),
        (["speed_mps=9"], "--grid speed_mps: must be within (0, 3] m/s, got 9"),
        (["condition=lasers"], "unknown cue 'lasers'"),
        (["model=walker", "model=yielder"], "--grid: model given twice"),
        (["model"], "--grid: expected KEY=V1,V2,..., got 'model'"),
        (["model=walker,,yielder"], "--grid model: expected comma-separated values"),
    ],
)
def test_a_bad_grid_is_one_line_naming_what_is_wrong(grid, says):
    with pytest.raises(ValueError) as e:
        parse_grid(grid)
    assert says in str(e.value) and "\n" not in str(e.value)


@pytest.mark.parametrize("text", ["", "a-b", "5-2", "-1", "0-9,x"])
def test_bad_seeds_are_refused(text):
    with pytest.raises(ValueError, match="--seeds"):
        parse_seeds(text)


def test_the_sweep_is_every_combination_and_sets_only_the_simulated_participants():
    room = load_scenario("shared_room")
    mixed = replace(load_scenario("hallway_pair"), name="mixed")
    mixed = replace(mixed, humans=(mixed.humans[0], HumanTask("h2", "teleop", mixed.humans[1].route, 1.0)))
    specs = plan_sweep(
        [room, mixed], {"condition": ("all", "none"), "model": ("yielder",), "speed_mps": (0.7,)}, (4, 5)
    )
    assert [s.index for s in specs] == list(range(8))
    assert [(s.scenario.name, s.columns()["condition"], s.seed) for s in specs[:4]] == [
        ("shared_room", "all", 4),
        ("shared_room", "all", 5),
        ("shared_room", "none", 4),
        ("shared_room", "none", 5),
    ]
    assert specs[0].columns() == {
        "trial": 0,
        "scenario": "shared_room",
        "condition": "all",
        "model": "yielder",
        "robot": "turtlebot2",
        "speed_mps": 0.7,
        "seed": 4,
    }
    h1, h2 = specs[4].scenario.humans
    assert (h1.model, h1.speed_mps) == ("yielder", 0.7) and h2 == mixed.humans[1]  # the teleoperated one is left alone
    assert specs[2].toggles != specs[0].toggles


def test_without_a_grid_each_scenario_keeps_its_own_condition_and_participants():
    hallway = load_scenario("hallway")
    (spec,) = plan_sweep([hallway], {}, (3,))
    assert (
        spec.scenario == hallway
        and spec.columns()["condition"] == "turn_signals"
        and spec.columns()["model"] == hallway.humans[0].model
    )


SWEEP = (["shared_room"], {"model": ("walker", "yielder")}, (0, 1))


def _sweep_csv(tmp_path, name, **where):
    specs = plan_sweep([load_scenario(s) for s in SWEEP[0]], SWEEP[1], SWEEP[2])
    out = tmp_path / f"{name}.csv"
    rows = run_batch(specs, out, **where)
    assert [r["trial"] for r in rows] == list(range(len(specs))) and not journal_path(out).exists()
    return out.read_bytes()


def test_rows_are_byte_identical_in_this_process_in_fresh_worker_processes_and_on_a_dask_local_cluster(tmp_path):
    """The in-process run reuses this (already used) interpreter; the workers are spawned fresh,
    each with its own hash seed, so module state or set order that leaked into a row would show."""
    one = _sweep_csv(tmp_path, "one")
    assert _sweep_csv(tmp_path, "pool", workers=2) == one
    assert _sweep_csv(tmp_path, "dask", workers=2, cluster="local") == one
    read = list(csv.DictReader(one.decode().splitlines()))
    assert [(r["model"], r["seed"]) for r in read] == [
        ("walker", "0"),
        ("walker", "1"),
        ("yielder", "0"),
        ("yielder", "1"),
    ]
    assert len({r["min_human_centre_distance_m"] for r in read}) > 1  # the model and the seed change the trial


def test_finished_rows_are_journaled_as_they_come(tmp_path, monkeypatch):
    """A crash after the second trial: both finished rows are in the journal, nothing is lost."""
    import haven_scenarios.run.batch as batch

    real = batch.run_rows

    def crash_after_two(*args, **kwargs):
        for i, row in enumerate(real(*args, **kwargs)):
            if i == 2:
                raise KeyboardInterrupt
            yield row

    monkeypatch.setattr(batch, "run_rows", crash_after_two)
    out = tmp_path / "b.csv"
    with pytest.raises(KeyboardInterrupt):
        run_batch(plan_sweep([load_scenario("shared_room")], {}, (0, 1, 2)), out)
    saved = [json.loads(line) for line in journal_path(out).read_text().splitlines()]
    assert [(r["trial"], r["seed"]) for r in saved] == [(0, 0), (1, 1)] and not out.exists()


@pytest.mark.parametrize(
    "argv, says",
    [
        (["batch", "hallway", "--grid", "mood=happy"], "haven: error: --grid: unknown key 'mood' (valid: "),
        (
            ["batch", "hallway", "--seeds", "0-3", "--trials", "4"],
            "haven: error: give either --seeds or --trials/--seed, not both",
        ),
        (
            ["batch", "hallway", "--condition", "none", "--grid", "condition=all"],
            "haven: error: give either --condition or --grid condition",
        ),
        (["batch", "hallway", "--cluster", "myhost"], "haven: error: --cluster: expected local or a scheduler address"),
        (["batch", "hallway", "--workers", "0"], "argument --workers: must be 1..1024, got 0"),
    ],
)
def test_bad_batch_arguments_are_one_line(argv, says, capsys):
    try:
        code = main(argv)
    except SystemExit as ended:
        code = ended.code
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and says in err


def test_a_participant_parameter_is_a_grid_axis_set_on_every_simulated_person():
    room = load_scenario("shared_room")
    specs = plan_sweep([room], {"reaction_s": (0.3, 2.0), "fov_deg": (60.0,)}, (0,))
    assert [(s.scenario.humans[0].params.reaction_s, s.scenario.humans[0].params.fov_deg) for s in specs] == [
        (0.3, 60.0),
        (2.0, 60.0),
    ]
    columns = {
        "trial": 1,
        "scenario": "shared_room",
        "condition": "all",
        "model": "walker",
        "robot": "turtlebot2",
        "reaction_s": 2.0,
        "fov_deg": 60.0,
        "seed": 0,
    }
    assert specs[1].columns() == columns
    with pytest.raises(ValueError, match=r"^--grid: fov_deg must be within \(0, 360\], got 400$"):
        plan_sweep([room], {"fov_deg": (400.0,)}, (0,))


def test_in_a_log_the_progress_is_a_line_now_and_then_with_rate_and_eta(monkeypatch):
    import io

    from haven_scenarios.run.batch import Progress

    monkeypatch.setattr(Progress, "LOG_EVERY_S", 0.0)
    out = io.StringIO()  # not a terminal: no bar
    progress = Progress(3, out)
    for done in (1, 2, 3):
        progress.update(done)
    progress.close()
    lines = out.getvalue().splitlines()
    assert (
        len(lines) == 3
        and all("trials/min, about" in line and "s to go" in line for line in lines[:2])
        and lines[2].startswith("3/3 trials in ")
    )
