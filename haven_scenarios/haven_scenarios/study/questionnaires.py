"""Questionnaires: the built-ins, a study's own Likert items, checking and scoring answers.

Built-ins:
  * `nasa_tlx`: the NASA Task Load Index, raw (unweighted) form: six subscales rated 0-100 in steps
    of 5 (the paper form's 21 marks); the raw TLX is their mean (Hart & Staveland 1988; Hart 2006,
    "NASA-TLX: 20 years later", on dropping the pairwise weighting). Performance runs from
    "Perfect" (0) to "Failure" (100), so higher is more load on every subscale.
  * `godspeed`: the Godspeed series (Bartneck, Kulic, Croft & Zoghbi 2009): 5-point semantic
    differentials for anthropomorphism, animacy, likeability, perceived intelligence and perceived
    safety, asked as published (perceived safety about the participant's own emotional state, the
    others about the robot) and scored as published: each series is the mean of its items, none
    reversed, so scores compare with other papers' (International Journal of Social Robotics 1:71-81).

  * `nars` and `demographics` (study/instruments.py), asked before a study.

Each carries its citation (`source`), which the page shows under its title. Items can be mixed
(`shuffle`; `item_order`): a Likert mapping's `shuffle: true`, or `{name: godspeed, shuffle: true}`
for a registered one; the order is seeded per participant and trial and stored with the answers.

A study adds its own Likert questionnaire as a mapping (in the study file, or a YAML file named on
`haven run --questionnaire`):

```yaml
name: legibility                 # [A-Za-z0-9_]+, the score's column name
title: About the robot           # shown above the items (default: the name)
points: 7                        # 2..11 answer points, 1..points
anchors: [Strongly disagree, Strongly agree]
items:
  - {id: side, text: "I could tell which way the robot would pass me."}
  - {id: surprise, text: "The robot surprised me.", reverse: true}
```

A lab's package adds questionnaires any study can name as plugins (entry point group
`haven.questionnaires`, docs: Your own plugins): a `Questionnaire`, or a Likert mapping as above;
the two built-ins are registered the same way.

Answers are integers keyed by item id; `score` gives one number per scale, named
`<questionnaire>_<scale>` (`nasa_tlx_raw`, `nasa_tlx_mental`, ..., `godspeed_likeability`, or the
custom questionnaire's own name). `ANSWERS_FILE` in a session folder holds, per person, each
questionnaire's answers and scores (`answers_record`).
"""

from __future__ import annotations

import hashlib
import itertools
import random
import re
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, replace
from typing import Annotated, Any

from pydantic import Field, ValidationError

from haven_sim.common import plugins
from haven_sim.common.schema import FileModel, Whole, checked, listing, problem
from haven_sim.common.yaml_file import short

ANSWERS_FILE = "questionnaires.json"
NAME = re.compile(r"[A-Za-z0-9_]{1,40}")
MAX_ITEMS = 100
MAX_TEXT = 300


# an item's kind: a rating, one of its options (1..n), optional free text
SCALE, CHOICE, TEXT = "scale", "choice", "text"
MAX_ANSWER_TEXT = 100  # a free-text answer (e.g. a self-described gender)


@dataclass(frozen=True)
class Item:
    id: str
    text: str  # the question, or for a semantic differential the scale's low end
    low: str  # the anchor at the scale's low end
    high: str  # ... and at its high end
    reverse: bool = False  # scored as (min + max - answer)
    # the instruction the page shows above this item and those after it, until another ("": the questionnaire's)
    prompt: str = ""
    kind: str = SCALE
    options: tuple[str, ...] = ()  # CHOICE: the answer k means options[k - 1]


