"""Protocols without order confounds: scenario blocks and conditions counterbalanced together,
random assignment that is seeded, recorded and balanced, a neutral practice, the stored study's
comparison, and the order/carry-over table."""

from __future__ import annotations

import itertools
import json
from collections import Counter
from pathlib import Path

import pytest
import yaml

from haven_scenarios.record.order_table import FIRST, order_rows
from haven_scenarios.record.progress import STORED, bind, differences
from haven_scenarios.record.study_table import Measure, TrialResults
from haven_scenarios.study.protocol import StudyError, load_study
from haven_scenarios.study.schedule import (
    PlannedTrial,
    assignment,
    design_note,
    practice_note,
    schedule,
    sequence_count,
    sequences,
)

FOUR = {"none": ["none"], "path": ["path_projection"], "signals": ["turn_signals"], "all": ["all"]}
THREE = {"none": ["none"], "path": ["path_projection"], "all": ["all"]}
SCENARIOS = ["hallway", "shared_room", "hallway_pair"]


def write(tmp_path: Path, **keys: object) -> Path:
    data = {"name": "pilot", "scenarios": SCENARIOS[:2], "conditions": FOUR, "participants": 4, **keys}
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def study_trials(trials: list[PlannedTrial]) -> dict[str, list[PlannedTrial]]:
    out: dict[str, list[PlannedTrial]] = {}
    for t in trials:
        if not t.practice:
            out.setdefault(t.participant, []).append(t)
    return out


@pytest.mark.parametrize(
    "blocks, scenarios, design, conditions, policy",
    [
        ("williams", 2, "williams", FOUR, "by_id"),
        ("williams", 2, "williams", FOUR, "random"),
        ("williams", 3, "williams", FOUR, "random"),  # 6 block orders x 4 condition orders: 12 sequences
        ("williams", 2, "williams", THREE, "by_id"),  # 2 x 6: 6 sequences
        ("latin", 3, "latin", THREE, "random"),
        ("full", 3, "williams", FOUR, "by_id"),
    ],
)
def test_a_complete_set_balances_blocks_conditions_and_carry_over(
    tmp_path: Path, blocks: str, scenarios: int, design: str, conditions: dict[str, list[str]], policy: str
) -> None:
    probe = load_study(
        write(tmp_path, scenarios=SCENARIOS[:scenarios], conditions=conditions, blocks=blocks, counterbalancing=design)
    )
    n = sequence_count(probe)
    study = load_study(write(tmp_path, scenarios=SCENARIOS[:scenarios], conditions=conditions, blocks=blocks,
                             counterbalancing=design, participants=2 * n,
                             assignment={"policy": policy, "seed": 11}))  # fmt: skip
    mine = study_trials(schedule(study))
    assert len(mine) == 2 * n
    # each scenario at each block position equally often
    at_block = Counter(
        (b, next(block).scenario) for ts in mine.values() for b, block in itertools.groupby(ts, key=lambda t: t.block)
    )
    assert len(at_block) == scenarios**2 and len(set(at_block.values())) == 1, at_block
    # each condition at each position within a block equally often, per scenario
    at_position = Counter((t.scenario, t.position_in_block, t.condition) for ts in mine.values() for t in ts)
    assert len(at_position) == scenarios * len(conditions) ** 2 and len(set(at_position.values())) == 1, at_position
    # within blocks, each condition right before each other equally often (williams: carry-over balanced)
    pairs = Counter(
        (t.scenario, t.previous_condition, t.condition) for ts in mine.values() for t in ts if t.previous_condition
    )
    if design == "williams":
        assert len(pairs) == scenarios * len(conditions) * (len(conditions) - 1) and len(set(pairs.values())) == 1, (
            pairs
        )
    assert all(t.previous_condition == "" for ts in mine.values() for t in ts if t.position_in_block == 1)


def test_random_assignment_is_seeded_reproducible_and_balanced_in_every_complete_set(tmp_path: Path) -> None:
    def drawn(seed: int, participants: int = 12) -> list[int]:
        return sequences(
            load_study(write(tmp_path, participants=participants, assignment={"policy": "random", "seed": seed}))
        )

    draws = {seed: drawn(seed) for seed in range(20)}  # (each study loaded once: the loads are this test's time)
    assert drawn(5) == draws[5]  # the same seed: the same assignment, every time
    assert draws[5] != draws[6]
    assert drawn(5, 14)[:12] == draws[5]  # more participants later: the first ones keep theirs
    for got in draws.values():
        assert all(sorted(got[i : i + 4]) == [0, 1, 2, 3] for i in range(0, 12, 4))  # permuted sets of 4
    assert {tuple(got[:4]) for got in draws.values()} != {(0, 1, 2, 3)}  # it does shuffle
    by_id = sequences(load_study(write(tmp_path, participants=6)))
    assert by_id == [0, 1, 2, 3, 0, 1]


def test_assignment_and_protocol_are_recorded_and_a_change_is_refused(tmp_path: Path) -> None:
    root = tmp_path / "studies" / "pilot"
    study = load_study(write(tmp_path, assignment={"policy": "random", "seed": 3}))
    trials = bind(study, root)
    stored = json.loads((root / STORED).read_text())
    assert stored["assignment"] == assignment(study) and sorted(stored["assignment"].values()) == [1, 2, 3, 4]
    assert stored["study"]["assignment"] == {"policy": "random", "seed": 3} and stored["study"]["blocks"] == "williams"
    assert [(t["participant"], t["sequence"], t["block"], t["position_in_block"]) for t in stored["schedule"]] == [
        (t.participant, t.sequence, t.block, t.position_in_block) for t in trials
    ]
    for changed, key in [({"assignment": {"policy": "random", "seed": 4}}, "assignment"),
                         ({"blocks": "none"}, "blocks"),
                         ({"practice": {"cues": ["none"]}}, "practice")]:  # fmt: skip
        with pytest.raises(StudyError, match=f"the study changed since its first run .*\\({key} differ"):
            bind(load_study(write(tmp_path, **{"assignment": {"policy": "random", "seed": 3}, **changed})), root)


