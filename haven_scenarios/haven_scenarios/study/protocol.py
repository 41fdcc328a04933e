"""Study files: which scenarios and cue conditions, who takes part, how often, in which order.

```yaml
name: haven_paper                  # the study's folder: studies/<name>
scenarios: [hallway, shared_room]  # shipped names or scenario files (relative to this file)
conditions:                        # name: the cues shown (a list `haven run --condition` takes)
  none: [none]
  path_projection: [path_projection]
  all: [all]
participants: 8                    # a count (p01..p08) or a list of ids [p01, anna, ...]
repetitions: 1                     # each scenario x condition this often per participant
counterbalancing: williams         # conditions in each block: williams | latin | full | none (study/schedule.py)
blocks: williams                   # the scenario blocks' order: williams | latin | full | none
assignment: {policy: random, seed: 7}   # who takes which order: by_id (default) | random (seeded)
practice: {scenario: practice, cues: [none]}   # run first, flagged practice, left out of the statistics
seeds: {policy: per_participant, base: 0}   # fixed | per_participant | per_trial
questionnaires: [nasa_tlx, godspeed]        # after each trial: built-ins or Likert mappings
consent: {file: consent.md}        # before anything: {text: ...} or a text file (relative to this file)
before_study: [demographics, nars]  # before the first trial, after consent (study/instruments.py)
after_study: [preference]           # after the last trial: `preference` ranks the conditions
robots: [turtlebot2, turtlebot4]    # a design factor (default: the scenario's robot); robot_design: between | within
online: {completion_code: C1A2B3}   # `haven serve`: the landing page's text, the code or redirect at the end
                                    # (study/online.py)
```

Scenarios run as blocks, in the participant's counterbalanced block order (`blocks`), each showing
the conditions in the participant's counterbalanced order; `assignment` says who takes which order
(study/schedule.py); `robots`, the robot as a design factor (study/study_robots.py). Every key:
docs/reference/files.md. Errors name the file and the key in one line (`StudyError`).
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field

from haven_scenarios.study.conditions import SEED_MAX, condition_name, parse_condition
from haven_scenarios.study.instruments import PREFERENCE, StudyInstruments, consent, preference, read_text
from haven_scenarios.study.names import check_name
from haven_scenarios.study.online import Online, resolved
from haven_scenarios.study.questionnaires import Questionnaire, resolve
from haven_scenarios.study.scenario import ScenarioError, load_scenario
from haven_scenarios.study.study_robots import StudyRobot, parse_robots
from haven_sim.common.schema import FileModel, Whole, check, checked, listing, mapping
from haven_sim.common.yaml_file import file_label, read_yaml, short, shown_key

MAX_PARTICIPANTS = 999
MAX_REPETITIONS = 100
MAX_CONSENT_CHARS = 20_000  # a consent form of a few pages
MAX_CONDITIONS = 12  # `full` on more would be 12! orders


class StudyError(ValueError):
    """A study file is missing or invalid; the message is one line for the user."""


@dataclass(frozen=True)
class StudyScenario:
    spec: str  # as `haven run` takes it: a shipped name, or the file's absolute path
    name: str  # the scenario's own name


@dataclass(frozen=True)
class Condition:
    name: str
    cues: tuple[str, ...]  # as `haven run --condition` takes them


@dataclass(frozen=True)
class Practice:
    scenario: StudyScenario
    condition: Condition  # one of the study's, or the practice's own cues (named as `haven run` names them)
    own: bool = False  # given as cues, not as a study condition's name


@dataclass(frozen=True)
class Study:
    name: str
    scenarios: tuple[StudyScenario, ...]
    conditions: tuple[Condition, ...]
    participants: tuple[str, ...]
    repetitions: int = 1
    counterbalancing: str = "williams"
    practice: tuple[Practice, ...] = ()
    seed_policy: str = "per_participant"
    seed_base: int = 0
    questionnaires: tuple[Any, ...] = ()  # as written: built-in names and Likert mappings
    source: str = ""
    # The protocol against order confounds (study/schedule.py).
    blocks: str = "williams"
    assignment: str = "by_id"  # by_id | random
    assignment_seed: int = 0
    # Before and after the whole study (study/instruments.py); not part of the schedule.
    consent_text: str = ""  # "": no consent asked
    before_study: tuple[Any, ...] = ()  # as written, like questionnaires
    after_study: tuple[Any, ...] = ()  # ... and `preference`
    robots: tuple[StudyRobot, ...] = ()  # the robot as a design factor (); none: the scenario's own
    robot_design: str = "between"  # between | within (study/study_robots.py)
    online: Online = Online()  # `haven serve` (study/online.py)

    def resolved_questionnaires(self) -> tuple[Questionnaire, ...]:
        return resolve(self.questionnaires, "questionnaires")

    def instruments(self) -> StudyInstruments:
        ranking = preference([(c.name, c.cues) for c in self.conditions])
        after = [s for s in self.after_study if s != PREFERENCE]
        by_name = {q.name: q for q in (*resolve(after, "after_study"), ranking)}
        return StudyInstruments(
            consent(self.consent_text) if self.consent_text else None,
            resolve(self.before_study, "before_study"),
            tuple(by_name[s if isinstance(s, str) else s["name"]] for s in self.after_study),
        )

    def condition(self, name: str) -> Condition:
        return next(c for c in self.conditions if c.name == name)

    def describe(self) -> dict[str, Any]:
        """Everything that decides the schedule and the trials, as JSON (stored with the schedule
        to tell a changed study file)."""
        return {
            "name": self.name,
            "scenarios": [[s.spec, s.name] for s in self.scenarios],
            "conditions": {c.name: list(c.cues) for c in self.conditions},
            "participants": list(self.participants),
            "repetitions": self.repetitions,
            "counterbalancing": self.counterbalancing,
            "practice": [
                [p.scenario.spec, p.condition.name, *([list(p.condition.cues)] if p.own else [])] for p in self.practice
            ],
            "seeds": {"policy": self.seed_policy, "base": self.seed_base},
            "questionnaires": list(self.questionnaires),
            "blocks": self.blocks if len(self.scenarios) > 1 else "none",  # (one scenario: one block, nothing to order)
            "assignment": {"policy": self.assignment, "seed": self.assignment_seed}
            if self.assignment == "random"
            else {"policy": self.assignment},
            **(
                {"robots": [[r.spec, r.name] for r in self.robots], "robot_design": self.robot_design}
                if self.robots
                else {}
            ),
        }


def study_names() -> list[str]:
    return sorted(p.stem for p in Path(str(resources.files("haven_scenarios") / "studies")).glob("*.yaml"))


def study_path(spec: str) -> Path:
    """A study file, or a shipped study by name."""
    p = Path(spec)
    if p.suffix in (".yaml", ".yml") or p.exists():
        return p
    shipped = Path(str(resources.files("haven_scenarios") / "studies" / f"{spec}.yaml"))
    if shipped.exists():
        return shipped
    raise StudyError(f"{file_label(spec)}: no such study file (shipped: {', '.join(study_names())})")


def load_study(spec: str | Path) -> Study:
    path = study_path(str(spec))
    return parse_study(read_yaml(path, "study file", StudyError), str(path))


def parse_study(data: Any, source: str) -> Study:
    """A study from its YAML tree; `source` names the file in errors."""
    return _StudyParser(source).study(check(StudyFile, data, source, StudyError, "study file"))


class Seeds(FileModel):
    policy: Literal["fixed", "per_participant", "per_trial"] = "per_participant"
    base: Whole(0, SEED_MAX) = 0  # type: ignore[valid-type]


PRACTICE_SCENARIO = "practice"  # the shipped practice room: neither study scenario


class Consent(FileModel):
    """The consent text, written here or in a text file (relative to the study file)."""

    text: str | None = None
    file: str | None = None


class PracticeTrial(FileModel):
    scenario: str = PRACTICE_SCENARIO
    condition: str | None = None  # one of the study's conditions, or:
    cues: Annotated[list[str], listing("a list of cue names (or [all] / [none])")] | None = None  # default [none]


class Assignment(FileModel):
    policy: Literal["by_id", "random"] = "by_id"
    seed: Whole(0, SEED_MAX) | None = None  # type: ignore[valid-type]  # (required with random)


def _practice(v: Any) -> Any:
    return [v] if isinstance(v, dict) else v


def _one_or_list(schema: dict[str, Any]) -> None:
    """The JSON Schema of `practice`: one trial or a list of them (the reader wraps one in a list)."""
    array = {k: schema.pop(k) for k in ("type", "items") if k in schema}
    schema["anyOf"] = [array["items"], array]


def _participants(v: Any) -> Any:
    if isinstance(v, int) and not isinstance(v, bool):
        if not 1 <= v <= MAX_PARTICIPANTS:
            raise ValueError(f"must be a whole number 1..{MAX_PARTICIPANTS}, got {v}")
        return v
    if not isinstance(v, list) or not v or len(v) > MAX_PARTICIPANTS:
        raise ValueError(f"must be a count (1..{MAX_PARTICIPANTS}) or a list of participant ids, got {short(v)}")
    return v


class StudyFile(FileModel):
    """A study file's shape (the module docstring shows one)."""

    name: str
    scenarios: Annotated[list[Any], listing("a non-empty list of scenarios")]
    conditions: Annotated[
        dict[Any, Any], mapping("a mapping of condition name to its cue list, e.g. {none: [none], all: [all]}")
    ]
    participants: Annotated[int | list[Any], checked(_participants)]
    repetitions: Whole(1, MAX_REPETITIONS) = 1  # type: ignore[valid-type]
    counterbalancing: Literal["williams", "latin", "full", "none"] = "williams"
    practice: Annotated[
        list[PracticeTrial],
        listing("{scenario: S, cues: [C, ...]} or a list of them (or of {scenario: S, condition: C})", non_empty=False),
        checked(_practice),  # (runs first: before-validators run last to first)
        Field(json_schema_extra=_one_or_list),
    ] = []  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    seeds: Seeds | None = None
    questionnaires: Annotated[
        list[Any], listing("a list of built-in names (nasa_tlx, godspeed) and Likert mappings", non_empty=False)
    ] = []  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    # The protocol against order confounds (study/schedule.py).
    blocks: Literal["williams", "latin", "full", "none"] = "williams"
    assignment: Assignment | None = None
    # before and after the whole study (study/instruments.py)
    consent: Consent | None = None
    before_study: Annotated[
        list[Any], listing("a list of questionnaires (demographics, nars, ...)", non_empty=False)
    ] = []  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    after_study: Annotated[list[Any], listing("a list of questionnaires (preference, ...)", non_empty=False)] = []  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    robots: Annotated[list[Any], listing("a list of robots: names (haven robots) or robot files", non_empty=False)] = []  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    robot_design: Literal["between", "within"] = "between"
    online: Online | None = None


