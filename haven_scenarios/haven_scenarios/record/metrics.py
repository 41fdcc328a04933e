"""Trial metrics from a `Recording`: the same code for a bag read back and for a batch trial.

Every metric is defined in `metric_table` (name, unit, definition, source). Each group of them is a
plugin of kind `metrics`, as a lab's own metric is (`TrialData` in, columns out). Ours are computed on the
trial's own timeline (`timeline.Timeline`): header stamps, one grid, exactly [trial_start,
trial_end]; HuNavSim's (`hunav`, record/hunav.py) on its own samples, as its evaluator takes them.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from haven_scenarios.record.contacts import PERSON_ON_ROBOT, ROBOT_ON_PERSON, attribute, episodes
from haven_scenarios.record.hesitation import hesitations
from haven_scenarios.record.metric_kind import TrialData, rounded
from haven_scenarios.record.metric_table import ZONES
from haven_scenarios.record.timeline import Recording, Timeline
from haven_scenarios.study.participants import HUMAN_PLANNER
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.events import Event, EventKind
from haven_sim.common.geometry import FloatArray, wrap_angle
from haven_sim.nav.planner import GridPlanner, PlanningError
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import World
from haven_viz.cues import CUE_SPECS, cues_for

TURN_RATE_RPS = 0.3  # |angular velocity| above this is a turn
# The robot is not moving: |v| and |w| below these (ours; HuNavSim's time_not_moving compares the
# signed v < 0.01 m/s and w < 0.02 rad/s, see record/hunav.py).
STILL_MPS, STILL_RPS = 0.01, 0.01
PERSON_STILL_MPS = 0.05


def _length(xy: FloatArray) -> float:
    return float(np.sum(np.hypot(*np.diff(xy, axis=0).T))) if len(xy) > 1 else 0.0


def robot(d: TrialData) -> dict[str, Any]:
    return _robot(d.tl, d.events)


def navigation(d: TrialData) -> dict[str, Any]:
    return _navigation(d.tl, d.events, d.rec, d.t0, d.t1)


def proximity(d: TrialData) -> dict[str, Any]:
    return _proximity(d.tl, d.robot.radius_m)


def contacts(d: TrialData) -> dict[str, Any]:
    return _contacts(d.tl, d.rec.events, d.t0, d.t1)


def mission(d: TrialData) -> dict[str, Any]:
    return _mission(d.tl, d.events)


def cues(d: TrialData) -> dict[str, Any]:
    return _cues(d.tl, cues_for(d.robot.kinematics))


def passes(d: TrialData) -> dict[str, Any]:
    return _passes(d.tl, d.events)


def people(d: TrialData) -> dict[str, Any]:
    """Every person's own columns (`<h>_...`)."""
    out: dict[str, Any] = {}
    for hid in d.tl.humans:
        out.update(_person(hid, d.tl, d.events, d.world, d.rec))
    return out


def _first(events: Sequence[Event], kind: EventKind, **match: Any) -> float | None:
    return next((e.stamp for e in events if e.kind is kind and all(e.get(k) == v for k, v in match.items())), None)


def _count(events: Sequence[Event], kind: EventKind) -> int:
    return sum(1 for e in events if e.kind is kind)


def _robot(tl: Timeline, events: Sequence[Event]) -> dict[str, Any]:
    dt, v, w = tl.dt, tl.robot_v, tl.robot_w
    step = np.diff(tl.t) if len(tl.t) > 1 else np.ones(0)
    accel = np.diff(v) / step if len(v) > 1 else np.zeros(0)
    jerk = np.diff(accel) / step[1:] if len(accel) > 1 else np.zeros(0)
    still = (np.abs(v) < STILL_MPS) & (np.abs(w) < STILL_RPS)
    return {
        "robot_time_to_finish_s": rounded(_first(events, EventKind.TASK_DONE, by="robot"), 2),
        "robot_path_length_m": rounded(_length(tl.robot_xy)),
        "robot_time_not_moving_s": rounded(float(np.sum(dt[still])), 2),
        "robot_speed_mean_mps": rounded(float(np.mean(np.abs(v))) if len(v) else None),
        "robot_speed_max_mps": rounded(float(np.max(np.abs(v))) if len(v) else None),
        "robot_accel_mean_mps2": rounded(float(np.mean(np.abs(accel))) if len(accel) else None),
        "robot_accel_max_mps2": rounded(float(np.max(np.abs(accel))) if len(accel) else None),
        "robot_jerk_mean_mps3": rounded(float(np.mean(np.abs(jerk))) if len(jerk) else None, 2),
        "cumulative_heading_change_rad": rounded(_heading_change(tl.robot_yaw)),
    }


