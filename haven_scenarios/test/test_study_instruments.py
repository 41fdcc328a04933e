"""The instruments before and after a study: NARS and the ranking scored as published, mixed item
orders, the study file's keys, the participant's instruments.json and participants.csv."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest
import yaml

from haven_scenarios.conduct.instruments import BATCH_REASON, run_instruments, terminal_asker
from haven_scenarios.record.participants import InstrumentBook, codebook_rows, participant_rows, write_participants
from haven_scenarios.study.instruments import DEMOGRAPHICS, NARS, consent, preference
from haven_scenarios.study.protocol import StudyError, load_study, parse_study
from haven_scenarios.study.questionnaires import BUILTINS, check_answers, in_order, item_order, resolve, score

CONDITIONS = [("none", ["none"]), ("signals", ["turn_signals"]), ("all", ["all"])]


def test_nars_has_the_published_14_items_3_subscales_and_reverses_s3_only() -> None:
    assert len(NARS.items) == 14 and (NARS.minimum, NARS.maximum) == (1, 5)
    scales = dict(NARS.scales)
    number = lambda ids: sorted(int(i.split("_")[1]) for i in ids)  # noqa: E731
    assert number(scales["s1_interaction"]) == [4, 7, 8, 9, 10, 12]
    assert number(scales["s2_social_influence"]) == [1, 2, 11, 13, 14]
    assert number(scales["s3_emotions"]) == [3, 5, 6]
    assert sorted(int(i.id.split("_")[1]) for i in NARS.items if i.reverse) == [3, 5, 6]
    assert NARS.items[2].text == "I would feel relaxed talking with robots."  # item 3 (S3)
    assert "Nomura" in NARS.source and "2006" in NARS.source
    # Published scoring: each subscale the sum of its items, S3 turned round (6 - answer).
    all_ones = {i.id: 1 for i in NARS.items}
    assert score(NARS, all_ones) == {
        "nars_s1_interaction": 6.0,
        "nars_s2_social_influence": 5.0,
        "nars_s3_emotions": 15.0,
    }
    mixed = {**all_ones, "nars_3": 2, "nars_5": 4, "nars_6": 5, "nars_7": 5, "nars_13": 3}
    assert score(NARS, mixed) == {
        "nars_s1_interaction": 10.0,
        "nars_s2_social_influence": 7.0,
        "nars_s3_emotions": 4 + 2 + 1,
    }


def test_a_ranking_takes_each_rank_once() -> None:
    q = preference(CONDITIONS)
    assert [i.id for i in q.items] == ["none", "signals", "all"] and (q.minimum, q.maximum) == (1, 3)
    assert score(q, check_answers(q, {"none": 3, "signals": 1, "all": 2})) == {
        "preference_none": 3,
        "preference_signals": 1,
        "preference_all": 2,
    }
    with pytest.raises(ValueError, match=r"preference: every item needs a different answer \(each of 1\.\.3 once\)"):
        check_answers(q, {"none": 1, "signals": 1, "all": 2})
    with pytest.raises(ValueError, match=r"preference\.all: must be one of 1\.\.3"):
        check_answers(q, {"none": 1, "signals": 2, "all": 4})


def test_demographics_take_an_option_each_and_optional_text() -> None:
    answers = {"age": 2, "gender": 4, "gender_self": " agender ", "robots": 1, "vr": 2, "games": 5}
    assert check_answers(DEMOGRAPHICS, answers)["gender_self"] == "agender"
    assert check_answers(DEMOGRAPHICS, {k: v for k, v in answers.items() if k != "gender_self"})["gender_self"] == ""
    gender = next(i for i in DEMOGRAPHICS.items if i.id == "gender")
    assert gender.options[-1] == "Prefer not to say" and "self-describe" in gender.options[3]
    with pytest.raises(ValueError, match=r"demographics\.age: must be one of 1\.\.7"):
        check_answers(DEMOGRAPHICS, {**answers, "age": 8})
    with pytest.raises(ValueError, match=r"demographics\.gender_self: must be one line of text"):
        check_answers(DEMOGRAPHICS, {**answers, "gender_self": "x" * 101})
    assert score(DEMOGRAPHICS, answers) == {}


def test_shuffled_items_are_seeded_per_key_keep_their_prompt_and_score_the_same() -> None:
    (g,) = resolve([{"name": "godspeed", "shuffle": True}], "q")
    published = [i.id for i in BUILTINS["godspeed"].items]
    first, again, other = item_order(g, "s1/h1"), item_order(g, "s1/h1"), item_order(g, "s2/h1")
    assert first == again and first != other and sorted(first) == sorted(published) and list(first) != published
    assert [i.split("_")[0] for i in first[-3:]] == ["safety"] * 3  # the safety items stay under their own prompt
    assert item_order(BUILTINS["godspeed"], "s1/h1") == tuple(published)  # without shuffle: as published
    answers = {i: k % 5 + 1 for k, i in enumerate(published)}
    assert score(in_order(g, first), answers) == score(BUILTINS["godspeed"], answers)
    with pytest.raises(ValueError, match=r"q\[0\]\.shuffle"):
        resolve([{"name": "godspeed", "shuffle": "often"}], "q")


def study_yaml(tmp_path: Path, **extra: object) -> Path:
    data = {
        "name": "s",
        "scenarios": ["hallway"],
        "conditions": {"none": ["none"], "all": ["all"]},
        "participants": 2,
        **extra,
    }
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def test_a_study_file_names_consent_and_the_instruments_before_and_after(tmp_path: Path) -> None:
    (tmp_path / "consent.md").write_text("You will walk past a robot.\n\nYou may stop at any time.\n")
    study = load_study(
        study_yaml(
            tmp_path, consent={"file": "consent.md"}, before_study=["demographics", "nars"], after_study=["preference"]
        )
    )
    inst = study.instruments()
    assert (
        inst.consent is not None
        and inst.consent.instructions.startswith("You will walk past")
        and "stop at any time" in inst.consent.instructions
    )
    assert [q.name for q in inst.first] == ["consent", "demographics", "nars"] and [q.name for q in inst.after] == [
        "preference"
    ]
    assert [i.id for i in inst.after[0].items] == ["none", "all"]
    assert not load_study(study_yaml(tmp_path)).instruments()


@pytest.mark.parametrize(
    "extra, message",
    [
        ({"consent": {"text": "x", "file": "y"}}, "consent: give either text or file"),
        ({"consent": {"file": "missing.md"}}, "consent.file: .*missing.md is not a readable regular file"),
        ({"consent": {"file": "/dev/zero"}}, "consent.file: /dev/zero is not a readable regular file"),
        ({"consent": {"text": "x" * 20_001}}, r"consent: the text must be 1\.\.20000 characters"),
        ({"consent": {"txt": "x"}}, "consent.txt: unknown key"),
        ({"before_study": ["nars", "nars"]}, "named twice"),
        ({"before_study": ["narz"]}, r"before_study\[0\]: unknown questionnaire 'narz'"),
        ({"after_study": ["preference", "preference"]}, "after_study: a questionnaire is named twice"),
    ],
)
def test_bad_instrument_keys_are_one_line_errors(tmp_path: Path, extra: dict[str, object], message: str) -> None:
    with pytest.raises(StudyError, match=message) as e:
        load_study(study_yaml(tmp_path, **extra))
    assert "\n" not in str(e.value) and "study.yaml" in str(e.value)


def lines(*answers: str):  # type: ignore[no-untyped-def]
    it = iter(answers)
    shown: list[str] = []

    def read(prompt: str) -> str:
        shown.append(prompt)
        return next(it)

    return read, shown


def test_terminal_answers_are_stored_with_their_order_and_consent_no_stops_the_rest(tmp_path: Path) -> None:
    study = parse_study(
        {"name": "s", "scenarios": ["hallway"], "conditions": {"none": ["none"], "all": ["all"]}, "participants": 2,
         "consent": {"text": "Walk past a robot."}, "before_study": [{"name": "nars", "shuffle": True}],
         "after_study": ["preference"]},
        "study.yaml",
    )  # fmt: skip
    inst = study.instruments()
    # p01 agrees, mistypes one NARS answer (asked again), answers 1 to everything; the ranking once twice-ranked, then
    # right.
    read, shown = lines("1", *["9", "1"], *["1"] * 13)
    book = InstrumentBook(tmp_path, "p01")
    said: list[str] = []
    assert run_instruments(book, inst.first, "s/p01/study", terminal_asker(read, said.append))
    assert any("please type one of 1..5" in s for s in said) and any("Nomura" in s for s in said)
    data = json.loads((tmp_path / "p01" / "instruments.json").read_text())
    assert (
        data["consent"]["agreed"] is True
        and data["consent"]["answers"] == {"agree": 1}
        and data["consent"]["text"] == "Walk past a robot."
    )
    assert data["nars"]["scores"] == {
        "nars_s1_interaction": 6.0,
        "nars_s2_social_influence": 5.0,
        "nars_s3_emotions": 15.0,
    }
    assert sorted(data["nars"]["order"]) == sorted(i.id for i in NARS.items) and data["nars"]["order"] != [
        i.id for i in NARS.items
    ]
    # asked in the stored order
    assert f"1/14 {NARS.items[int(data['nars']['order'][0].split('_')[1]) - 1].text}" in shown[1]
    read, _ = lines("1", "1", "2", "1")
    assert run_instruments(book, inst.after, "s/p01/study", terminal_asker(read, said.append))
    assert "Each of 1..2 once, please: again." in said
    assert json.loads(book.path.read_text())["preference"]["scores"] == {"preference_none": 2.0, "preference_all": 1.0}

    read, _ = lines("2")  # p02 declines: nothing more is asked
    other = InstrumentBook(tmp_path, "p02")
    assert not run_instruments(other, inst.first, "s/p02/study", terminal_asker(read, said.append))
    assert other.declined() and set(json.loads(other.path.read_text())) == {"consent"}

    rows = {r["participant"]: r for r in participant_rows(tmp_path, ["p01", "p02"], inst)}
    assert (
        rows["p01"]["consent"] == "yes"
        and rows["p01"]["nars_s3_emotions"] == 15.0
        and rows["p01"]["preference_all"] == 1.0
    )
    assert rows["p02"]["consent"] == "no" and rows["p02"]["nars_s1_interaction"] == ""
    write_participants(tmp_path / "report", tmp_path, ["p01", "p02"], inst)
    with open(tmp_path / "report" / "participants.csv") as f:
        table = list(csv.DictReader(f))
    assert [r["consent"] for r in table] == ["yes", "no"] and table[0]["nars_s1_interaction"] == "6.0"
    book_rows = {r[0]: r for r in codebook_rows(inst)}
    assert set(book_rows) == set(table[0]) and book_rows["nars_s1_interaction"][1] == "points 6-30"
    assert (
        "reverse-scored (1+5-answer): nars_3, nars_5, nars_6" in book_rows["nars_s3_emotions"][2]
        and "Nomura" in book_rows["nars_s3_emotions"][3]
    )


def test_a_batch_pilot_records_not_asked_instead_of_answers(tmp_path: Path) -> None:
    inst = parse_study(
        {"name": "s", "scenarios": ["hallway"], "conditions": {"none": ["none"], "all": ["all"]}, "participants": 1,
         "consent": {"text": "ok"}, "before_study": ["demographics"], "after_study": ["preference"]},
        "study.yaml",
    ).instruments()  # fmt: skip
    book = InstrumentBook(tmp_path, "p01")
    assert run_instruments(book, (*inst.first, *inst.after), "k", None)
    assert json.loads(book.path.read_text()) == {
        n: {"not_asked": BATCH_REASON} for n in ("consent", "demographics", "preference")
    }
    (row,) = participant_rows(tmp_path, ["p01"], inst)
    assert row["consent"] == "not asked" and row["demographics_age"] == "" and row["preference_all"] == ""
    assert row["not_asked"] == "consent demographics preference"
    assert consent("x").items[0].options[0].startswith("Yes")


@pytest.mark.integration
def test_haven_study_run_asks_at_the_terminal_before_the_first_trial_and_after_the_last(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """`haven study run STUDY --participant P` with a person at the terminal (the ROS trials swapped
    for batch trials to keep it fast): p01 declines and runs no trial; p02 agrees, answers
    demographics and NARS, does both trials, then ranks the conditions; the report has
    participants.csv. A `--batch` pilot's p03 is asked nothing and stored as not asked."""
    from haven_scenarios.conduct import study_run
    from haven_scenarios.tools.cli import main

    data = {
        "name": "s", "scenarios": ["shared_room"], "conditions": {"none": ["none"], "all": ["all"]}, "participants": 3,
        "counterbalancing": "none", "consent": {"text": "You will walk past a robot."},
        "before_study": ["demographics", "nars"], "after_study": ["preference"],
    }  # fmt: skip
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    study = load_study(path)
    ran: list[str] = []

    def batch_instead(args, trial, sessions, questionnaires, name):  # type: ignore[no-untyped-def]
        ran.append(f"{args.participant}/{trial.trial_id}")
        return study_run.run_batch_trial(args, trial, sessions, study)

    monkeypatch.setattr(study_run, "run_recorded_trial", batch_instead)
    root = tmp_path / "out"
    answers = iter(["2"])
    monkeypatch.setattr("builtins.input", lambda prompt="": next(answers))
    assert main(["study", "run", str(path), "--participant", "p01", "--dir", str(root)]) == 0
    assert ran == [] and "p01 did not agree to take part: no trial is run" in capsys.readouterr().err
    # (asked once)
    assert main(["study", "run", str(path), "--participant", "p01", "--dir", str(root)]) == 0 and ran == []

    demographics = ["3", "2", "", "1", "2", "5"]
    answers = iter(["1", *demographics, *["2"] * 14, "2", "1"])
    assert main(["study", "run", str(path), "--participant", "p02", "--dir", str(root)]) == 0
    assert ran == ["p02/shared_room-none", "p02/shared_room-all"]
    assert next(answers, None) is None  # every answer was asked for
    stored = json.loads((root / "p02" / "instruments.json").read_text())
    assert list(stored) == ["consent", "demographics", "nars", "preference"]
    assert stored["preference"]["scores"] == {"preference_none": 2.0, "preference_all": 1.0}

    assert main(["study", "run", str(path), "--participant", "p03", "--dir", str(root), "--batch"]) == 0
    assert set(json.loads((root / "p03" / "instruments.json").read_text())["nars"]) == {"not_asked"}

    capsys.readouterr()
    assert main(["study", "report", str(path), "--dir", str(root)]) == 0
    assert (
        "participants.csv: consent: 1 yes, 1 no, 1 not asked; demographics: 1/3 answered; nars: 1/3 answered"
        in capsys.readouterr().out
    )
    with open(root / "report" / "participants.csv") as f:
        rows = {r["participant"]: r for r in csv.DictReader(f)}
    assert (
        rows["p02"]["demographics_age"] == "35-44"
        and rows["p02"]["demographics_gender"] == "Man"
        and rows["p02"]["demographics_games"].startswith("Every")
    )
    # 6 x 2; 3 x (6 - 2)
    assert rows["p02"]["nars_s1_interaction"] == "12.0" and rows["p02"]["nars_s3_emotions"] == "12.0"
    assert (
        rows["p01"]["consent"] == "no" and rows["p03"]["consent"] == "not asked" and rows["p03"]["preference_all"] == ""
    )
    assert rows["p03"]["not_asked"] == "consent demographics nars preference" and rows["p02"]["not_asked"] == ""


