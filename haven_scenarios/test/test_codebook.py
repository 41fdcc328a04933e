"""The study report's codebook: a row for every measure of the long table, with its unit, definition,
source and formula, and the long table's unit column taken from it."""

from __future__ import annotations

import csv
import json
from pathlib import Path

from haven_scenarios.record import codebook
from haven_scenarios.record.codebook import FIELDS, Codebook
from haven_scenarios.record.study_table import LONG, Measure, TrialResults, long_rows
from haven_scenarios.study.questionnaires import likert

ITEMS = [{"id": "side", "text": "I could tell."}, {"id": "surprise", "text": "Surprised me.", "reverse": True}]
LEGIBILITY = likert({"name": "legibility", "points": 7, "items": ITEMS}, "study: questionnaires[0]")


def results() -> list[TrialResults]:
    design = {
        "participant": "p1",
        "trial_id": "hallway-all",
        "practice": False,
        "scenario": "hallway",
        "condition": "all",
        "valid": True,
    }
    measures = (
        Measure("", "hunav_intimate_space_intrusions_pct", 0.4),
        Measure("", "min_human_centre_distance_m", 0.76),
        Measure("h1", "time_not_moving_s", 0.1),
        Measure("h1", "intimate_centre_intrusion_s", 0.0),
        Measure("h1", "contacts_robot_on_person", 0.0),
        Measure("h2", "time_not_moving_s", 3.0),
        Measure("h1", "godspeed_safety", 4.0),
        Measure("h1", "legibility", 5.5),
        Measure("", "a_labs_metric", 1.0),
    )
    return [TrialResults(design, measures)]


def test_every_measure_of_the_long_table_has_one_row_with_its_unit_source_and_formula():
    book = Codebook([LEGIBILITY])
    long = long_rows(results(), book.unit)
    assert LONG.index("unit") == LONG.index("measure") + 1
    assert [r["unit"] for r in long] == ["%", "m", "s", "s", "episodes", "s", "points 1-5", "points 1-7", ""]
    entries = {(e.per_person, e.measure): e for e in book.entries(long)}
    assert len(entries) == 8  # h1's and h2's time_not_moving_s are one measure
    hunav = entries[(False, "hunav_intimate_space_intrusions_pct")]
    assert (
        hunav.formula
        == "robotics-upo/hunav_sim@afa9743 hunav_evaluator/hunav_evaluator/hunav_metrics.py:intimate_space_intrusions"
    )
    assert "HuNavSim" in hunav.source and "surface" in hunav.definition
    assert entries[(False, "min_human_centre_distance_m")].source == "HAVEN for ROS 2"
    standing = entries[(True, "time_not_moving_s")]
    assert standing.wide_column == "<h>_time_not_moving_s" and "task_done" in standing.definition
    assert entries[(True, "intimate_centre_intrusion_s")].wide_column == "<h>_<zone>_centre_intrusion_s"
    assert entries[(True, "contacts_robot_on_person")].wide_column == "<h>_contacts"
    safety = entries[(True, "godspeed_safety")]
    assert (
        safety.unit == "points 1-5"
        and safety.formula.endswith("questionnaires.py:score")
        and "safety_1" in safety.definition
    )
    assert "reverse-scored (1+7-answer): surprise" in entries[(True, "legibility")].definition
    assert entries[(False, "a_labs_metric")].definition.startswith("undocumented")


def test_the_codebook_is_written_as_csv_and_json(tmp_path: Path):
    book = Codebook([LEGIBILITY])
    entries = book.entries(long_rows(results(), book.unit))
    codebook.write(tmp_path, entries)
    with (tmp_path / "codebook.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert tuple(rows[0]) == FIELDS and len(rows) == len(entries)
    assert json.loads((tmp_path / "codebook.json").read_text(encoding="utf-8"))[2]["measure"] == "time_not_moving_s"


def test_participants_csv_columns_have_rows_of_their_own_table():
    from haven_scenarios.study.instruments import NARS, StudyInstruments

    entries = {e.measure: e for e in codebook.participants(StudyInstruments(before=(NARS,)))}
    s3 = entries["nars_s3_emotions"]
    assert (
        s3.table == "participants.csv"
        and s3.unit == "points 3-15"
        and "reverse-scored" in s3.definition
        and "Nomura" in s3.source
    )
    assert {"participant", "not_asked"} <= set(entries)