@dataclass(frozen=True)
class Questionnaire:
    """One questionnaire as the participant page shows it: answers run from `minimum` to `maximum` in steps of
    `step`."""

    name: str
    title: str
    instructions: str
    minimum: int
    maximum: int
    step: int
    items: tuple[Item, ...]
    scales: tuple[tuple[str, tuple[str, ...]], ...]  # (scale name, its item ids): scored as means
    differential: bool = False  # semantic differentials: each item is a row between its own two labels
    source: str = ""  # the citation the page shows with it ("" for a study's own)
    shuffle: bool = False  # items in a seeded order per participant and trial (`item_order`)
    scoring: str = "mean"  # a scale's score: the "mean" or the "sum" of its items (as its authors publish)
    distinct: bool = False  # every item answered differently (a ranking: each rank once)

    def to_dict(self) -> dict[str, Any]:
        """As the web node hands it to the page (JSON)."""
        d = asdict(self)
        d["scales"] = {name: list(ids) for name, ids in self.scales}
        return d


def _tlx() -> Questionnaire:
    subscales = (
        ("mental", "Mental demand: how mentally demanding was the task?", "Very low", "Very high"),
        ("physical", "Physical demand: how physically demanding was the task?", "Very low", "Very high"),
        ("temporal", "Temporal demand: how hurried or rushed was the pace of the task?", "Very low", "Very high"),
        (
            "performance",
            "Performance: how successful were you in accomplishing what you were asked to do?",
            "Perfect",
            "Failure",
        ),
        (
            "effort",
            "Effort: how hard did you have to work to accomplish your level of performance?",
            "Very low",
            "Very high",
        ),
        (
            "frustration",
            "Frustration: how insecure, discouraged, irritated, stressed and annoyed were you?",
            "Very low",
            "Very high",
        ),
    )
    items = tuple(Item(i, text, low, high) for i, text, low, high in subscales)
    scales = (("raw", tuple(i.id for i in items)), *((i.id, (i.id,)) for i in items))
    source = "Hart & Staveland (1988), NASA Task Load Index; raw (unweighted) TLX: Hart (2006)"
    return Questionnaire(
        "nasa_tlx",
        "NASA Task Load Index",
        "Rate the trial you just did on each scale.",
        0,
        100,
        5,
        items,
        scales,
        source=source,
    )


GODSPEED_SERIES: dict[str, tuple[tuple[str, str], ...]] = {
    "anthropomorphism": (("Fake", "Natural"), ("Machinelike", "Humanlike"), ("Unconscious", "Conscious"),
                         ("Artificial", "Lifelike"), ("Moving rigidly", "Moving elegantly")),
    "animacy": (("Dead", "Alive"), ("Stagnant", "Lively"), ("Mechanical", "Organic"), ("Artificial", "Lifelike"),
                ("Inert", "Interactive"), ("Apathetic", "Responsive")),
    "likeability": (("Dislike", "Like"), ("Unfriendly", "Friendly"), ("Unkind", "Kind"), ("Unpleasant", "Pleasant"),
                    ("Awful", "Nice")),
    "intelligence": (("Incompetent", "Competent"), ("Ignorant", "Knowledgeable"), ("Irresponsible", "Responsible"),
                     ("Unintelligent", "Intelligent"), ("Foolish", "Sensible")),
    "safety": (("Anxious", "Relaxed"), ("Agitated", "Calm"), ("Quiescent", "Surprised")),
}  # fmt: skip
# The published instructions (Bartneck et al. 2009, the questionnaire's appendix): the first four
# series rate the robot, perceived safety the participant's own emotional state. The published
# scoring reverses no item: each series is the mean of its items as printed (so for perceived
# safety "Quiescent - Surprised" runs as printed).
GODSPEED_PROMPTS = {
    "safety": "Please rate your emotional state on these scales.",
}
GODSPEED_IMPRESSION = "Please rate your impression of the robot on these scales."
GODSPEED_SOURCE = "Bartneck, Kulić, Croft & Zoghbi (2009), Int. J. Social Robotics 1:71-81"


