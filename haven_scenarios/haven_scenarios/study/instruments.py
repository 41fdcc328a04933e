"""The instruments before and after a whole study (not after each trial): consent, demographics,
the Negative Attitudes toward Robots Scale, and a ranking of the conditions.

A study file names them (study/protocol.py):

```yaml
consent: {text: "You will walk past a robot in a virtual hallway ..."}   # or {file: consent.md}
before_study: [demographics, nars]      # registered questionnaires or Likert mappings, in order
after_study: [preference]               # `preference`: each condition ranked once, 1 = liked best
```

Consent is asked first; a participant who does not agree runs no trial. Each is a `Questionnaire`
(study/questionnaires.py), so the terminal and the participant's page ask them as they ask the
per-trial ones, and `answers_record` checks and scores them:

  * `nars` (Nomura, Kanda, Suzuki & Kato 2006, "Measurement of negative attitudes toward robots",
    Interaction Studies 7(3):437-454; English items as in Syrdal, Dautenhahn, Koay & Walters 2009,
    AISB'09 symposium on new frontiers in HRI): 14 statements, 5 points (1 strongly disagree .. 5
    strongly agree), three subscales scored as the sum of their items as published: S1 situations
    of interaction with robots (items 4, 7, 8, 9, 10, 12; 6..30), S2 social influence of robots
    (1, 2, 11, 13, 14; 5..25), S3 emotions in interaction with robots (3, 5, 6, reverse-scored; 3..15).
  * `demographics` (ours): age band, gender (the inclusive form Spiel, Haimson & Lottridge 2019
    recommend, "How to do better with gender on surveys", ACM Interactions 26(4):62-65: woman, man,
    non-binary, self-describe with a text field, prefer not to say), and how often the participant
    uses robots, VR headsets and video games (frequency bands, ours). Not scored.
  * `preference`: made from the study's conditions; its scores are each condition's rank.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from haven_scenarios.study.questionnaires import CHOICE, TEXT, Item, Questionnaire

NARS_SOURCE = "Nomura, Kanda, Suzuki & Kato (2006), Interaction Studies 7(3):437-454"
NARS_ITEMS = (  # (published number, statement, subscale); reversed: S3
    (1, "I would feel uneasy if robots really had emotions.", "s2"),
    (2, "Something bad might happen if robots developed into living beings.", "s2"),
    (3, "I would feel relaxed talking with robots.", "s3"),
    (4, "I would feel uneasy if I was given a job where I had to use robots.", "s1"),
    (5, "If robots had emotions, I would be able to make friends with them.", "s3"),
    (6, "I feel comforted being with robots that have emotions.", "s3"),
    (7, 'The word "robot" means nothing to me.', "s1"),
    (8, "I would feel nervous operating a robot in front of other people.", "s1"),
    (9, "I would hate the idea that robots or artificial intelligences were making judgements about things.", "s1"),
    (10, "I would feel very nervous just standing in front of a robot.", "s1"),
    (11, "I feel that if I depend on robots too much, something bad might happen.", "s2"),
    (12, "I would feel paranoid talking with a robot.", "s1"),
    (13, "I am concerned that robots would be a bad influence on children.", "s2"),
    (14, "I feel that in the future society will be dominated by robots.", "s2"),
)
NARS_SUBSCALES = {"s1": "s1_interaction", "s2": "s2_social_influence", "s3": "s3_emotions"}
NARS_REVERSED = "s3"


def _nars() -> Questionnaire:
    items = tuple(
        Item(f"nars_{n}", text, "Strongly disagree", "Strongly agree", reverse=s == NARS_REVERSED)
        for n, text, s in NARS_ITEMS
    )
    scales = tuple(
        (name, tuple(f"nars_{n}" for n, _, s in NARS_ITEMS if s == key)) for key, name in NARS_SUBSCALES.items()
    )
    text = (
        "How much do you agree with each statement? (1 strongly disagree, "
        "2 disagree, 3 undecided, 4 agree, 5 strongly agree)"
    )
    return Questionnaire(
        "nars", "Attitudes towards robots", text, 1, 5, 1, items, scales, source=NARS_SOURCE, scoring="sum"
    )


PREFER_NOT = "Prefer not to say"
FREQUENCY = ("Never", "Less than once a month", "About once a month", "About once a week", "Every day or nearly")
GENDER_SOURCE = "gender item: Spiel, Haimson & Lottridge (2019), ACM Interactions 26(4):62-65; the other items ours"


def _demographics() -> Questionnaire:
    def choice(id: str, text: str, options: Sequence[str]) -> Item:
        return Item(id, text, "", "", kind=CHOICE, options=tuple(options))

    items = (
        choice("age", "How old are you?", ("18-24", "25-34", "35-44", "45-54", "55-64", "65 or older", PREFER_NOT)),
        choice(
            "gender",
            "What is your gender?",
            ("Woman", "Man", "Non-binary", "I prefer to self-describe (below)", PREFER_NOT),
        ),
        Item("gender_self", "If you prefer to self-describe your gender: (optional)", "", "", kind=TEXT),
        choice("robots", "How often do you use or work with robots (for example a robot vacuum cleaner)?", FREQUENCY),
        choice("vr", "How often do you use a virtual-reality headset?", FREQUENCY),
        choice("games", "How often do you play video games?", FREQUENCY),
    )
    return Questionnaire(
        "demographics",
        "About you",
        "Please answer a few questions about yourself.",
        1,
        1,
        1,
        items,
        (),
        source=GENDER_SOURCE,
    )


NARS, DEMOGRAPHICS = _nars(), _demographics()  # registered as plugins in pyproject.toml, beside nasa_tlx and godspeed

CONSENT = "consent"
AGREE, DECLINE = "Yes, I agree to take part", "No, I do not agree"
PREFERENCE = "preference"


def consent(text: str) -> Questionnaire:
    """The study's consent text and one question: the answer 1 is agreement."""
    item = Item("agree", "Do you agree to take part in this study?", "", "", kind=CHOICE, options=(AGREE, DECLINE))
    return Questionnaire(CONSENT, "Consent to take part", text, 1, 1, 1, (item,), ())


