"""Counterbalancing and the study's schedule: every participant's trials in order, with their seeds.

Orders (rows) of n things, for the scenario blocks (`blocks`) and for the conditions inside each
block (`counterbalancing`):
  * `williams`: a Latin square balanced for first-order carry-over (Williams 1949): each comes at
    each position once and immediately before every other exactly once. With an odd n one square
    cannot do that; two can (each row and its reverse): 2n orders, every one then precedes every
    other exactly twice. With 2 scenarios it is AB/BA.
  * `latin`: the cyclic Latin square (row r: r, r+1, ...): positions balanced, carry-over not.
  * `full`: all n! permutations, in lexicographic order.
  * `none`: the file's order for everyone.

Blocks and conditions combine into sequences: sequence s (0..L-1, L the least common multiple of
the two row counts) runs block order s mod B with condition order s mod C in every block. Over
any L consecutive sequences each block order is used L/B times and each condition order L/C
times, so both stay balanced; a participant count that is a multiple of L completes the design.
Which participant takes which sequence (`assignment`): `by_id`, participant k (from 0, in the
list's order) takes sequence k mod L; `random`, each successive set of L participants takes the L
sequences in a random order (permuted blocks, as clinical trials randomise: balanced after every
complete set), from `random.Random(seed)`, whose integer seeding and `sample` give the same
numbers on every CPython since 3.2.

Robots (study/study_robots.py): `within`, the robots' orders (by `counterbalancing`) join the
combination: L is then the least common multiple of the three row counts, sequence s running robot
order s mod R; `between`, participant k meets robot (k // L) mod R.
"""

from __future__ import annotations

import itertools
import math
import random
from dataclasses import asdict, dataclass
from typing import Any

from haven_scenarios.study.protocol import Study
from haven_scenarios.study.study_robots import StudyRobot


def williams(n: int) -> list[list[int]]:
    """Williams design for n conditions: n rows for even n, 2n (the square and its mirror) for odd n."""
    first, low, high = [0], 1, n - 1
    while len(first) < n:  # 0, 1, n-1, 2, n-2, ...
        first.append(low)
        low += 1
        if len(first) < n:
            first.append(high)
            high -= 1
    rows = [[(c + r) % n for c in first] for r in range(n)]
    return rows if n % 2 == 0 else rows + [row[::-1] for row in rows]


def latin(n: int) -> list[list[int]]:
    return [[(c + r) % n for c in range(n)] for r in range(n)]


def orders(design: str, n: int) -> list[list[int]]:
    """The design's orders of n things (indices into the study's conditions or scenarios)."""
    if n <= 1:  # (one thing has one order: Williams' mirror of it would count it twice)
        return [list(range(n))]
    if design == "williams":
        return williams(n)
    if design == "latin":
        return latin(n)
    if design == "full":
        return [list(p) for p in itertools.permutations(range(n))]
    return [list(range(n))]


def block_orders(study: Study) -> list[list[int]]:
    return orders(study.blocks, len(study.scenarios))


def condition_orders(study: Study) -> list[list[int]]:
    return orders(study.counterbalancing, len(study.conditions))


def robot_orders(study: Study) -> list[list[int]]:
    """The orders of the robots each participant meets (`within`); one robot each otherwise."""
    return (
        orders(study.counterbalancing, len(study.robots)) if study.robot_design == "within" and study.robots else [[0]]
    )


def sequence_count(study: Study) -> int:
    """L: the sequences of the combined design (participants complete it in multiples of L)."""
    return math.lcm(len(block_orders(study)), len(condition_orders(study)), len(robot_orders(study)))