def _heading_change(yaw: FloatArray) -> float:
    """Sum of |heading changes|, each wrapped to [-pi, pi) (a yaw read as +pi then -pi turned 0)."""
    return float(np.sum(np.abs((np.diff(yaw) + math.pi) % (2.0 * math.pi) - math.pi))) if len(yaw) > 1 else 0.0


def _turning(poses: Sequence[Any]) -> float:
    return sum(
        abs(wrap_angle(b.yaw - a.yaw))
        for a, b in itertools.pairwise(poses)
        if math.isfinite(a.yaw) and math.isfinite(b.yaw)
    )


def _navigation(tl: Timeline, events: Sequence[Event], rec: Recording, t0: float, t1: float) -> dict[str, Any]:
    """Waits, re-plans, and how the driving compared with the plans (the first plan of each goal)."""
    waits: list[tuple[float, float]] = []
    since: float | None = None
    for e in events:
        if e.kind is EventKind.WAITING and since is None:
            since = e.stamp
        elif e.kind in (EventKind.RESUMED, EventKind.PLAN_MADE, EventKind.REPLANNED) and since is not None:
            waits.append((since, e.stamp))
            since = None
    if since is not None:
        waits.append((since, float(tl.t[-1])))
    made = [e.stamp for e in events if e.kind is EventKind.PLAN_MADE]
    planned = sum(float(e["length_m"]) for e in events if e.kind is EventKind.PLAN_MADE and "length_m" in e.data)
    driven = 0.0
    for a, b in zip(made, [*made[1:], float(tl.t[-1])], strict=False):  # (no plan made: nothing driven)
        sel = (tl.t >= a - 1e-9) & (tl.t <= b + 1e-9)
        driven += _length(tl.robot_xy[sel])
    plans = {round(s - t0, 4): p for s, p in rec.plans if t0 - 1e-9 <= s <= t1 + 1e-9}
    plan_turning = sum(_turning(plans[round(s, 4)]) for s in made if round(s, 4) in plans)
    turning = _heading_change(tl.robot_yaw)
    return {
        "waits": len(waits),
        "wait_time_s": rounded(sum(b - a for a, b in waits), 2),
        "replans": _count(events, EventKind.REPLANNED),
        "reverts": _count(events, EventKind.REVERTED),
        "plans_refused": _count(events, EventKind.PLAN_REFUSED),
        "path_efficiency": rounded(planned / driven if driven > 0 else None),
        "path_irregularity_rad": rounded(turning - plan_turning if made else None),
    }


def _distances(tl: Timeline) -> dict[str, FloatArray]:
    return {hid: np.hypot(*(xy - tl.robot_xy).T) for hid, xy in tl.humans.items()}


def _proximity(tl: Timeline, robot_radius_m: float) -> dict[str, Any]:
    d = _distances(tl)
    if not d:
        return {
            k: None
            for k in (
                "min_human_centre_distance_m",
                "min_human_surface_distance_m",
                "avg_closest_human_centre_distance_m",
            )
        }
    closest = np.nanmin(np.vstack(list(d.values())), axis=0)
    total = float(np.sum(tl.dt)) or 1.0
    bands = {
        "intimate": (0.0, ZONES["intimate"]),
        "personal": (ZONES["intimate"], ZONES["personal"]),
        "social": (ZONES["personal"], ZONES["social"]),
        "public": (ZONES["social"], math.inf),
    }
    out: dict[str, Any] = {
        "min_human_centre_distance_m": rounded(float(np.nanmin(closest))),
        "min_human_surface_distance_m": rounded(float(np.nanmin(closest)) - robot_radius_m - HUMAN_BODY.radius_m),
        "avg_closest_human_centre_distance_m": rounded(float(np.nanmean(closest))),
    }
    for name, (lo, hi) in bands.items():
        out[f"closest_{name}_centre_pct"] = rounded(
            100.0 * float(np.sum(tl.dt[(closest >= lo) & (closest < hi)])) / total, 1
        )
    return out