class _StudyParser:
    """What a study file says beyond its shape: every error names the file and the key in one line."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, key: str, msg: str) -> StudyError:
        return StudyError(f"{file_label(self.source)}: {key}: {msg}")

    def name(self, value: Any, key: str) -> str:
        try:
            return check_name(value, key)
        except ValueError as e:
            raise self.fail(key, str(e).removeprefix(f"{key}: ")) from None

    def study(self, f: StudyFile) -> Study:
        scenarios, conditions = self.scenarios(f.scenarios), self.conditions(f.conditions)
        if f.counterbalancing == "full" and len(conditions) > 8:
            raise self.fail(
                "counterbalancing", f"full: {len(conditions)} conditions have too many orders; use williams"
            )
        if f.blocks == "full" and len(scenarios) > 6:
            raise self.fail("blocks", f"full: {len(scenarios)} scenarios have too many orders; use williams")
        assignment = f.assignment or Assignment()
        if assignment.policy == "random" and assignment.seed is None:
            raise self.fail(
                "assignment.seed",
                "required with policy random: a whole number, fixed before the study (e.g. {policy: random, seed: 7})",
            )
        seeds = f.seeds or Seeds()
        return Study(
            name=self.name(f.name, "name"),
            scenarios=scenarios,
            conditions=conditions,
            participants=self.participants(f.participants),
            repetitions=f.repetitions,
            counterbalancing=f.counterbalancing,
            practice=self.practice(f.practice, scenarios, conditions),
            seed_policy=seeds.policy,
            seed_base=seeds.base,
            questionnaires=self.questionnaires(f.questionnaires),
            source=self.source,
            blocks=f.blocks,
            assignment=assignment.policy,
            assignment_seed=assignment.seed or 0,
            consent_text=self.consent(f.consent),
            before_study=self.instruments(f.before_study, "before_study", ()),
            after_study=self.instruments(f.after_study, "after_study", (PREFERENCE,)),
            robots=parse_robots(f.robots, self.source, StudyError),
            robot_design=f.robot_design,
            online=resolved(f.online, self.source, StudyError),
        )

    def scenario(self, value: Any, key: str) -> StudyScenario:
        if not isinstance(value, str) or not value:
            raise self.fail(key, f"must be a shipped scenario name or a scenario file, got {short(value)}")
        path = Path(value)
        if not path.is_absolute() and (Path(self.source).parent / path).is_file():
            path = Path(self.source).parent / path
        spec = str(path.resolve()) if path.is_file() else value
        try:
            scenario = load_scenario(spec)
        except ScenarioError as e:
            raise self.fail(key, str(e)) from None
        return StudyScenario(spec, self.name(scenario.name, f"{key} (its name)"))

    def scenarios(self, value: list[Any]) -> tuple[StudyScenario, ...]:
        out = tuple(self.scenario(v, f"scenarios[{i}]") for i, v in enumerate(value))
        names = [s.name for s in out]
        for i, n in enumerate(names):
            if n in names[:i]:
                raise self.fail(f"scenarios[{i}]", f"scenario {n!r} is listed twice")
        return out

    def conditions(self, value: dict[Any, Any]) -> tuple[Condition, ...]:
        if len(value) > MAX_CONDITIONS:
            raise self.fail("conditions", f"at most {MAX_CONDITIONS} conditions, got {len(value)}")
        out: list[Condition] = []
        seen: dict[Any, str] = {}
        for name, cues in value.items():
            key = f"conditions.{shown_key(name)}"
            self.name(name, key)
            if "-" in name:  # (trial ids join scenario and condition with '-')
                raise self.fail(key, "a condition name has no '-' (use '_')")
            if not isinstance(cues, list) or not cues or not all(isinstance(c, str) for c in cues):
                raise self.fail(key, f"must be a list of cue names (or [all] / [none]), got {short(cues)}")
            try:
                toggles = parse_condition(cues)
            except ValueError as e:
                raise self.fail(key, str(e)) from None
            if toggles in seen:
                raise self.fail(key, f"shows the same cues as condition {seen[toggles]!r}")
            seen[toggles] = name
            out.append(Condition(name, tuple(cues)))
        return tuple(out)

    def participants(self, value: int | list[Any]) -> tuple[str, ...]:
        if isinstance(value, int):
            width = max(2, len(str(value)))
            return tuple(f"p{k:0{width}d}" for k in range(1, value + 1))
        ids = tuple(self.name(v, f"participants[{i}]") for i, v in enumerate(value))
        for i, p in enumerate(ids):
            if p in ids[:i]:
                raise self.fail(f"participants[{i}]", f"participant {p!r} is listed twice")
        return ids

    def practice(
        self, value: list[PracticeTrial], scenarios: tuple[StudyScenario, ...], conditions: tuple[Condition, ...]
    ) -> tuple[Practice, ...]:
        by_name = {c.name: c for c in conditions}
        listed = {s.name: s for s in scenarios}
        out = []
        for i, p in enumerate(value):
            key = f"practice[{i}]"
            scenario = listed.get(p.scenario) or self.scenario(p.scenario, f"{key}.scenario")
            if p.condition is None:
                out.append(Practice(scenario, self.practice_cues(p.cues or ["none"], f"{key}.cues"), own=True))
            elif p.cues is not None:
                raise self.fail(key, "give cues or condition, not both")
            elif p.condition not in by_name:
                raise self.fail(
                    f"{key}.condition",
                    f"names no condition of the study ({', '.join(by_name)}), got {short(p.condition)}",
                )
            else:
                out.append(Practice(scenario, by_name[p.condition]))
        return tuple(out)

    def practice_cues(self, cues: list[str], key: str) -> Condition:
        try:
            return Condition(condition_name(parse_condition(cues)).replace("+", "_"), tuple(cues))
        except ValueError as e:
            raise self.fail(key, str(e)) from None

    def questionnaires(self, value: list[Any]) -> tuple[Any, ...]:
        try:
            resolve(value, "questionnaires")
        except ValueError as e:
            raise StudyError(f"{file_label(self.source)}: {e}") from None
        return tuple(value)

    def consent(self, value: Consent | None) -> str:
        """The consent text ("" for none); a file is read now, so a study runs with what it said."""
        if value is None:
            return ""
        if (value.text is None) == (value.file is None):
            raise self.fail("consent", "give either text or file")
        text = value.text
        if value.file is not None:
            path = Path(value.file)
            try:
                text = read_text(path if path.is_absolute() else Path(self.source).parent / path, 4 * MAX_CONSENT_CHARS)
            except ValueError as e:
                raise self.fail("consent.file", str(e)) from None
        text = (text or "").strip()
        if not text or len(text) > MAX_CONSENT_CHARS:
            raise self.fail("consent", f"the text must be 1..{MAX_CONSENT_CHARS} characters")
        return text

    def instruments(self, value: list[Any], key: str, special: tuple[str, ...]) -> tuple[Any, ...]:
        if key != "after_study" and PREFERENCE in value:
            raise self.fail(
                f"{key}[{value.index(PREFERENCE)}]",
                f"{PREFERENCE} ranks the conditions after the last trial: list it in after_study",
            )
        try:
            resolve([v for v in value if v not in special], key)
        except ValueError as e:
            also = f" (and here {', '.join(special)})" if special else ""
            raise StudyError(f"{file_label(self.source)}: {e}{also}") from None
        if len({v if isinstance(v, str) else str(v.get("name")) for v in value}) != len(value):
            raise self.fail(key, "a questionnaire is named twice")
        return tuple(value)
