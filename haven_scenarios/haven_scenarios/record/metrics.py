"""Trial metrics from trajectories and events, so they can be recomputed from any recording.

Names and thresholds follow the social-navigation benchmarks where they exist: time to goal, path
length, minimum human-robot distance, intrusions into the intimate / personal / social zones at
0.45 / 1.2 / 3.6 m (Hall's proxemics; centre-to-centre distance), collisions; plus HAVEN's own:
waits, re-plans, battery used, charge trips, gems by each party, and cue exposure (time the thought
bubble was shown; how long before each turn the turn signal on that side was lit).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from haven_scenarios.record.log import TrialLog
from haven_sim.common.events import Event, EventKind
from haven_sim.common.geometry import FloatArray

ZONES = {"intimate": 0.45, "personal": 1.2, "social": 3.6}
TURN_RATE_RPS = 0.3  # |angular velocity| above this is a turn


def _path_length(xy: FloatArray) -> float:
    return float(np.sum(np.hypot(*np.diff(xy, axis=0).T))) if len(xy) > 1 else 0.0


def _first(events: Sequence[Event], kind: EventKind, **match: Any) -> float | None:
    for e in events:
        if e.kind is kind and all(e.get(k) == v for k, v in match.items()):
            return e.stamp
    return None


def _count(events: Sequence[Event], kind: EventKind) -> int:
    return sum(1 for e in events if e.kind is kind)


def _intervals(events: Sequence[Event], start: EventKind, stop: set[EventKind], end_t: float) -> list[tuple[float, float]]:
    out: list[tuple[float, float]] = []
    since: float | None = None
    for e in events:
        if e.kind is start and since is None:
            since = e.stamp
        elif e.kind in stop and since is not None:
            out.append((since, e.stamp))
            since = None
    if since is not None:
        out.append((since, end_t))
    return out


def signal_lead_times(t: FloatArray, wz: FloatArray, signal: Sequence[int]) -> list[float]:
    """For each turn (|wz| above TURN_RATE_RPS), how long the matching turn signal had been lit
    when it began (0 if it was not lit)."""
    leads = []
    turning = np.abs(wz) > TURN_RATE_RPS
    sig = np.asarray(signal)
    for i in range(1, len(t)):
        if turning[i] and not turning[i - 1]:
            side = 1 if wz[i] > 0 else -1
            j = i
            while j > 0 and sig[j - 1] == side:
                j -= 1
            leads.append(float(t[i] - t[j]) if sig[i - 1] == side else 0.0)
    return leads


def compute(log: TrialLog, scenario: str = "", end_reason: str = "") -> dict[str, Any]:
    """Times are seconds since the trial started (the `trial_start` event; in a recording the
    simulation may have run a little before it)."""
    start = _first(log.events, EventKind.TRIAL_START)
    t0 = start if start is not None else (log.t[0] if log.t else 0.0)
    keep = [i for i, ti in enumerate(log.t) if ti >= t0 - 1e-9]
    t = np.asarray([log.t[i] for i in keep], dtype=float) - t0
    robot = np.asarray([log.robot[i] for i in keep], dtype=float).reshape(-1, 4)
    humans = {h: [xy[i] for i in keep if i < len(xy)] for h, xy in log.humans.items()}
    # In stamp order: a recorder may receive some events late (kept for it by their publishers).
    events = sorted((replace(e, stamp=e.stamp - t0) for e in log.events if e.stamp >= t0 - 1e-9), key=lambda e: e.stamp)
    battery = [log.battery[i] for i in keep]
    bubble_log = [log.bubble[i] for i in keep]
    signal_log = [log.signal[i] for i in keep]
    end_t = float(t[-1]) if len(t) else 0.0
    m: dict[str, Any] = {"scenario": scenario, "end_reason": end_reason, "duration_s": round(end_t, 2)}
    robot_done = _first(events, EventKind.TASK_DONE, by="robot")
    m["robot_time_to_finish_s"] = None if robot_done is None else round(robot_done, 2)
    m["robot_path_length_m"] = round(_path_length(robot[:, :2]), 3)
    dmin = math.inf
    for hid, xy in humans.items():
        h = np.asarray(xy, dtype=float).reshape(-1, 2)
        done = _first(events, EventKind.TASK_DONE, by=hid)
        m[f"{hid}_time_to_finish_s"] = None if done is None else round(done, 2)
        m[f"{hid}_path_length_m"] = round(_path_length(h), 3)
        d = np.hypot(h[:, 0] - robot[: len(h), 0], h[:, 1] - robot[: len(h), 1])
        dmin = min(dmin, float(d.min()) if len(d) else math.inf)
        dt = np.diff(t[: len(d)], append=t[len(d) - 1] if len(d) else 0.0)
        for zone, r in ZONES.items():
            inside = d < r
            m[f"{hid}_{zone}_intrusion_s"] = round(float(np.sum(dt[inside])), 2)
            m[f"{hid}_{zone}_intrusions"] = int(np.sum(inside[1:] & ~inside[:-1]) + (1 if len(inside) and inside[0] else 0))
    m["min_human_distance_m"] = None if math.isinf(dmin) else round(dmin, 3)
    contacts = [e for e in events if e.kind is EventKind.CONTACT_BEGIN]
    m["human_contacts"] = sum(1 for e in contacts if str(e["other"]).startswith("human"))
    m["wall_contacts"] = sum(1 for e in contacts if e["other"] == "wall")
    waits = _intervals(events, EventKind.WAITING, {EventKind.RESUMED, EventKind.PLAN_MADE, EventKind.REPLANNED}, end_t)
    m["waits"] = len(waits)
    m["wait_time_s"] = round(sum(b - a for a, b in waits), 2)
    m["replans"] = _count(events, EventKind.REPLANNED)
    m["reverts"] = _count(events, EventKind.REVERTED)
    m["plans_refused"] = _count(events, EventKind.PLAN_REFUSED)
    levels = np.asarray(battery, dtype=float)
    m["battery_used"] = round(float(np.sum(np.clip(-np.diff(levels), 0, None))), 4) if len(levels) > 1 else 0.0
    m["battery_final"] = round(float(levels[-1]), 4) if len(levels) else None
    m["charge_trips"] = _count(events, EventKind.CHARGE_TRIP)
    collected = [e for e in events if e.kind is EventKind.GEM_COLLECTED]
    m["gems_robot"] = sum(1 for e in collected if e["by"] == "robot")
    m["gems_human"] = sum(1 for e in collected if e["by"] != "robot")
    m["robot_gem_order"] = " ".join(str(e["gem"]) for e in collected if e["by"] == "robot")
    dt_all = np.diff(t, append=t[-1]) if len(t) else np.zeros(0)
    m["thought_bubble_shown_s"] = round(float(np.sum(dt_all[np.asarray(bubble_log, dtype=bool)])), 2) if len(t) else 0.0
    leads = signal_lead_times(t, robot[:, 3], signal_log) if len(t) else []
    m["turns"] = len(leads)
    m["turn_signal_lead_s_mean"] = round(float(np.mean(leads)), 3) if leads else None
    m["turns_signalled"] = sum(1 for x in leads if x > 0)
    return m
