"""Questionnaires: the built-ins' structure and scoring, a study's own Likert items, refusals."""

from __future__ import annotations

import pytest

from haven_scenarios.study.questionnaires import (
    BUILTINS,
    answers_record,
    check_answers,
    codebook_rows,
    likert,
    resolve,
    score,
)

TLX = BUILTINS["nasa_tlx"]
GODSPEED = BUILTINS["godspeed"]


def test_raw_tlx_is_the_mean_of_six_subscales_on_0_to_100_in_fives() -> None:
    assert [i.id for i in TLX.items] == ["mental", "physical", "temporal", "performance", "effort", "frustration"]
    assert (TLX.minimum, TLX.maximum, TLX.step) == (0, 100, 5)
    answers = {"mental": 50, "physical": 10, "temporal": 30, "performance": 20, "effort": 60, "frustration": 0}
    s = score(TLX, answers)
    assert s["nasa_tlx_raw"] == pytest.approx(170 / 6, abs=1e-4)
    assert s["nasa_tlx_mental"] == 50 and s["nasa_tlx_performance"] == 20


def test_godspeed_has_its_five_series_asked_and_scored_as_published() -> None:
    assert [name for name, _ in GODSPEED.scales] == [
        "anthropomorphism",
        "animacy",
        "likeability",
        "intelligence",
        "safety",
    ]
    assert [len(ids) for _, ids in GODSPEED.scales] == [5, 6, 5, 5, 3]
    answers = {i.id: 5 for i in GODSPEED.items}
    s = score(GODSPEED, answers)
    assert s["godspeed_likeability"] == 5.0
    assert s["godspeed_safety"] == 5.0  # (published: no item reversed)
    s = score(GODSPEED, {**answers, "safety_1": 4, "safety_2": 5, "safety_3": 1})
    # the 4/5/1: 3.33 as published (4.67 reversed)
    assert s["godspeed_safety"] == pytest.approx(10 / 3, abs=1e-4)
    prompts = {i.id.split("_")[0]: i.prompt for i in GODSPEED.items}
    assert prompts["safety"] == "Please rate your emotional state on these scales."  # about the participant
    assert {prompts[s] for s in ("anthropomorphism", "animacy", "likeability", "intelligence")} == {
        "Please rate your impression of the robot on these scales."
    }


def test_a_studys_own_likert_items_score_as_one_mean_with_reversed_items() -> None:
    items = [{"id": "side", "text": "I knew its side."}, {"id": "odd", "text": "It surprised me.", "reverse": True}]
    q = likert({"name": "legibility", "points": 7, "items": items}, "study.yaml: questionnaires[2]")
    assert score(q, {"side": 7, "odd": 2}) == {"legibility": 6.5}
    record = answers_record(q, {"side": 7, "odd": 2}, "2026-11-24T10:00:00")
    assert record["scores"] == {"legibility": 6.5} and record["answers"] == {"side": 7, "odd": 2}


@pytest.mark.parametrize(
    "answers, message",
    [
        ({"mental": 50}, "nasa_tlx.physical: must be one of 0..100 in steps of 5"),
        ({i.id: 7 for i in TLX.items}, "steps of 5, got 7"),
        ({**{i.id: 5 for i in TLX.items}, "extra": 5}, "no item 'extra'"),
        ({**{i.id: 5 for i in TLX.items}, "mental": True}, "got True"),
        ([1, 2], "answers must be a mapping"),
    ],
)
def test_answers_off_the_scale_are_refused_in_one_line(answers: object, message: str) -> None:
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(".", r"\.")) as e:
        check_answers(TLX, answers)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize(
    "specs, message",
    [
        (["nasa"], r"q\[0\]: unknown questionnaire 'nasa'"),
        (
            [{"name": "nasa_tlx", "items": [{"id": "a", "text": "x"}]}],
            r"is a registered questionnaire \(haven plugins\)",
        ),
        (
            [{"name": "x", "points": 1, "items": [{"id": "a", "text": "x"}]}],
            r"q\[0\]\.points: must be a whole number 2\.\.11",
        ),
        ([{"name": "x", "items": []}], r"q\[0\]\.items: must be a list of 1\.\.100"),
        ([{"name": "x", "items": [{"id": "a", "text": "x"}, {"id": "a", "text": "y"}]}], "item ids must differ"),
        (
            [{"name": "x", "colour": 1, "items": [{"id": "a", "text": "x"}]}],
            r"q\[0\]\.colour: unknown key \(allowed: name, title, instructions, points, anchors, items, shuffle\)",
        ),
        (["godspeed", "godspeed"], "named twice"),
        ([3], "must be a registered questionnaire.s name or a mapping"),
        # YAML reads `anchors: [No, Yes]` as booleans
        (
            [{"name": "x", "anchors": [False, True], "items": [{"id": "a", "text": "x"}]}],
            r"anchors.*must be text, got False \(YAML reads Yes, No, "
            r"On and Off as true or false: put the words in quotes",
        ),
    ],
)
def test_bad_questionnaire_specs_are_one_line_errors(specs: list[object], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        resolve(specs, "q")


def test_resolve_keeps_order_and_serialises_for_the_page() -> None:
    qs = resolve(["godspeed", "nasa_tlx"], "q")
    assert [q.name for q in qs] == ["godspeed", "nasa_tlx"]
    d = qs[1].to_dict()
    assert (
        d["scales"]["raw"] == ["mental", "physical", "temporal", "performance", "effort", "frustration"]
        and d["step"] == 5
    )


def test_a_plugin_questionnaire_is_a_likert_mapping_or_a_questionnaire_under_its_registered_name() -> None:
    from fake_plugins import Entry

    from haven_sim.common import plugins

    trust = {"title": "Trust", "points": 5, "items": [{"id": "rely", "text": "I could rely on the robot."}]}
    reg = plugins.load(
        "questionnaires",
        [
            Entry("trust", "lab.q:TRUST", "lab_q", trust),
            Entry("tlx_again", "lab.q:TLX", "lab_q", TLX),
            Entry("broken", "lab.q:BROKEN", "lab_q", {"items": []}),
            Entry("number", "lab.q:N", "lab_q", 7),
        ],
    )
    assert reg.names() == ["tlx_again", "trust"]
    assert (
        reg.get("trust").name == "trust" and reg.get("trust").maximum == 5 and reg.get("tlx_again").items == TLX.items
    )
    assert reg.problems == [
        "haven.questionnaires broken (lab.q:BROKEN, from lab_q): "
        "questionnaire broken: items: must be a list of 1..100 items, got []",
        "haven.questionnaires number (lab.q:N, from lab_q): is neither a Questionnaire "
        "nor a mapping of Likert items (title, points, anchors, items)",
    ]


def test_codebook_rows_give_each_score_its_range_definition_and_source() -> None:
    rows = {r[0]: r for r in codebook_rows(GODSPEED)}
    assert set(rows) == {f"godspeed_{s}" for s, _ in GODSPEED.scales}
    assert (
        rows["godspeed_safety"][1] == "points 1-5"
        and "mean of items safety_1, safety_2, safety_3" in rows["godspeed_safety"][2]
    )
    assert "reverse" not in rows["godspeed_safety"][2] and "Bartneck" in rows["godspeed_safety"][3]
    assert codebook_rows(TLX)[0][:2] == ("nasa_tlx_raw", "points 0-100")