def _contacts(tl: Timeline, raw: Sequence[Event], t0: float, t1: float) -> dict[str, Any]:
    eps = [attribute(ep, tl) for ep in episodes(raw, t0, t1)]
    people = [ep for ep in eps if ep.other.startswith("human:")]
    out: dict[str, Any] = {
        "human_contacts": len(people),
        "human_contacts_robot_on_person": sum(1 for ep in people if ep.by == ROBOT_ON_PERSON),
        "human_contacts_person_on_robot": sum(1 for ep in people if ep.by == PERSON_ON_ROBOT),
        "wall_contacts": sum(1 for ep in eps if ep.other == "wall"),
    }
    for hid in tl.humans:
        mine = [ep for ep in people if ep.other == f"human:{hid}"]
        out[f"{hid}_contacts"] = len(mine)
        out[f"{hid}_contacts_robot_on_person"] = sum(1 for ep in mine if ep.by == ROBOT_ON_PERSON)
        out[f"{hid}_contacts_person_on_robot"] = sum(1 for ep in mine if ep.by == PERSON_ON_ROBOT)
    return out


def _mission(tl: Timeline, events: Sequence[Event]) -> dict[str, Any]:
    levels = tl.battery[np.isfinite(tl.battery)]
    collected = [e for e in events if e.kind is EventKind.GEM_COLLECTED]
    return {
        "battery_used": rounded(float(np.sum(np.clip(-np.diff(levels), 0, None))), 4) if len(levels) > 1 else 0.0,
        "battery_final": rounded(float(levels[-1]), 4) if len(levels) else None,
        "charge_trips": _count(events, EventKind.CHARGE_TRIP),
        "gems_robot": sum(1 for e in collected if e["by"] == "robot"),
        "gems_human": sum(1 for e in collected if e["by"] != "robot"),
        "robot_gem_order": " ".join(str(e["gem"]) for e in collected if e["by"] == "robot"),
    }


def _exposure(tl: Timeline, names: Sequence[str], sel: Any = slice(None)) -> dict[str, float]:
    dt, cues = (
        tl.dt[sel],
        tl.cues[sel] if isinstance(sel, slice) else [c for c, keep in zip(tl.cues, sel, strict=True) if keep],
    )
    # every registered cue the robot has
    shown = {CUE_SPECS[name].exposure: [c.shown(name) for c in cues] for name in names}
    return {k: round(float(np.sum(dt[np.asarray(v, dtype=bool)])), 2) for k, v in shown.items()}


def signal_lead_times(t: FloatArray, wz: FloatArray, signal: Sequence[int]) -> list[float]:
    """For each turn (|wz| rising above TURN_RATE_RPS), how long the matching turn signal had been
    lit when it began (0 if it was not lit)."""
    turning = np.abs(wz) > TURN_RATE_RPS
    sig = np.asarray(signal)
    return [_lit_for(t, sig, i, 1 if wz[i] > 0 else -1) for i in range(1, len(t)) if turning[i] and not turning[i - 1]]


def _lit_for(t: FloatArray, sig: Any, i: int, side: int) -> float:
    """How long the signal on `side` had been lit, without a break, when sample i began (0 if not)."""
    j = i
    while j > 0 and sig[j - 1] == side:
        j -= 1
    return float(t[i] - t[j])


def pass_signal_leads(
    t: FloatArray, wz: FloatArray, signal: Sequence[int], passes: Sequence[tuple[float, int]], within_s: float = 10.0
) -> list[float]:
    """For each pass (time of the re-plan, side +1 left / -1 right): how long the signal on that
    side had been lit when the robot began to turn that way (0 if it was not lit or never turned)."""
    sig = np.asarray(signal)
    leads = []
    for when, side in passes:
        i = int(np.searchsorted(t, when))
        lead = 0.0
        while i < len(t) and t[i] <= when + within_s:
            if wz[i] * side > TURN_RATE_RPS:
                lead = _lit_for(t, sig, i, side)
                break
            i += 1
        leads.append(lead)
    return leads


def _passes(tl: Timeline, events: Sequence[Event]) -> dict[str, Any]:
    """Figure 3: each re-plan around a person, whether its side's signal showed before the curve."""
    passes = [
        (e.stamp, 1 if e.get("side") == "left" else -1)
        for e in events
        if e.kind is EventKind.REPLANNED and e.get("side") in ("left", "right")
    ]
    leads = pass_signal_leads(tl.t, tl.robot_w, [c.turn_signal for c in tl.cues], passes) if len(tl.t) else []
    return {
        "passes": len(passes),
        "passes_signalled": sum(1 for x in leads if x > 0),
        "pass_signal_lead_s_median": rounded(float(np.median(leads)) if leads else None),
    }


