"""The study's mixed model: per scenario and measure, `value ~ condition (+ robot) (+ position) + (1 | participant)`.

A linear mixed model with a random intercept per participant (statsmodels `MixedLM`, REML), fitted
on the valid, non-practice trials: the conditions are within-subject, so each participant's own
level is a random effect and the condition effects are fixed ones, coded against a reference
condition (treatment coding). The trial's overall position in the participant's session enters as
a linear fixed effect when it varies and is not confounded with the condition (with no
counterbalancing it is: then it is left out and the note says so). Where the study's robot varies (a
design factor, between or within participants), the robot enters as a fixed effect too, coded against
the first robot in alphabetical order (terms `robot:<name>`). A per-person measure is averaged over the
trial's people first, so a trial is one observation.

A fit whose participant variance is (numerically) zero is *singular*: the data show no difference
between participants beyond the trial-to-trial noise, the model degenerates to ordinary least
squares, and its p values are then those of a design that ignores the pairing. It is flagged, never
hidden; deterministic simulated participants always give one.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from haven_scenarios.record.study_table import TrialResults

# A participant variance below this fraction of the residual variance counts as zero (a singular
# fit, at the boundary): statsmodels' optimiser never reaches exactly 0, and on data with no
# participant variance it stopped between 6e-5 and 2e-3 of the residual variance (our measurement,
# test_mixed_model.py's data). An intraclass correlation under 1 % is no participant effect to speak of.
SINGULAR_FRACTION = 0.01
EXACT_FRACTION = 1e-12  # variances this small against the values' own are round-off: no noise at all
ALPHA = 0.05  # the confidence intervals' level: 95 %
# The design column of the trial's overall position in the participant's session: the first of
# these the table has (the study table's name for it, and the schedule's).
POSITIONS = ("order_position", "sequence", "position")
MIXED = (
    "scenario", "measure", "human", "formula", "reference", "participants", "trials",
    "term", "coef", "ci_low", "ci_high", "p", "participant_var", "residual_var", "converged", "singular", "note",
)  # fmt: skip


@dataclass(frozen=True)
class Observation:
    participant: str
    condition: str
    position: float
    value: float
    robot: str = ""  # the trial's robot (a design factor where it varies)


@dataclass(frozen=True)
class Term:
    name: str  # "intercept", a condition's name (its difference from the reference) or "position"
    coef: float
    ci_low: float | None
    ci_high: float | None
    p: float | None


@dataclass(frozen=True)
class Fit:
    formula: str
    reference: str
    participants: int
    trials: int
    terms: tuple[Term, ...] = ()  # empty when nothing could be fitted (`note` says why)
    participant_var: float | None = None
    residual_var: float | None = None
    converged: bool = False
    singular: bool = False
    note: str = ""

    def term(self, name: str) -> Term | None:
        return next((t for t in self.terms if t.name == name), None)


def observations(results: Sequence[TrialResults], scenario: str, measure: str, per_person: bool) -> list[Observation]:
    """The valid, non-practice trials' values of one measure in one scenario (people averaged per trial)."""
    out = []
    for r in results:
        d = r.design
        if d["practice"] or not d["valid"] or d["scenario"] != scenario:
            continue
        values = [m.value for m in r.measures if m.measure == measure and bool(m.human) == per_person]
        if values and all(math.isfinite(v) for v in values):
            position = next((float(d[k]) for k in POSITIONS if d.get(k) is not None), 0.0)
            robot = str(d.get("robot") or "")
            out.append(
                Observation(str(d["participant"]), str(d["condition"]), position, sum(values) / len(values), robot)
            )
    return out


def _finite(x: Any) -> float | None:
    v = float(x)
    return v if math.isfinite(v) else None


def _design(obs: Sequence[Observation], conditions: Sequence[str], reference: str) -> tuple[np.ndarray, list[str], str]:
    """The fixed effects' matrix, its columns' names, and a note on position when it was left out."""
    others = [c for c in conditions if c != reference and any(o.condition == c for o in obs)]
    columns = [np.ones(len(obs))] + [np.array([o.condition == c for o in obs], dtype=float) for c in others]
    names = ["intercept", *others]
    note = ""
    robots = sorted({o.robot for o in obs})
    if len(robots) > 1:  # the robot as a design factor, against the first robot
        with_robot = [*columns, *(np.array([o.robot == r for o in obs], dtype=float) for r in robots[1:])]
        if np.linalg.matrix_rank(np.column_stack(with_robot)) == len(with_robot):
            columns, names = with_robot, [*names, *(f"robot:{r}" for r in robots[1:])]
            note = f"robot coded against {robots[0]}"
        else:
            note = "robot left out: confounded with condition"
    position = np.array([o.position for o in obs])
    if np.ptp(position) > 0:
        with_position = np.column_stack([*columns, position - position.mean()])
        if np.linalg.matrix_rank(with_position) == with_position.shape[1]:
            return with_position, [*names, "position"], note
        note = "; ".join(filter(None, [note, "position left out: confounded with condition"]))
    return np.column_stack(columns), names, note