def _godspeed() -> Questionnaire:
    items: list[Item] = []
    scales: list[tuple[str, tuple[str, ...]]] = []
    for series, pairs in GODSPEED_SERIES.items():
        ids = tuple(f"{series}_{k + 1}" for k in range(len(pairs)))
        prompt = GODSPEED_PROMPTS.get(series, GODSPEED_IMPRESSION)
        items += [
            Item(i, f"{low} - {high}", low, high, prompt=prompt) for i, (low, high) in zip(ids, pairs, strict=True)
        ]
        scales.append((series, ids))
    text = "Rate each pair on the scale between its two words."
    return Questionnaire(
        "godspeed",
        "Godspeed questionnaire",
        text,
        1,
        5,
        1,
        tuple(items),
        tuple(scales),
        differential=True,
        source=GODSPEED_SOURCE,
    )


NASA_TLX, GODSPEED = _tlx(), _godspeed()
# ours, registered as plugins in pyproject.toml
BUILTINS: dict[str, Questionnaire] = {q.name: q for q in (NASA_TLX, GODSPEED)}


def accept_plugin(name: str, value: Any) -> Questionnaire:
    """A `haven.questionnaires` plugin (haven_sim/common/plugins.py): a Questionnaire, or a mapping
    of Likert items as a study file writes one; it takes the name it is registered under."""
    if isinstance(value, Questionnaire):
        return replace(value, name=name)
    if isinstance(value, Mapping):
        return likert({**value, "name": name}, f"questionnaire {name}:", registered=False)
    raise ValueError("is neither a Questionnaire nor a mapping of Likert items (title, points, anchors, items)")


def registered() -> dict[str, Questionnaire]:
    """Every questionnaire a study can name: ours and the plugins' (kind `questionnaires`)."""
    return {p.name: p.value for p in plugins.registry("questionnaires")}


def _text(limit: int) -> Any:
    """One line of text of at most `limit` characters, stripped (a YAML Yes, No or 5 is refused)."""

    def check(value: Any) -> str:
        if isinstance(value, (bool, int, float)):  # YAML reads Yes, No, On, Off as booleans, 5 as a number
            words = (
                "YAML reads Yes, No, On and Off as true or false"
                if isinstance(value, bool)
                else "YAML reads it as a number"
            )
            raise ValueError(f'must be text, got {short(value)} ({words}: put the words in quotes, e.g. "No")')
        if not isinstance(value, str) or not value.strip() or len(value) > limit or "\n" in value.strip():
            raise ValueError(f"must be one line of text (at most {limit} characters)")
        return value.strip()

    return Annotated[str, checked(check)]


def _name(value: Any) -> Any:
    if not isinstance(value, str) or not NAME.fullmatch(value):
        raise ValueError(f"must be a name of letters, digits and _ (at most 40), got {str(value)[:50]!r}")
    return value


def _anchors(value: Any) -> Any:
    if not isinstance(value, list) or len(value) != 2:
        raise ValueError("must be a list of two labels [low, high]")
    return value


Name = Annotated[str, checked(_name)]


class LikertItem(FileModel):
    id: Name
    text: _text(MAX_TEXT)  # type: ignore[valid-type]
    reverse: bool = False


class LikertFile(FileModel):
    """A study's own Likert questionnaire (the module docstring shows one)."""

    name: Name
    title: _text(80) | None = None  # type: ignore[valid-type]
    instructions: _text(MAX_TEXT) = "How much do you agree with each statement?"  # type: ignore[valid-type]
    points: Whole(2, 11) = 7  # type: ignore[valid-type]
    anchors: Annotated[list[_text(60)], checked(_anchors)] = ["Strongly disagree", "Strongly agree"]  # type: ignore[valid-type]  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    items: Annotated[list[LikertItem], listing(f"a list of 1..{MAX_ITEMS} items"), Field(max_length=MAX_ITEMS)]
    shuffle: bool = False  # items in a seeded order per participant and trial


class Mixed(FileModel):
    """A registered questionnaire with its items mixed: `{name: godspeed, shuffle: true}`."""

    name: Name
    shuffle: bool


def _at(where: str, key: str) -> str:
    """A key's place: `where.key`, or `file.yaml: key` when `where` is a file's label ending in ':'."""
    return f"{where} {key}" if where.endswith(":") else f"{where}.{key}"