def test_a_study_stored_before_blocks_and_assignment_compares_as_file_order_by_id(tmp_path: Path) -> None:
    """study.json from before the keys existed: blocks ran in the file's order, by id."""
    old = {
        k: v
        for k, v in load_study(write(tmp_path, blocks="none")).describe().items()
        if k not in ("blocks", "assignment")
    }
    assert differences(old, load_study(write(tmp_path, blocks="none")).describe()) == []
    assert differences(old, load_study(write(tmp_path)).describe()) == ["blocks"]  # now counterbalanced: a change
    one = {
        k: v
        for k, v in load_study(write(tmp_path, scenarios=["hallway"])).describe().items()
        if k not in ("blocks", "assignment")
    }
    # one block: the same schedule
    assert differences(one, load_study(write(tmp_path, scenarios=["hallway"])).describe()) == []


def test_practice_defaults_to_no_cue_in_the_practice_room_and_need_not_be_a_study_condition(tmp_path: Path) -> None:
    study = load_study(write(tmp_path, conditions={"path": ["path_projection"], "all": ["all"]}, practice={}))
    (p,) = study.practice
    assert (p.scenario.name, p.condition.name, p.condition.cues) == ("practice", "none", ("none",))
    first = schedule(study)[0]
    assert (first.trial_id, first.practice, first.block, first.cues) == ("practice1-practice-none", True, 0, ("none",))
    two = load_study(
        write(
            tmp_path,
            practice=[{"cues": ["path_projection", "turn_signals"]}, {"scenario": "shared_room", "condition": "none"}],
        )
    )
    assert [t.trial_id for t in schedule(two)[:2]] == [
        "practice1-practice-path_projection_turn_signals",
        "practice2-shared_room-none",
    ]
    # cues before the no-cue condition
    assert practice_note(two) is not None and "path_projection" in str(practice_note(two))
    # (the old form still loads)
    old = load_study(write(tmp_path, practice=[{"scenario": "shared_room", "condition": "all"}]))
    assert "carry-over" in str(practice_note(old)) and practice_note(study) is None


def result(participant: str, scenario: str, condition: str, position: int, block: int, in_block: int, previous: str,
           value: float, valid: bool = True, practice: bool = False) -> TrialResults:  # fmt: skip
    design = {"participant": participant, "scenario": scenario, "condition": condition, "order_position": position,
              "block": block, "position_in_block": in_block, "previous_condition": previous, "valid": valid,
              "practice": practice}  # fmt: skip
    return TrialResults(design, (Measure("", "x_m", value),))


def test_order_table_means_by_position_and_previous_condition() -> None:
    results = [
        result("p1", "s", "none", 2, 1, 1, "", 1.0),
        result("p1", "s", "all", 3, 1, 2, "none", 3.0),
        result("p2", "s", "all", 2, 1, 1, "", 2.0),
        result("p2", "s", "none", 3, 1, 2, "all", 6.0),
        result("p2", "s", "none", 4, 1, 3, "all", 100.0, valid=False),  # left out
        result("p2", "s", "none", 1, 0, 1, "", 50.0, practice=True),  # left out
    ]
    rows = {
        (r["factor"], r["level"], r["condition"]): (r["n"], r["mean"]) for r in order_rows(results, ["none", "all"])
    }
    assert rows[("order_position", "2", "")] == (2, 1.5) and rows[("order_position", "3", "")] == (2, 4.5)
    assert (
        rows[("block", "1", "")] == (4, 3.0)
        and ("block", "0", "") not in rows
        and ("order_position", "4", "") not in rows
    )
    assert rows[("previous_condition", FIRST, "")] == (2, 1.5) and rows[("previous_condition", "all", "none")] == (
        1,
        6.0,
    )
    assert rows[("previous_condition", "none", "all")] == (1, 3.0) and rows[("previous_condition", FIRST, "none")] == (
        1,
        1.0,
    )
    order = [(r["factor"], r["condition"], r["level"]) for r in order_rows(results, ["none", "all"])]
    assert order[:2] == [("block", "", "1"), ("order_position", "", "2")]
    assert order[-4:] == [("previous_condition", "none", FIRST), ("previous_condition", "none", "all"),
                          ("previous_condition", "all", FIRST), ("previous_condition", "all", "none")]  # fmt: skip


def test_plan_states_the_combined_design_and_the_participants_it_needs(tmp_path: Path) -> None:
    two = load_study(write(tmp_path, participants=6))
    assert sequence_count(two) == 4 and "4 sequences (the least common multiple of 2 and 4)" in design_note(two)
    assert "6 participant(s) do not complete it: use a multiple of 4" in design_note(
        two
    ) and "Assignment: by id" in design_note(two)
    three = load_study(
        write(tmp_path, scenarios=SCENARIOS, participants=12, assignment={"policy": "random", "seed": 2})
    )
    note = design_note(three)
    assert sequence_count(three) == 12 and "two Latin squares" in note and "12 participant(s) complete it" in note
    assert "Assignment: random (seed 2)" in note
    one = load_study(write(tmp_path, scenarios=["hallway"], blocks="none"))
    assert design_note(one).startswith("Scenario blocks: one scenario.") and sequence_count(one) == 4