def participant_robots(study: Study, k: int, sequence: int) -> list[StudyRobot | None]:
    """The robots participant k meets, in order (None: the scenario's own robot)."""
    if not study.robots:
        return [None]
    if study.robot_design == "within":
        rows = robot_orders(study)
        return [study.robots[i] for i in rows[sequence % len(rows)]]
    return [study.robots[(k // sequence_count(study)) % len(study.robots)]]


def sequences(study: Study) -> list[int]:
    """Each participant's sequence (0..L-1), in the participant list's order (module docstring)."""
    n, p = sequence_count(study), len(study.participants)
    if study.assignment == "by_id":
        return [k % n for k in range(p)]
    rng, out = random.Random(study.assignment_seed), list[int]()
    while len(out) < p:
        out += rng.sample(range(n), n)
    return out[:p]


def _design(kind: str, rows: int, n: int, what: str) -> str:
    if n == 1:
        return f"one {what[:-1]}"
    text = {
        "williams": (
            f"Williams design (Williams 1949): {rows} {what[:-1]} orders, "
            "balanced for position and first-order carry-over"
        ),
        "latin": f"cyclic Latin square: {rows} {what[:-1]} orders, balanced for position (not for carry-over)",
        "full": f"all {rows} permutations of the {what}",
        "none": f"not counterbalanced: every participant takes the {what} in the file's order",
    }[kind]
    if kind == "williams" and n % 2 == 1:
        text += f" ({n} {what} is odd, so two Latin squares: each order and its reverse)"
    return text


def design_note(study: Study) -> str:
    """What the counterbalancing gives this study, in a few sentences for `haven study plan`."""
    b, c, n, p = len(block_orders(study)), len(condition_orders(study)), sequence_count(study), len(study.participants)
    text = (
        f"Scenario blocks: {_design(study.blocks, b, len(study.scenarios), 'scenarios')}. "
        f"Conditions in each block: {_design(study.counterbalancing, c, len(study.conditions), 'conditions')}"
    )
    if b > 1 and c > 1:
        text += (
            f". Combined: {n} sequences (the least common multiple of {b} "
            f"and {c}): every {n} participants use each block order "
        )
        text += "and each condition order equally often"
        if n < b * c:
            text += (
                " (the two are paired, not crossed: sequence s takes "
                f"block order s mod {b} and condition order s mod {c}, "
            )
            text += f"so only {n} of the {b * c} pairs occur)"
    text += _robots_note(study, n, c)
    full = n * (len(study.robots) if study.robots and study.robot_design == "between" else 1)
    if full > 1:
        text += f"; {p} participant(s) " + (
            "complete it" if p % full == 0 else f"do not complete it: use a multiple of {full}"
        )
    if study.assignment == "random":
        text += (
            f". Assignment: random (seed {study.assignment_seed}), "
            f"each set of {n} participants takes the {n} sequences in a shuffled order"
        )
    else:
        text += f". Assignment: by id, participant k in the list takes sequence k mod {n}"
    return text + "."


def _robots_note(study: Study, n: int, c: int) -> str:
    if not study.robots:
        return ""
    names = ", ".join(r.name for r in study.robots)
    if study.robot_design == "within":
        rows = len(robot_orders(study))
        text = (
            f". Robots (within): every participant meets {names}, "
            f"one block of trials each, in one of {rows} robot orders"
        )
        if rows > 1 and c > 1 and n < rows * c:
            text += f" (paired with the condition orders, not crossed: sequence s takes robot order s mod {rows}, "
            text += f"so only {n} of the {rows * c} pairs occur)"
        return text
    return f". Robots (between): each set of {n} participants meets one robot, in turn {names}"


def sequence_orders(study: Study) -> list[tuple[list[str], list[str]]]:
    """Each sequence's scenario order and condition order, by name (sequence s is item s - 1)."""
    blocks, conditions = block_orders(study), condition_orders(study)
    return [
        (
            [study.scenarios[i].name for i in blocks[s % len(blocks)]],
            [study.conditions[i].name for i in conditions[s % len(conditions)]],
        )
        for s in range(sequence_count(study))
    ]


def practice_note(study: Study) -> str | None:
    """A carry-over the practice builds in, if any: cues shown in practice before a no-cue condition."""
    shown = sorted({c for p in study.practice if p.condition.cues != ("none",) for c in p.condition.cues})
    plain = [c.name for c in study.conditions if c.cues == ("none",)]
    if not shown or not plain:
        return None
    return (
        f"the practice shows {', '.join(shown)} before every participant's {plain[0]} trials, "
        "a carry-over no order undoes; `practice: {scenario: practice, cues: [none]}` practises without cues"
    )


@dataclass(frozen=True)
class PlannedTrial:
    participant: str
    position: int  # 1.. in the participant's order, practice first
    trial_id: str  # `<scenario>-<condition>` (+ `-r<k>` with repetitions), `practice<k>-...` for practice
    scenario: str  # the scenario's name
    scenario_spec: str  # what `haven run` is given
    condition: str  # the study's condition name (practice: its own, or the cues' name)
    cues: tuple[str, ...]
    seed: int
    practice: bool
    repetition: int  # 1.. (0 for practice)
    sequence: int = 1  # 1.. the participant's sequence of the design (schedule's docstring)
    block: int = 0  # the scenario block's place in the participant's order, 1..; 0 for practice
    position_in_block: int = 1  # 1.. within the block (practice: within the practice trials)
    previous_condition: str = ""  # the condition of the trial before in the same block; "" for the first
    robot: str = ""  # `haven run --robot`: the study's robot (a name or a file); "": the scenario's own
    robot_name: str = ""  # its name ("": the scenario's own)

    @property
    def folder(self) -> str:
        """The trial's folder under the participant's: its attempts (session folders) live in it."""
        return f"{self.position:02d}_{self.trial_id}"

    def to_json(self) -> dict[str, Any]:
        d = asdict(self)
        d["cues"] = list(self.cues)
        return d


def trials_per_participant(study: Study) -> int:
    robots = len(study.robots) if study.robot_design == "within" and study.robots else 1
    return len(study.practice) + len(study.scenarios) * len(study.conditions) * study.repetitions * robots


def _seed(study: Study, k: int, position: int) -> int:
    if study.seed_policy == "fixed":
        return study.seed_base
    if study.seed_policy == "per_participant":
        return study.seed_base + k
    return study.seed_base + k * trials_per_participant(study) + position - 1


def _trials(study: Study, k: int, sequence: int) -> list[PlannedTrial]:
    """Participant k's trials: practice (with their first robot), then for each of their robots
    each scenario's block (in the sequence's block order) of conditions in the sequence's
    condition order, repeated `repetitions` times."""
    robots = participant_robots(study, k, sequence)
    spec, name = (robots[0].spec, robots[0].name) if robots[0] else ("", "")
    participant, out = study.participants[k], list[PlannedTrial]()
    for i, p in enumerate(study.practice, 1):
        c = p.condition
        tid = f"practice{i}-{p.scenario.name}-{c.name}"
        out.append(PlannedTrial(participant, i, tid, p.scenario.name, p.scenario.spec, c.name, c.cues,
                                _seed(study, k, i), True, 0, sequence + 1, 0, i, out[-1].condition if out else "",
                                spec, name))  # fmt: skip
    for robot in robots:
        _blocks(study, k, sequence, robot, out)
    return out


def _blocks(study: Study, k: int, sequence: int, robot: StudyRobot | None, out: list[PlannedTrial]) -> None:
    """The scenario blocks with one robot, appended to `out` (block numbers go on across robots)."""
    blocks, conditions = block_orders(study), condition_orders(study)
    order = [study.conditions[i] for i in conditions[sequence % len(conditions)]]
    spec, name = (robot.spec, robot.name) if robot else ("", "")
    tag = f"-{robot.name}" if robot and study.robot_design == "within" else ""
    first_block = max((t.block for t in out), default=0)
    for b, s in enumerate((study.scenarios[i] for i in blocks[sequence % len(blocks)]), first_block + 1):
        previous = ""
        for rep in range(1, study.repetitions + 1):
            for c in order:
                position, suffix = len(out) + 1, f"-r{rep}" if study.repetitions > 1 else ""
                in_block = (rep - 1) * len(order) + order.index(c) + 1
                out.append(PlannedTrial(study.participants[k], position, f"{s.name}-{c.name}{suffix}{tag}",
                                        s.name, s.spec, c.name, c.cues, _seed(study, k, position), False, rep,
                                        sequence + 1, b, in_block, previous, spec, name))  # fmt: skip
                previous = c.name


def participant_schedule(study: Study, participant: str) -> list[PlannedTrial]:
    """One participant's trials in order (see `_trials`)."""
    k = study.participants.index(participant)
    return _trials(study, k, sequences(study)[k])


def schedule(study: Study) -> list[PlannedTrial]:
    return [t for k, s in enumerate(sequences(study)) for t in _trials(study, k, s)]


def assignment(study: Study) -> dict[str, int]:
    """Participant -> sequence (1..L): what the stored schedule records of the assignment."""
    return {p: s + 1 for p, s in zip(study.participants, sequences(study), strict=True)}