def _cues(tl: Timeline, names: Sequence[str]) -> dict[str, Any]:
    out: dict[str, Any] = dict(_exposure(tl, names))
    leads = signal_lead_times(tl.t, tl.robot_w, [c.turn_signal for c in tl.cues])
    mean = rounded(float(np.mean(leads))) if leads else None
    out.update(turns=len(leads), turns_signalled=sum(1 for x in leads if x > 0), turn_signal_lead_s_mean=mean)
    segments, start = [], 0
    for i in range(1, len(tl.t) + 1):
        if i == len(tl.t) or tl.cues[i].toggles != tl.cues[start].toggles:
            on = [c for c in tl.cues[start].toggles.names_on() if c in names]
            sel = np.zeros(len(tl.t), dtype=bool)
            sel[start:i] = True
            segments.append(
                {
                    "start_s": round(float(tl.t[start]), 2),
                    "end_s": round(float(tl.t[i - 1]), 2),
                    "cues_on": on,
                    **_exposure(tl, names, sel),
                }
            )
            start = i
    out["condition_segments"] = segments
    return out


def _person(hid: str, tl: Timeline, events: Sequence[Event], world: World | None, rec: Recording) -> dict[str, Any]:
    xy, dt = tl.humans[hid], tl.dt
    speed = np.hypot(*np.diff(xy, axis=0).T) / np.maximum(np.diff(tl.t), 1e-9) if len(xy) > 1 else np.zeros(0)
    d = np.hypot(*(xy - tl.robot_xy).T)
    own = [e for e in events if e.get("by") == hid and e.kind in (EventKind.GEM_COLLECTED, EventKind.ROOM_REACHED)]
    done = _first(events, EventKind.TASK_DONE, by=hid)
    working = tl.t[:-1] < (done if done is not None else math.inf)  # standing counts until their task is done
    out: dict[str, Any] = {
        f"{hid}_time_to_finish_s": rounded(max([e.stamp for e in own], default=done) if done is not None else None, 2),
        f"{hid}_path_length_m": rounded(_length(xy)),
        f"{hid}_time_not_moving_s": rounded(
            float(np.sum(dt[:-1][(speed < PERSON_STILL_MPS) & working])) if len(speed) else 0.0, 2
        ),
        f"{hid}_detour_m": rounded(_detour(tl.t, xy, own, world)),
        f"{hid}_gems": sum(1 for e in own if e.kind is EventKind.GEM_COLLECTED),
        f"{hid}_min_centre_distance_m": rounded(float(np.min(d)) if len(d) else None),
    }
    at = [min(int(np.searchsorted(tl.t, e.stamp - 1e-9)), len(xy) - 1) for e in own]
    count, seconds = hesitations(tl.t, xy, xy[at] if at else np.zeros((0, 2)), done)
    out[f"{hid}_hesitations"], out[f"{hid}_hesitation_s"] = count, rounded(seconds, 2)
    previous = 0.0
    for zone, r in ZONES.items():
        inside = d < r
        out[f"{hid}_{zone}_centre_intrusion_s"] = round(float(np.sum(dt[inside])), 2)
        out[f"{hid}_{zone}_centre_intrusions"] = int(
            np.sum(inside[1:] & ~inside[:-1]) + (1 if len(inside) and inside[0] else 0)
        )
        out[f"{hid}_{zone}_centre_band_s"] = round(float(np.sum(dt[(d >= previous) & (d < r)])), 2)
        previous = r
    return out


def _detour(t: FloatArray, xy: FloatArray, own: Sequence[Event], world: World | None) -> float | None:
    """Walked length until the last task step (gem or room) minus the shortest walk, planned around
    the walls for a person's body, from the start through the places where the person stood when
    each step counted, in that order (a gem counts anywhere within its radius, so its centre would
    be the wrong reference)."""
    if world is None or not own or len(xy) < 2:
        return None
    walked = xy[t <= own[-1].stamp + 1e-9]
    at = [min(int(np.searchsorted(t, e.stamp - 1e-9)), len(xy) - 1) for e in own]
    points = [(float(xy[0, 0]), float(xy[0, 1]))] + [(float(xy[i, 0]), float(xy[i, 1])) for i in at]
    planner = GridPlanner(rasterise(world), HUMAN_PLANNER)
    try:
        shortest = sum(planner.plan(a, b).length_m for a, b in itertools.pairwise(points) if math.dist(a, b) > 1e-6)
    except PlanningError:
        return None
    return _length(walked) - shortest
