"""Study files and their schedules: Williams balance, positions, seeds, practice, refusals in one line."""

from __future__ import annotations

import itertools
from collections import Counter
from pathlib import Path

import pytest
import yaml

from haven_scenarios.study.protocol import StudyError, load_study
from haven_scenarios.study.schedule import (
    design_note,
    latin,
    orders,
    participant_schedule,
    practice_note,
    schedule,
    williams,
)
from haven_viz.cues import DEFAULT_ON

BASE = {
    "name": "pilot",
    "scenarios": ["shared_room"],
    "conditions": {"none": ["none"], "path": ["path_projection"], "signals": ["turn_signals"], "all": ["all"]},
    "participants": 4,
}


def write(tmp_path: Path, **changes: object) -> Path:
    data = {**BASE, **changes}
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def carry_over(rows: list[list[int]]) -> Counter[tuple[int, int]]:
    return Counter((a, b) for row in rows for a, b in itertools.pairwise(row))


@pytest.mark.parametrize("n", [2, 4, 6, 8])
def test_williams_even_every_condition_precedes_every_other_exactly_once(n: int) -> None:
    rows = williams(n)
    assert len(rows) == n
    pairs = carry_over(rows)
    assert set(pairs) == {(a, b) for a in range(n) for b in range(n) if a != b}
    assert set(pairs.values()) == {1}


@pytest.mark.parametrize("n", [3, 5, 7])
def test_williams_odd_needs_two_squares_and_then_each_pair_comes_twice(n: int) -> None:
    rows = williams(n)
    assert len(rows) == 2 * n
    pairs = carry_over(rows)
    assert set(pairs) == {(a, b) for a in range(n) for b in range(n) if a != b}
    assert set(pairs.values()) == {2}
    assert set(carry_over(rows[:n]).values()) != {1}  # one square alone is not balanced


@pytest.mark.parametrize("design", ["williams", "latin", "full", "none"])
def test_one_scenario_or_condition_has_one_order(design: str) -> None:
    assert orders(design, 1) == [[0]]  # (Williams' mirror once made one scenario two "block orders")


@pytest.mark.parametrize(
    "design, n", [("williams", 4), ("williams", 5), ("latin", 3), ("latin", 4), ("full", 3), ("full", 4)]
)
def test_every_design_is_balanced_for_position(design: str, n: int) -> None:
    rows = orders(design, n)
    assert all(sorted(r) == list(range(n)) for r in rows)
    for position in range(n):
        counts = Counter(r[position] for r in rows)
        assert len(counts) == n and len(set(counts.values())) == 1


def test_latin_is_cyclic_and_full_is_every_permutation_once() -> None:
    assert latin(3) == [[0, 1, 2], [1, 2, 0], [2, 0, 1]]
    assert sorted(map(tuple, orders("full", 4))) == sorted(itertools.permutations(range(4)))


def test_schedule_of_a_study_file(tmp_path: Path) -> None:
    path = write(
        tmp_path, practice=[{"scenario": "shared_room", "condition": "all"}], seeds={"policy": "per_trial", "base": 100}
    )
    study = load_study(path)
    trials = schedule(study)
    assert len(trials) == 4 * 5
    p1 = participant_schedule(study, "p01")
    assert [t.position for t in p1] == [1, 2, 3, 4, 5]
    assert (
        p1[0].practice
        and p1[0].trial_id == "practice1-shared_room-all"
        and p1[0].folder == "01_practice1-shared_room-all"
    )
    assert not any(t.practice for t in p1[1:])
    names = [c.name for c in study.conditions]
    for k, p in enumerate(study.participants):  # participant k takes the Williams square's row k
        mine = [t for t in trials if t.participant == p and not t.practice]
        assert [t.condition for t in mine] == [names[i] for i in williams(4)[k]]
    assert [t.seed for t in trials] == list(range(100, 120))  # per_trial: every trial of the study its own


def test_seed_policies_and_repetitions(tmp_path: Path) -> None:
    fixed = load_study(write(tmp_path, seeds={"policy": "fixed", "base": 7}, repetitions=2))
    assert {t.seed for t in schedule(fixed)} == {7}
    ids = [t.trial_id for t in participant_schedule(fixed, "p02")]
    assert len(ids) == 8 and ids[0].endswith("-r1") and ids[4].endswith("-r2") and len(set(ids)) == 8
    per = load_study(write(tmp_path, seeds={"policy": "per_participant", "base": 3}))
    assert {p: {t.seed for t in participant_schedule(per, p)} for p in per.participants} == {
        "p01": {3},
        "p02": {4},
        "p03": {5},
        "p04": {6},
    }


def test_schedule_is_deterministic_and_scenarios_are_counterbalanced_blocks(tmp_path: Path) -> None:
    path = write(
        tmp_path, scenarios=["hallway", "shared_room"], participants=["anna", "ben", "cleo"], counterbalancing="full"
    )
    a, b = schedule(load_study(path)), schedule(load_study(path))
    assert a == b
    anna, ben = ([t for t in a if t.participant == p] for p in ("anna", "ben"))
    assert [t.scenario for t in anna] == ["hallway"] * 4 + ["shared_room"] * 4  # blocks: williams, AB / BA
    assert [t.scenario for t in ben] == ["shared_room"] * 4 + ["hallway"] * 4
    assert [t.block for t in ben] == [1] * 4 + [2] * 4 and [t.position_in_block for t in ben] == [1, 2, 3, 4] * 2
    assert [t.condition for t in ben[:4]] == [t.condition for t in ben[4:]]  # the same order in each block
    assert [t.previous_condition for t in ben[4:]] == ["", *(t.condition for t in ben[4:7])]  # within the block only
    in_file_order = load_study(write(tmp_path, scenarios=["hallway", "shared_room"], participants=3, blocks="none"))
    assert {next(t.scenario for t in participant_schedule(in_file_order, p)) for p in in_file_order.participants} == {
        "hallway"
    }