def agreed(answers: dict[str, object]) -> bool:
    return answers.get("agree") == 1


def preference(conditions: Sequence[tuple[str, Sequence[str]]]) -> Questionnaire:
    """Rank each condition (name, its cues) once, 1 = liked best; the scores are the ranks."""
    n = len(conditions)

    def label(name: str, cues: Sequence[str]) -> str:
        return f"{name.replace('_', ' ')} ({', '.join(c.replace('_', ' ') for c in cues)})"

    items = tuple(Item(name, label(name, cues), "liked best", "liked least") for name, cues in conditions)
    text = (
        f"You saw the robot with {n} different cue settings. Rank them: "
        f"1 for the one you liked best, {n} for the one you liked least, "
    )
    text += "each number once."
    return Questionnaire(
        PREFERENCE,
        "Which did you like best?",
        text,
        1,
        n,
        1,
        items,
        tuple((i.id, (i.id,)) for i in items),
        distinct=True,
    )


@dataclass(frozen=True)
class StudyInstruments:
    """What a study asks before its first trial (consent first) and after its last."""

    consent: Questionnaire | None = None
    before: tuple[Questionnaire, ...] = ()
    after: tuple[Questionnaire, ...] = ()

    @property
    def first(self) -> tuple[Questionnaire, ...]:
        return ((self.consent,) if self.consent else ()) + self.before

    def __bool__(self) -> bool:
        return bool(self.first or self.after)


def read_text(path: Path, max_bytes: int) -> str:
    """A small text file a study names (a consent text, an allow-list of ids, a link secret), read
    when the study is loaded (so a study runs with what it said); ValueError (one line) when it is
    not a readable regular file of UTF-8 within `max_bytes`."""
    if not path.is_file():  # (not a FIFO or a device, which would block or never end)
        raise ValueError(f"{path} is not a readable regular file")
    try:
        with path.open("rb") as f:
            raw = f.read(max_bytes + 1)
        if len(raw) > max_bytes:
            raise ValueError(f"{path} is longer than {max_bytes} bytes")
        return raw.decode("utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise ValueError(f"cannot read {path}: {getattr(e, 'strerror', None) or e}") from None
