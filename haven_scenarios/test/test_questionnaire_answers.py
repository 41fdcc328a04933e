"""Questionnaire answers after a trial, without ROS: what the web node takes from a page and writes,
what `haven run` reads back to know the questionnaires are over, and `--questionnaire`'s errors."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from haven_scenarios.conduct.after_trial import as_parameter
from haven_scenarios.record.answers import AnswerBook, answered, from_parameter, over, wanted
from haven_scenarios.study.questionnaires import ANSWERS_FILE, BUILTINS, likert, registered, score
from haven_scenarios.tools.cli import main
from haven_scenarios.web.access import ANSWERS, CONSOLE, SKIP_QUESTIONNAIRES, roles
from haven_scenarios.web.page_config import PageSettings, page_config
from haven_scenarios.web.wizard import Wizard
from haven_sim.common.events import Event, EventKind

TLX, GODSPEED = BUILTINS["nasa_tlx"], BUILTINS["godspeed"]
LEGIBILITY = {
    "name": "legibility",
    "points": 7,
    "anchors": ["Strongly disagree", "Strongly agree"],
    "items": [
        {"id": "side", "text": "I could tell which way the robot would pass me."},
        {"id": "surprise", "text": "It surprised me.", "reverse": True},
    ],
}
TLX_ANSWERS = {"mental": 50, "physical": 10, "temporal": 30, "performance": 20, "effort": 60, "frustration": 0}


def message(answers, human="h1", questionnaire="nasa_tlx"):
    return json.dumps({"human": human, "questionnaire": questionnaire, "answers": answers})


def book(folder: Path) -> AnswerBook:
    return AnswerBook(folder, ["h1", "h2"], [TLX, GODSPEED, likert(LEGIBILITY, "test")])


def test_answers_are_checked_written_and_an_event(tmp_path):
    e = book(tmp_path).take("h1", message(TLX_ANSWERS), 12.5, "2026-11-24T10:00:00+00:00")
    assert e.kind is EventKind.QUESTIONNAIRE_ANSWERED and e.stamp == 12.5
    assert (e["by"], e["questionnaire"], e["scores"]) == ("h1", "nasa_tlx", score(TLX, TLX_ANSWERS))
    assert Event.from_json(e.to_json()) == e  # the recorder and the console read it back
    written = json.loads((tmp_path / ANSWERS_FILE).read_text())
    assert written == {
        "h1": {
            "nasa_tlx": {
                "answers": TLX_ANSWERS,
                "scores": score(TLX, TLX_ANSWERS),
                "answered_at": "2026-11-24T10:00:00+00:00",
                "order": list(TLX_ANSWERS),
            }
        }
    }
    assert [p.name for p in tmp_path.iterdir()] == [ANSWERS_FILE]  # (no temporary file left beside it)


@pytest.mark.parametrize(
    ("page", "text", "problem"),
    [
        ("h2", message(TLX_ANSWERS), "h2's page may not answer for 'h1'"),
        ("h1", message(TLX_ANSWERS, questionnaire="sus"), "no questionnaire 'sus' for h1"),
        (
            "h1",
            message({**TLX_ANSWERS, "mental": None}),
            "nasa_tlx.mental: must be one of 0..100 in steps of 5, got None",
        ),
        ("h1", message({k: v for k, v in TLX_ANSWERS.items() if k != "effort"}), "nasa_tlx.effort: must be one of"),
        ("h1", message({**TLX_ANSWERS, "mental": 52}), "nasa_tlx.mental: must be one of 0..100 in steps of 5, got 52"),
        ("h1", message({**TLX_ANSWERS, "extra": 5}), "nasa_tlx: no item 'extra'"),
        ("h1", "{not json", "not JSON"),
        (
            "h1",
            json.dumps({"human": "h1", "answers": {}}),
            "must be a JSON object with human, questionnaire and answers",
        ),
        ("h1", json.dumps([1]), "must be a JSON object"),
        ("h1", " " * 70_000, "questionnaire answers of 70000 bytes"),
    ],
)
def test_a_message_that_is_not_the_pages_own_complete_answers_is_refused_and_nothing_written(
    tmp_path, page, text, problem
):
    with pytest.raises(ValueError, match=re.escape(problem)) as refused:
        book(tmp_path).take(page, text, 1.0, "t")
    assert "\n" not in str(refused.value)
    assert not (tmp_path / ANSWERS_FILE).exists()


def test_each_questionnaire_is_answered_once_and_a_restarted_node_goes_on_from_the_file(tmp_path):
    first = book(tmp_path)
    first.take("h1", message(TLX_ANSWERS), 1.0, "t1")
    again = book(tmp_path)  # (the web node started again)
    with pytest.raises(ValueError, match="h1 has answered nasa_tlx already"):
        again.take("h1", message({k: 0 for k in TLX_ANSWERS}), 2.0, "t2")
    again.take("h2", message({k: 100 for k in TLX_ANSWERS}, human="h2"), 3.0, "t3")
    data = json.loads((tmp_path / ANSWERS_FILE).read_text())
    assert (
        data["h1"]["nasa_tlx"]["answers"] == TLX_ANSWERS and data["h2"]["nasa_tlx"]["scores"]["nasa_tlx_raw"] == 100.0
    )


def record(folder: Path, *events: Event) -> None:
    with (folder / "events.jsonl").open("a") as f:
        f.writelines(e.to_json() + "\n" for e in events)


def trial(folder: Path, reason: str) -> None:
    record(
        folder,
        Event(EventKind.TRIAL_START, 0.0, "scenario"),
        Event(EventKind.TRIAL_END, 9.0, "scenario", {"reason": reason}),
    )


def test_the_questionnaires_are_over_when_every_answer_is_written_and_recorded(tmp_path):
    humans, names = ["h1"], ["nasa_tlx", "legibility"]
    trial(tmp_path, "completed")
    assert wanted(tmp_path) and over(tmp_path, humans, names) is None
    b = book(tmp_path)
    record(tmp_path, b.take("h1", message(TLX_ANSWERS), 10.0, "t"))
    legibility = b.take("h1", message({"side": 6, "surprise": 2}, questionnaire="legibility"), 11.0, "t")
    assert legibility["scores"] == {"legibility": 6.0}  # (surprise reversed: 8 - 2)
    assert over(tmp_path, humans, names) is None  # written, not yet recorded: the bag would miss it
    assert answered(tmp_path, ["h1", "h2"], names) == {"h1": ["nasa_tlx", "legibility"], "h2": []}
    record(tmp_path, legibility)
    assert over(tmp_path, humans, names) == "answered"
    assert over(tmp_path, ["h1", "h2"], names) is None  # h2 has not answered


def test_the_researchers_skip_ends_them_and_an_aborted_or_unstarted_trial_has_none(tmp_path):
    trial(tmp_path, "stopped")
    record(tmp_path, *Wizard().skip_questionnaires(10.0))
    assert over(tmp_path, ["h1"], ["nasa_tlx"]) == "skipped"
    aborted, unstarted = tmp_path / "a", tmp_path / "b"
    aborted.mkdir()
    unstarted.mkdir()
    trial(aborted, "aborted")
    record(unstarted, Event(EventKind.TRIAL_END, 0.0, "scenario", {"reason": "aborted"}))
    assert not wanted(aborted) and not wanted(unstarted) and not wanted(tmp_path / "nothing")
    interrupted = tmp_path / "c"  # (Ctrl-C mid-trial: it runs again, and is asked about then)
    interrupted.mkdir()
    trial(interrupted, "interrupted")
    assert not wanted(interrupted)


def test_the_pages_get_the_questionnaires_and_only_participants_answer_only_the_console_skips():
    from haven_scenarios.study.scenario import load_scenario

    r, string = roles(["h1"]), "std_msgs/msg/String"
    assert r["h1"].may_publish(ANSWERS, string) is None and r[CONSOLE].may_publish(ANSWERS, string)
    assert r[CONSOLE].may_publish(SKIP_QUESTIONNAIRES, string) is None and r["h1"].may_publish(
        SKIP_QUESTIONNAIRES, string
    )
    settings = PageSettings(questionnaires=(TLX, GODSPEED), teleoperated=("h1",))
    c = page_config(r["h1"], load_scenario("hallway"), settings)
    assert [q["name"] for q in c["questionnaires"]] == ["nasa_tlx", "godspeed"] and c["teleoperated"] == ["h1"]
    assert c["questionnaires"][1]["differential"] and not c["questionnaires"][0]["differential"]
    assert c["questionnaires"][0]["items"][3]["low"] == "Perfect"


def test_the_web_nodes_parameter_carries_the_specs(tmp_path):
    specs = ["nasa_tlx", {**LEGIBILITY, "title": "It's 'quoted'"}]
    text = as_parameter(specs)
    assert text.startswith("'") and text.endswith("'")  # (ROS reads a quoted YAML string; '' is one quote)
    assert [q.name for q in from_parameter(text[1:-1].replace("''", "'"))] == ["nasa_tlx", "legibility"]
    for bad, problem in (
        ("{", "not JSON"),
        ('{"a": 1}', "must be a JSON list"),
        ('["sus"]', "unknown questionnaire 'sus'"),
    ):
        with pytest.raises(ValueError, match=problem):
            from_parameter(bad)


def run_errors(capsys, *argv) -> list[str]:
    assert main(["run", *argv]) == 2
    return capsys.readouterr().err.splitlines()


def test_questionnaire_usage_errors_are_one_line(tmp_path, capsys):
    assert run_errors(capsys, "--questionnaire", "nasa_tlx") == [
        "haven: error: --questionnaire: participants answer in their pages: "
        "needs --web and teleoperated humans (--teleop)"
    ]
    assert run_errors(capsys, "--web", "--questionnaire", "nasa_tlx")[0].endswith(
        "needs --web and teleoperated humans (--teleop)"
    )
    web = ["--web", "--teleop", "h1", "--port", "0", "--sessions", str(tmp_path / "s")]
    assert run_errors(capsys, *web, "--questionnaire", "sus") == [
        f"haven: error: --questionnaire sus: neither a registered questionnaire ({', '.join(registered())}) nor a file"
    ]
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: legibility\npoints: 12\nitems: [{id: a, text: A}]\n")
    assert run_errors(capsys, *web, "--questionnaire", str(bad)) == [
        f"haven: error: {bad}: points: must be a whole number 2..11, got 12"
    ]
    bad.write_text("- just a list\n")
    assert run_errors(capsys, *web, "--questionnaire", str(bad)) == [
        f"haven: error: {bad}: must be a mapping of one Likert questionnaire (name, points, anchors, items)"
    ]
    bad.write_text("name: [unclosed\n")
    (line,) = run_errors(capsys, *web, "--questionnaire", str(bad))
    assert line.startswith(f"haven: error: {bad}:")
    assert run_errors(capsys, *web, "--questionnaire", "godspeed", "godspeed") == [
        "haven: error: --questionnaire: a questionnaire is named twice"
    ]
    assert not (tmp_path / "s").exists()  # refused before anything started


def test_mixed_items_reach_the_page_in_the_order_the_answers_record_per_person_and_trial(tmp_path):
    """`{name: godspeed, shuffle: true}`: the page of h1 in session s1 shows the items in the order
    item_order gives for s1/h1, h2 and another session in others; the answers store that order."""
    from haven_scenarios.study.scenario import load_scenario

    (mixed,) = from_parameter(json.dumps([{"name": "godspeed", "shuffle": True}]))
    r = roles(["h1", "h2"])
    settings = PageSettings(session="s1", questionnaires=(mixed,), teleoperated=("h1", "h2"))
    shown = {
        h: [i["id"] for i in page_config(r[h], load_scenario("hallway"), settings)["questionnaires"][0]["items"]]
        for h in ("h1", "h2")
    }
    other = page_config(r["h1"], load_scenario("hallway"), PageSettings(session="s2", questionnaires=(mixed,)))[
        "questionnaires"
    ][0]["items"]
    assert (
        shown["h1"] != shown["h2"]
        and shown["h1"] != [i["id"] for i in other]
        and sorted(shown["h1"]) == sorted(i.id for i in GODSPEED.items)
    )
    (tmp_path / "s1").mkdir()
    answers = {i.id: 3 for i in GODSPEED.items}
    AnswerBook(tmp_path / "s1", ["h1"], [mixed]).take("h1", message(answers, questionnaire="godspeed"), 1.0, "t")
    stored = json.loads((tmp_path / "s1" / ANSWERS_FILE).read_text())["h1"]["godspeed"]
    assert stored["order"] == shown["h1"] and stored["scores"] == score(GODSPEED, answers)