def test_plan_says_when_two_squares_are_needed_or_the_design_is_incomplete(tmp_path: Path) -> None:
    odd = load_study(
        write(tmp_path, conditions={"none": ["none"], "path": ["path_projection"], "all": ["all"]}, participants=6)
    )
    assert "two Latin squares" in design_note(odd) and "6 participant(s) complete it" in design_note(odd)
    short = load_study(write(tmp_path, participants=5))
    assert "use a multiple of 4" in design_note(short)


def test_shipped_study_and_scenario_files_relative_to_the_study(tmp_path: Path) -> None:
    paper = load_study("haven_paper")
    assert [s.name for s in paper.scenarios] == ["hallway", "shared_room", "shared_room_crossing"] and len(
        paper.conditions
    ) == 4
    assert (paper.blocks, paper.counterbalancing, paper.assignment) == ("williams", "williams", "random")
    assert [(p.scenario.name, p.condition.cues, p.own) for p in paper.practice] == [("practice", ("none",), True)]
    assert practice_note(paper) is None and "12 participant(s) complete it" in design_note(paper)
    assert [q.name for q in paper.resolved_questionnaires()] == ["nasa_tlx", "godspeed", "legibility"]
    shipped = Path(__file__).resolve().parents[1] / "haven_scenarios" / "scenarios" / "shared_room.yaml"
    (tmp_path / "mine.yaml").write_text(
        shipped.read_text().replace(
            "world: shared_room", f"world: {shipped.parents[1] / 'worlds' / 'shared_room.yaml'}"
        )
    )
    study = load_study(write(tmp_path, scenarios=["mine.yaml"]))
    assert study.scenarios[0].spec == str((tmp_path / "mine.yaml").resolve())


@pytest.mark.parametrize(
    "changes, message",
    [
        ({"name": "a/b"}, "name: must be 1 to 64 ASCII letters"),
        ({"scenarios": ["nowhere"]}, "scenarios[0]: nowhere: no such scenario"),
        ({"scenarios": []}, "scenarios: must be a non-empty list"),
        ({"conditions": {"x": ["blink"]}}, "conditions.x: unknown cue 'blink'"),
        (
            {"conditions": {"a": ["all"], "b": list(DEFAULT_ON)}},  # (every cue on in `all`, the drone's too)
            "shows the same cues as condition 'a'",
        ),
        ({"conditions": {"a-b": ["all"]}}, "conditions.a-b: a condition name has no '-'"),
        ({"participants": 0}, "participants: must be a whole number 1..999"),
        ({"participants": ["p1", "p1"]}, "participants[1]: participant 'p1' is listed twice"),
        ({"participants": ["../x"]}, "participants[0]: must be 1 to 64"),
        ({"counterbalancing": "random"}, "counterbalancing: must be one of williams, latin, full, none"),
        ({"practice": [{"scenario": "shared_room", "condition": "nope"}]}, "practice[0].condition: names no condition"),
        ({"practice": {"condition": "all", "cues": ["all"]}}, "practice[0]: give cues or condition, not both"),
        ({"practice": {"cues": ["blink"]}}, "practice[0].cues: unknown cue 'blink'"),
        ({"practice": "practice"}, "practice: must be {scenario: S, cues: [C, ...]} or a list of them"),
        ({"blocks": "random"}, "blocks: must be one of williams, latin, full, none"),
        ({"assignment": {"policy": "random"}}, "assignment.seed: required with policy random"),
        ({"assignment": {"policy": "shuffle", "seed": 1}}, "assignment.policy: must be one of by_id, random"),
        ({"assignment": {"policy": "random", "seed": -1}}, "assignment.seed: must be a whole number 0.."),
        ({"seeds": {"policy": "random"}}, "seeds.policy: must be one of fixed, per_participant, per_trial"),
        ({"questionnaires": ["sus"]}, "questionnaires[0]: unknown questionnaire 'sus'"),
        ({"questionnaires": [{"name": "x", "items": []}]}, "questionnaires[0].items: must be a list"),
        ({"repetitions": True}, "repetitions: must be a whole number"),
        ({"colour": 1}, "colour: unknown key"),
    ],
)
def test_bad_study_files_are_refused_in_one_line_naming_file_and_key(
    tmp_path: Path, changes: dict[str, object], message: str
) -> None:
    with pytest.raises(StudyError) as e:
        load_study(write(tmp_path, **changes))
    text = str(e.value)
    assert "\n" not in text and text.startswith(str(tmp_path / "study.yaml")) and message in text, text


def test_missing_keys_and_files(tmp_path: Path) -> None:
    (tmp_path / "study.yaml").write_text("name: x\n")
    with pytest.raises(StudyError, match="scenarios: is required"):
        load_study(tmp_path / "study.yaml")
    with pytest.raises(StudyError, match="no such study file"):
        load_study("no_such_study")