def fit(obs: Sequence[Observation], conditions: Sequence[str], reference: str) -> Fit:
    """The mixed model on these observations; a Fit with a note instead of terms when there is
    nothing to fit (too few participants or conditions, no variation, a failed optimisation)."""
    from statsmodels.regression.mixed_linear_model import MixedLM

    people = sorted({o.participant for o in obs})
    x, names, note = _design(obs, conditions, reference)
    robot = " + robot" if any(n.startswith("robot:") for n in names) else ""
    formula = "value ~ condition" + robot + (" + position" if "position" in names else "") + " + (1 | participant)"
    base = Fit(formula, reference, len(people), len(obs))
    if not any(o.condition == reference for o in obs):
        return replace(base, note=f"no valid trial in the reference condition {reference}")
    if len(people) < 2 or len(names) < 2 or x.shape[0] <= x.shape[1] + 1:
        return replace(base, note="too few participants, conditions or trials to fit")
    y = np.array([o.value for o in obs])
    if np.ptp(y) == 0:
        return replace(base, note=f"all values equal ({y[0]:g}): nothing to fit")
    groups = np.array([people.index(o.participant) for o in obs])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = MixedLM(y, x, groups=groups).fit(reml=True)
        except (ValueError, np.linalg.LinAlgError) as e:
            return replace(base, note=f"fit failed: {str(e)[:80]}")
    k = x.shape[1]
    ci = np.asarray(result.conf_int(ALPHA))[:k]
    params, pvalues = np.asarray(result.fe_params), np.asarray(result.pvalues)[:k]
    terms = tuple(
        Term(n, float(params[i]), _finite(ci[i, 0]), _finite(ci[i, 1]), _finite(pvalues[i]))
        for i, n in enumerate(names)
    )
    participant_var, residual_var = float(np.asarray(result.cov_re)[0, 0]), float(result.scale)
    exact = participant_var + residual_var <= EXACT_FRACTION * float(np.var(y))
    singular = exact or participant_var <= SINGULAR_FRACTION * residual_var
    said = sorted({str(w.message).split("\n")[0][:70] for w in caught})
    notes = [note] if note else []
    if exact:
        notes.append(
            "singular fit: no variance left, the fixed effects give every "
            "value exactly (deterministic data): p values mean nothing"
        )
    elif singular:
        notes.append(
            "singular fit: participant variance 0 (under 1 % of the residual: no spread between participants to model)"
        )
    # (statsmodels tries its optimizers in turn: a warning from one that failed may precede a converged fit)
    said_by = "statsmodels, on the way to a converged fit" if result.converged else "statsmodels, not converged"
    notes += [f"{said_by}: {s}" for s in said if not (singular and "boundary" in s)]
    return replace(
        base,
        terms=terms,
        participant_var=max(participant_var, 0.0),
        residual_var=residual_var,
        converged=bool(result.converged),
        singular=singular,
        note="; ".join(notes),
    )


def model_rows(
    results: Sequence[TrialResults], measures: Sequence[tuple[str, bool]], conditions: Sequence[str]
) -> list[dict[str, Any]]:
    """mixed_models.csv: per scenario x measure (name, per person?), a row per fixed effect (or one
    with the note when nothing was fitted); the reference is the study's first condition."""
    scenarios = sorted({str(r.design["scenario"]) for r in results if not r.design["practice"]})
    rows: list[dict[str, Any]] = []
    for scenario in scenarios:
        for measure, per_person in measures:
            obs = observations(results, scenario, measure, per_person)
            if not obs:
                continue
            f = fit(obs, conditions, conditions[0])
            head = {
                "scenario": scenario,
                "measure": measure,
                "human": "person" if per_person else "",
                "formula": f.formula,
                "reference": f.reference,
            }
            tail = {
                "participants": f.participants,
                "trials": f.trials,
                "participant_var": _significant(f.participant_var),
                "residual_var": _significant(f.residual_var),
                "converged": f.converged if f.terms else "",
                "singular": f.singular if f.terms else "",
                "note": f.note,
            }
            for t in f.terms or (Term("", math.nan, None, None, None),):
                values = {
                    "term": t.name,
                    "coef": _round(t.coef),
                    "ci_low": _round(t.ci_low),
                    "ci_high": _round(t.ci_high),
                    "p": _round(t.p, 6),
                }
                rows.append({**head, **tail, **values})
    return rows


def _round(v: float | None, digits: int = 4) -> float | None:
    return round(v, digits) if v is not None and math.isfinite(v) else None


def _significant(v: float | None) -> float | None:
    return float(f"{v:.4g}") if v is not None and math.isfinite(v) else None


def fit_counts(rows: Sequence[dict[str, Any]]) -> tuple[int, int, int]:
    """(singular fits, fits that did not converge, fits) among model_rows' models."""
    fits: dict[tuple[str, str, str], tuple[bool, bool]] = {}
    for r in rows:
        if r["term"]:
            fits[(r["scenario"], r["measure"], r["human"])] = (bool(r["singular"]), not r["converged"])
    return sum(s for s, _ in fits.values()), sum(u for _, u in fits.values()), len(fits)
