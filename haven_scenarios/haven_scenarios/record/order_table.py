"""A study's order and carry-over table (`order_effects.csv`): is a measure different when a trial
comes earlier or later, or right after another condition?

One row per scenario x person x measure x factor x level, over valid non-practice trials:
  * `block`: the scenario block's place in the session (1: this scenario came first). With blocks
    counterbalanced, a difference here is time in session (learning, fatigue), not the scenario.
  * `order_position`: the trial's place in the participant's session (practice counted).
  * `position_in_block`: its place in its scenario's block.
  * `previous_condition`: the condition of the trial before in the same block (`(first)` for a
    block's first trial), pooled over the trial's own conditions (`condition` empty), and per
    condition: a carry-over shows as a condition's mean that depends on what came before it.
With a complete counterbalanced design each position holds every condition equally often, so
position means are not condition means in disguise; the table describes, the analysis (a mixed
model with the order columns of study_long.csv) tests.
"""

from __future__ import annotations

import statistics
from collections import defaultdict
from collections.abc import Sequence
from typing import Any

from haven_scenarios.record.study_table import TrialResults

ORDER_EFFECTS = ("scenario", "human", "measure", "factor", "level", "condition", "n", "mean", "sd")
POSITIONS = ("block", "order_position", "position_in_block")  # numeric factors, pooled over conditions
FIRST = "(first)"  # the level of `previous_condition` for a block's first trial

Cell = tuple[str, str, str, str, str, str]  # scenario, human, measure, factor, level, condition


def _cells(results: Sequence[TrialResults]) -> dict[Cell, list[float]]:
    out: dict[Cell, list[float]] = defaultdict(list)
    for r in results:
        d = r.design
        if d["practice"] or not d["valid"]:
            continue
        previous = str(d["previous_condition"]) or FIRST
        for m in r.measures:
            head = (str(d["scenario"]), m.human, m.measure)
            for factor in POSITIONS:
                out[(*head, factor, str(d[factor]), "")].append(m.value)
            out[(*head, "previous_condition", previous, "")].append(m.value)
            out[(*head, "previous_condition", previous, str(d["condition"]))].append(m.value)
    return out


def order_rows(results: Sequence[TrialResults], conditions: Sequence[str]) -> list[dict[str, Any]]:
    """The table's rows: per scenario, person and measure as first met; factors in POSITIONS order
    then previous_condition; numeric levels ascending, conditions in the study's order."""
    rank = {c: i for i, c in enumerate([FIRST, *conditions])}
    factors = {f: i for i, f in enumerate((*POSITIONS, "previous_condition"))}
    cells = _cells(results)
    heads = {c[:3]: i for i, c in reversed(list(enumerate(cells)))}

    def key(c: Cell) -> tuple[Any, ...]:
        level = (int(c[4]), 0) if c[3] in POSITIONS else (rank.get(c[4], len(rank)), 0)
        return (heads[c[:3]], factors[c[3]], c[5] != "", rank.get(c[5], len(rank)), level)

    rows = []
    for c in sorted(cells, key=key):
        values = cells[c]
        sd = statistics.stdev(values) if len(values) > 1 else None
        rows.append(dict(zip(ORDER_EFFECTS, (*c, len(values), statistics.fmean(values), sd), strict=True)))
    return rows