def likert(spec: Mapping[str, Any], where: str, registered: bool = True) -> Questionnaire:
    """A study's own Likert questionnaire from its mapping (see the module docstring); ValueError
    with one line naming `where` (a key path, or a file's label ending in ':') and the key.
    `registered`: its name may not be one a plugin has (a study's own must be told apart)."""
    try:
        f = LikertFile.model_validate(spec)
    except ValidationError as e:
        raise ValueError(_at(where, problem(LikertFile, e))) from None
    if registered and f.name in plugins.registry("questionnaires"):
        raise ValueError(
            f"{_at(where, 'name')}: {f.name!r} is a registered questionnaire (haven plugins); name yours otherwise"
        )
    low, high = f.anchors
    items = tuple(Item(i.id, i.text, low, high, i.reverse) for i in f.items)
    ids = [i.id for i in items]
    if len(set(ids)) != len(ids):
        raise ValueError(f"{_at(where, 'items')}: item ids must differ")
    return Questionnaire(
        f.name, f.title or f.name, f.instructions, 1, f.points, 1, items, ((f.name, tuple(ids)),), shuffle=f.shuffle
    )


def resolve(specs: Sequence[Any], where: str) -> tuple[Questionnaire, ...]:
    """Built-in names and Likert mappings, in order; ValueError (one line) on anything else."""
    out: list[Questionnaire] = []
    for k, spec in enumerate(specs):
        at = f"{where}[{k}]"
        if isinstance(spec, str):
            known = registered()
            if spec in plugins.registry("questionnaires").left_out:
                raise ValueError(f"{at}: {plugins.registry('questionnaires').unknown(spec)}")
            if spec not in known:
                raise ValueError(
                    f"{at}: unknown questionnaire {spec[:50]!r} (registered: "
                    f"{', '.join(known)}, or a mapping of Likert items)"
                )
            out.append(known[spec])
        elif isinstance(spec, dict):
            out.append(from_mapping(spec, at))
        else:
            raise ValueError(f"{at}: must be a registered questionnaire's name or a mapping of Likert items")
    names = [q.name for q in out]
    if len(set(names)) != len(names):
        raise ValueError(f"{where}: a questionnaire is named twice")
    return tuple(out)


def from_mapping(spec: Mapping[str, Any], where: str) -> Questionnaire:
    """A Likert mapping, or a registered questionnaire's name with `shuffle` (`{name: godspeed, shuffle: true}`)."""
    if set(spec) == {"name", "shuffle"} and spec["name"] in registered():
        return mixed(spec, where)
    return likert(spec, where)


def mixed(spec: Mapping[str, Any], where: str) -> Questionnaire:
    """A registered questionnaire with `shuffle` set (`{name: godspeed, shuffle: true}`)."""
    try:
        f = Mixed.model_validate(spec)
    except ValidationError as e:
        raise ValueError(_at(where, problem(Mixed, e))) from None
    return replace(registered()[f.name], shuffle=f.shuffle)


def item_order(q: Questionnaire, key: str) -> tuple[str, ...]:
    """The order the page shows the items in: as listed, or with `shuffle` a random order seeded by
    `key` (participant and trial: the same key, the same order). Bartneck et al. (2009) suggest
    mixing the Godspeed items; items are mixed within each run of one prompt, so every item keeps
    its instruction (Godspeed's perceived safety stays after the robot's four series)."""
    if not q.shuffle:
        return tuple(i.id for i in q.items)
    rng = random.Random(int.from_bytes(hashlib.sha256(f"{key}/{q.name}".encode()).digest()[:8], "big"))
    out: list[str] = []
    for _, group in itertools.groupby(q.items, key=lambda i: i.prompt):
        ids = [i.id for i in group]
        rng.shuffle(ids)
        out += ids
    return tuple(out)


def trial_key(session: str, human: str) -> str:
    """What seeds the item order of a per-trial questionnaire: the session (one trial) and the person."""
    return f"{session}/{human}"


