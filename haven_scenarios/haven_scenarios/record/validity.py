"""How complete a recording is: a session is valid only when nothing the metrics rest on was lost.

Checked on the recording itself: /odom comes every physics step and /humans at a fixed rate, so
their header stamps show every missing message and every gap, a late start included; events carry a sequence number per
source (`seq`), so a missing one shows too, and the planner's and the scenario's name each /plan and
/goal_pose they publish, so a missing plan or goal shows; the recorder notes every message DDS reports lost,
and a loss on a topic the metrics read counts; a trial must have ended with `trial_end`; and no
publisher from outside the suite may have been there before it ended (`record/outsiders.py`), nor
the planner have planned before it began (for an outside goal); and no plugin may have failed (its code
raised or overran its deadline: `plugin_failed`, common/contain.py); and no participant may have been away (their
page disconnected) for longer than MAX_AWAY_S while it ran on without them (`study/presence.py`: with
`on_disconnect: pause` it stood still instead, and a participant not back in time aborts it).
"""

from __future__ import annotations

import math
from collections import Counter
from typing import Any

import numpy as np

from haven_scenarios.record.outsiders import METRIC_TOPICS, Declared, judge
from haven_scenarios.record.timeline import Recording
from haven_scenarios.study.presence import MAX_AWAY_S
from haven_sim.common import topics
from haven_sim.common.contain import failures
from haven_sim.common.events import PLAN_POSES, EventKind, Source

MIN_COVERAGE = 0.99
MAX_GAP_S = 0.1


def _stream(name: str, stamps: list[float], window: tuple[float, float]) -> list[str]:
    inside = [s for s in stamps if window[0] - MAX_GAP_S <= s <= window[1] + MAX_GAP_S]
    t = np.unique(np.array(inside, dtype=float))
    out = (
        [f"{name}: {len(inside) - len(t)} message(s) with the stamp of another (a second publisher?)"]
        if len(t) < len(inside)
        else []
    )
    if len(t) < 2:
        return [*out, f"{name}: {len(t)} message(s) in the trial"]
    gaps = np.diff(t)
    # The stream's period: robust to a few losses, and to rates that alternate between two step
    # counts (20 Hz on 50 Hz physics gives gaps of 0.04 and 0.06 s).
    period = float(np.median((gaps[:-1] + gaps[1:]) / 2.0)) if len(gaps) > 1 else float(gaps[0])
    expected = round((t[-1] - t[0]) / period) + 1.0  # rounded: a stream may end on its short gap
    # (coverage counts from the first message: a late start is a gap of its own)
    if t[0] > window[0] + MAX_GAP_S + 1e-6:
        out.append(f"{name}: recorded only from {t[0] - window[0]:.2f} s into the trial")
    if len(t) < MIN_COVERAGE * expected:
        out.append(f"{name}: {100.0 * len(t) / expected:.1f} % of the messages recorded")
    if gaps.max() > MAX_GAP_S + 1e-6:
        at = float(t[int(np.argmax(gaps))] - window[0])
        out.append(f"{name}: a gap of {gaps.max():.2f} s at {at:.1f} s")
    return out


def _missing_events(rec: Recording, window: tuple[float, float] | None) -> list[str]:
    """Events missing by their per-source `seq`, those that can have been published while the trial
    ran: a source numbers its events in time order, so the ones missing between two recorded ones
    came between their stamps (a gap that closes at or before trial_start is not the trial's)."""
    start = -math.inf if window is None else window[0] + 1e-9
    by_source: dict[str, dict[int, float]] = {}
    for e in rec.events:
        if isinstance(e.get("seq"), int):
            by_source.setdefault(e.source, {})[e["seq"]] = e.stamp
    out = []
    for source, stamps in sorted(by_source.items()):
        seqs = sorted(stamps)
        missing = sum(b - a - 1 for a, b in zip([0, *seqs], seqs, strict=False) if b - a > 1 and stamps[b] > start)
        if missing:
            out.append(f"events: {missing} of {source}'s missing")
    return out