@pytest.mark.integration
def test_the_instruments_wait_ends_cleanly_on_ctrl_c_and_on_a_closed_terminal(tmp_path: Path) -> None:
    """`haven study run --web` waiting for the instruments page: Ctrl-C ends it (130) with one line,
    even started in the background (SIGINT ignored);
    at a terminal whose input is closed, it says so instead of waiting (130); nothing is stored."""
    import signal
    import subprocess
    import sys

    path = tmp_path / "study.yaml"
    path.write_text(
        yaml.safe_dump(
            {
                "name": "s",
                "scenarios": ["hallway"],
                "conditions": {"a": ["none"]},
                "participants": 1,
                "before_study": ["nars"],
            }
        )
    )
    argv = [
        sys.executable,
        "-m",
        "haven_scenarios",
        "study",
        "run",
        str(path),
        "--participant",
        "p01",
        "--dir",
        str(tmp_path / "out"),
    ]
    # Started as a shell starts a background job, with SIGINT ignored: Ctrl-C must end the wait all the same.
    background = lambda: signal.signal(signal.SIGINT, signal.SIG_IGN)  # noqa: E731
    web = subprocess.Popen(
        [*argv, "--web", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        preexec_fn=background,
    )
    try:
        assert "web: participant p01 (before the first trial: nars): http://" in web.stdout.readline()  # type: ignore[union-attr]
        web.send_signal(signal.SIGINT)
        assert web.wait(timeout=60) == 130
        assert "stopped while asking p01; the same command asks what is missing" in web.stdout.read()  # type: ignore[union-attr]
    finally:
        if web.poll() is None:
            web.kill()
            web.wait()
    closed = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    assert closed.returncode == 130 and "no answers for p01 at the terminal (its input is closed)" in closed.stderr
    assert not (tmp_path / "out" / "p01" / "instruments.json").exists()