def in_order(q: Questionnaire, order: Sequence[str]) -> Questionnaire:
    """The questionnaire with its items in `order` (every item id once)."""
    by_id = {i.id: i for i in q.items}
    return replace(q, items=tuple(by_id[i] for i in order))


def _answer(q: Questionnaire, item: Item, v: Any) -> int | str:
    if item.kind == TEXT:
        v = "" if v is None else v
        if not isinstance(v, str) or len(v) > MAX_ANSWER_TEXT or "\n" in v:
            raise ValueError(
                f"{q.name}.{item.id}: must be one line of text "
                f"(at most {MAX_ANSWER_TEXT} characters), got {repr(v)[:30]}"
            )
        return v.strip()
    low, high, step = (1, len(item.options), 1) if item.kind == CHOICE else (q.minimum, q.maximum, q.step)
    if isinstance(v, bool) or not isinstance(v, int) or not low <= v <= high or (v - low) % step:
        raise ValueError(f"{q.name}.{item.id}: must be one of {low}..{high} in steps of {step}, got {repr(v)[:30]}")
    return v


def check_answers(q: Questionnaire, answers: Any) -> dict[str, Any]:
    """Every item answered with a value on its scale (a free-text item may be left empty; a
    ranking's items each differently); ValueError (one line) otherwise."""
    if not isinstance(answers, dict):
        raise ValueError(f"{q.name}: answers must be a mapping of item id to value")
    out = {item.id: _answer(q, item, answers.get(item.id)) for item in q.items}
    extra = sorted(set(answers) - set(out))
    if extra:
        raise ValueError(f"{q.name}: no item {str(extra[0])[:40]!r}")
    if q.distinct and len(set(out.values())) != len(out):
        raise ValueError(f"{q.name}: every item needs a different answer (each of {q.minimum}..{q.maximum} once)")
    return out


def score(q: Questionnaire, answers: Mapping[str, Any]) -> dict[str, float]:
    """One score per scale, the mean (or with `scoring: sum` the sum) of its items, reverse-scored
    items turned round; named `<questionnaire>_<scale>` (a custom questionnaire's single scale is
    named as the questionnaire)."""
    value = {
        i.id: (q.minimum + q.maximum - answers[i.id]) if i.reverse else answers[i.id]
        for i in q.items
        if i.kind == SCALE
    }
    out: dict[str, float] = {}
    for scale, ids in q.scales:
        key = q.name if scale == q.name else f"{q.name}_{scale}"
        total = sum(value[i] for i in ids)
        out[key] = round(float(total) if q.scoring == "sum" else total / len(ids), 4)
    return out


def codebook_rows(q: Questionnaire) -> list[tuple[str, str, str, str]]:
    """The scores `score` gives, as codebook rows (name, unit with the range, definition, source), for the report's
    codebook."""
    rows = []
    for scale, ids in q.scales:
        name = q.name if scale == q.name else f"{q.name}_{scale}"
        low, high = (q.minimum, q.maximum) if q.scoring == "mean" else (q.minimum * len(ids), q.maximum * len(ids))
        how = "rank (1 = liked best)" if q.distinct else f"{q.scoring} of items {', '.join(ids)}"
        turned = [i.id for i in q.items if i.id in ids and i.reverse]
        unit = f"rank {low}-{high}" if q.distinct else f"points {low}-{high}"
        turn = f"; reverse-scored ({q.minimum}+{q.maximum}-answer): {', '.join(turned)}" if turned else ""
        rows.append((name, unit, f"{q.title}: {how}{turn}", q.source))
    return rows


def answers_record(
    q: Questionnaire, answers: Any, answered_at: str, order: Sequence[str] | None = None
) -> dict[str, Any]:
    """What `ANSWERS_FILE` holds for one person's questionnaire: checked answers, scores, when, and
    the order the items were shown in (scores do not depend on it)."""
    checked = check_answers(q, answers)
    record = {"answers": checked, "scores": score(q, checked), "answered_at": answered_at}
    return record | ({"order": list(order)} if order is not None else {})