def _sent_but_not_recorded(rec: Recording, window: tuple[float, float]) -> list[str]:
    """Every /plan the planner's events say it published (`plan_poses`) and every /goal_pose the
    scenario's say it sent (`goal_sent`) must be in the recording, at the event's stamp."""
    t0, t1 = window[0] - MAX_GAP_S, window[1] + 1e-6
    plans = Counter((round(s, 3), len(p)) for s, p in rec.plans)
    goals = Counter(round(s, 3) for s, _ in rec.goals)
    missing_plans = missing_goals = 0
    for e in rec.events:
        if not t0 <= e.stamp <= t1:
            continue
        if e.source == Source.PLANNER and isinstance(e.get(PLAN_POSES), int):
            key = (round(e.stamp, 3), e[PLAN_POSES])
            missing_plans += plans[key] == 0
            plans[key] -= 1
        elif e.kind is EventKind.GOAL_SENT:
            missing_goals += goals[round(e.stamp, 3)] == 0
            goals[round(e.stamp, 3)] -= 1
    out = [f"/plan: {missing_plans} of the planner's plans not recorded"] if missing_plans else []
    return out + ([f"/goal_pose: {missing_goals} of the scenario's goals not recorded"] if missing_goals else [])


def _planned_before_start(
    rec: Recording, window: tuple[float, float], declared: Declared | None
) -> tuple[list[str], list[str]]:
    """(reasons, notes): the planner's plans from before trial_start. The scenario sends its first
    goal at the start, so an earlier plan followed somebody else's goal, which can have moved the
    robot the trial then starts from, even if its publisher was gone before the recorder looked."""
    early = sum(
        1
        for e in rec.events
        if e.source == Source.PLANNER and isinstance(e.get(PLAN_POSES), int) and e.stamp < window[0] - 1e-6
    )
    if not early:
        return [], []
    line = f"/plan: {early} plan(s) made before the trial began, for goals from outside the suite"
    return ([], [line]) if declared is not None and f"/{topics.GOAL}" in declared.open else ([line], [])


def _away(rec: Recording, window: tuple[float, float]) -> list[str]:
    """Participants whose page was disconnected for longer than MAX_AWAY_S while the trial ran on
    without them (policy keep): as the web node measured it, or, for one never back, to the trial's end."""
    out, left = [], {}
    for e in rec.events:
        if (
            e.kind is EventKind.PARTICIPANT_DISCONNECTED
            and window[0] - 1e-6 <= e.stamp <= window[1] + 1e-6
            and e.get("policy") == "keep"
        ):
            left[e["by"]] = e.stamp
        elif e.kind in (EventKind.PARTICIPANT_RECONNECTED, EventKind.PARTICIPANT_LOST) and e["by"] in left:
            at = left.pop(e["by"])
            if e["away_s"] > MAX_AWAY_S:
                out.append(
                    f"participant {e['by']}: away {e['away_s']:g} s from "
                    f"{at - window[0]:.1f} s into the trial (its page disconnected)"
                )
    out += [
        f"participant {who}: away from {at - window[0]:.1f} s into the trial to its end (its page disconnected)"
        for who, at in left.items()
        if window[1] - at > MAX_AWAY_S
    ]
    return out


def check(rec: Recording, window: tuple[float, float] | None, declared: Declared | None = None) -> dict[str, Any]:
    """`declared`: what the run said of itself (session.json), to judge the publishers the recorder
    saw (record/outsiders.py); None: nothing to judge (batch mode, sessions from before)."""
    reasons: list[str] = []
    noted: list[str] = []
    if declared is not None and rec.publishers is not None:
        reasons, noted = judge(rec.publishers, declared, window)
    if window is None:
        reasons.append("no trial_start or no /odom recorded")
    else:
        reasons += _stream("/odom", [s for s, _ in rec.odom], window)
        if rec.humans:
            reasons += _stream("/humans", [s for s, _ in rec.humans], window)
    lost = {topic: n for topic, n in rec.lost.items() if n and topic.lstrip("/") in METRIC_TOPICS}
    reasons += [f"{topic}: {n} message(s) lost before the recorder read them" for topic, n in sorted(lost.items())]
    if rec.first(EventKind.TRIAL_END) is None:
        reasons.append("no trial_end recorded")
    if window is not None:
        reasons += _sent_but_not_recorded(rec, window) + _away(rec, window)
        early, early_noted = _planned_before_start(rec, window, declared)
        reasons, noted = reasons + early, noted + early_noted
    reasons += _missing_events(rec, window)
    reasons += failures(e for e in rec.events if window is None or e.stamp <= window[1] + 1e-6)
    reasons += [
        f"{e['topic']}: {e['messages']} of the suite's message(s) never reached {e.source} on the lockstep clock"
        for e in rec.events
        if e.kind is EventKind.INPUT_LOST and (window is None or window[0] - MAX_GAP_S <= e.stamp <= window[1] + 1e-6)
    ]
    return {"valid": not reasons, "invalid_reasons": reasons, "outside_publishers": "; ".join(noted)}
