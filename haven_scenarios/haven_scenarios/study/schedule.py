"""Counterbalancing and the study's schedule: every participant's trials in order, with their seeds.

Condition orders (rows; participant k takes row k mod the number of rows):
  * `williams`: a Latin square balanced for first-order carry-over (Williams 1949): each condition
    comes at each position once and immediately before every other condition exactly once. With an
    odd number of conditions one square cannot do that; two can (each row and its reverse): 2n orders,
    every condition then precedes every other exactly twice.
  * `latin`: the cyclic Latin square (row r: r, r+1, ...): positions balanced, carry-over not.
  * `full`: all n! permutations, in lexicographic order, cycled over the participants.
  * `none`: the file's order for everyone.
A design is balanced when the number of participants is a multiple of its rows (`plan` says so).
"""

from __future__ import annotations

import itertools
from dataclasses import asdict, dataclass
from typing import Any

from haven_scenarios.study.protocol import Study


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
    """The design's condition orders (indices into the study's conditions)."""
    if design == "williams":
        return williams(n)
    if design == "latin":
        return latin(n)
    if design == "full":
        return [list(p) for p in itertools.permutations(range(n))]
    return [list(range(n))]


def design_note(study: Study) -> str:
    """What the counterbalancing gives this study, in a sentence or two for `haven study plan`."""
    n, p = len(study.conditions), len(study.participants)
    rows = len(orders(study.counterbalancing, n))
    text = {
        "williams": f"Williams design (Williams 1949): {rows} condition orders, balanced for position and first-order carry-over",
        "latin": f"cyclic Latin square: {rows} condition orders, balanced for position (not for carry-over)",
        "full": f"all {rows} permutations of the conditions",
        "none": "no counterbalancing: every participant sees the conditions in the file's order",
    }[study.counterbalancing]
    if study.counterbalancing == "williams" and n % 2 == 1 and n > 1:
        text += f"; {n} conditions is odd, so two Latin squares are needed (each order and its reverse)"
    if rows > 1:
        text += f"; {p} participant(s) " + ("complete it" if p % rows == 0 else f"do not complete it: use a multiple of {rows}")
    return text + "."


@dataclass(frozen=True)
class PlannedTrial:
    participant: str
    position: int  # 1.. in the participant's order, practice first
    trial_id: str  # `<scenario>-<condition>` (+ `-r<k>` with repetitions), `practice<k>-...` for practice
    scenario: str  # the scenario's name
    scenario_spec: str  # what `haven run` is given
    condition: str  # the study's condition name
    cues: tuple[str, ...]
    seed: int
    practice: bool
    repetition: int  # 1.. (0 for practice)

    @property
    def folder(self) -> str:
        """The trial's folder under the participant's: its attempts (session folders) live in it."""
        return f"{self.position:02d}_{self.trial_id}"

    def to_json(self) -> dict[str, Any]:
        d = asdict(self)
        d["cues"] = list(self.cues)
        return d


def trials_per_participant(study: Study) -> int:
    return len(study.practice) + len(study.scenarios) * len(study.conditions) * study.repetitions


def _seed(study: Study, k: int, position: int) -> int:
    if study.seed_policy == "fixed":
        return study.seed_base
    if study.seed_policy == "per_participant":
        return study.seed_base + k
    return study.seed_base + k * trials_per_participant(study) + position - 1


def participant_schedule(study: Study, participant: str) -> list[PlannedTrial]:
    """One participant's trials in order: practice, then each scenario's block of conditions in the
    participant's counterbalanced order (repeated `repetitions` times)."""
    k = study.participants.index(participant)
    rows = orders(study.counterbalancing, len(study.conditions))
    order = [study.conditions[i] for i in rows[k % len(rows)]]
    out: list[PlannedTrial] = []

    def add(scenario_name: str, spec: str, condition_name: str, cues: tuple[str, ...], trial_id: str, practice: bool, rep: int) -> None:
        position = len(out) + 1
        out.append(PlannedTrial(participant, position, trial_id, scenario_name, spec, condition_name, cues, _seed(study, k, position), practice, rep))

    for i, p in enumerate(study.practice, 1):
        add(p.scenario.name, p.scenario.spec, p.condition.name, p.condition.cues, f"practice{i}-{p.scenario.name}-{p.condition.name}", True, 0)
    for s in study.scenarios:
        for rep in range(1, study.repetitions + 1):
            for c in order:
                suffix = f"-r{rep}" if study.repetitions > 1 else ""
                add(s.name, s.spec, c.name, c.cues, f"{s.name}-{c.name}{suffix}", False, rep)
    return out


def schedule(study: Study) -> list[PlannedTrial]:
    return [t for p in study.participants for t in participant_schedule(study, p)]
