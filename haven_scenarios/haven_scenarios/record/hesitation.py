"""Hesitation: a person walking their task slows well below their own walking speed.

On the metrics' grid, a person's speed is taken over a centred `SMOOTH_S` window (the step-to-step
speed of interpolated poses is jumpy). Their own walking speed is the `CRUISE_PERCENTILE`th
percentile of that speed while they move (a person who hesitates often still cruises most of the
way). They walk their task from the moment they first reach `SLOW_FRACTION` of it until their task
is done (or the trial ends), except within `STOP_NEAR_M` of a place where one of their task steps
counted (a gem they stood on, a room centre they reached: slowing there is the task, not hesitation).
A hesitation is a stretch of at least `MIN_S` of that walk below `SLOW_FRACTION` of their own speed,
standing still included. (Speed drops as a sign of hesitation in front of a robot: Vassallo et al.
2017; the 0.5 s minimum is ours.)

`SLOW_FRACTION` 0.7 is ours too, fixed without reference to any participant model: a drop of 30 % of
one's own walking speed is well beyond ordinary pace variation (the spread of comfortable walking
speed between adults is a coefficient of variation of about 0.11, Bohannon 1997, Age and Ageing
26:15-19, so 30 % is more than twice that). It is deliberately not the simulated participants'
slowdown (`study.person.PersonParams.hesitate_factor`, a random effect centred on 0.5): a metric
whose threshold equals a model parameter measures the parameter, not the people.
"""

from __future__ import annotations

import numpy as np

from haven_sim.common.geometry import FloatArray

SMOOTH_S = 0.5
CRUISE_PERCENTILE = 75.0
SLOW_FRACTION = 0.7
MIN_S = 0.5
STOP_NEAR_M = 0.5
MOVING_MPS = 0.05


def smoothed_speed(t: FloatArray, xy: FloatArray, window_s: float = SMOOTH_S) -> FloatArray:
    """Speed at each grid time over a centred window (shortened at the ends)."""
    n = len(t)
    if n < 2:
        return np.zeros(n)
    half = max(1, round(window_s / 2.0 / max(float(np.median(np.diff(t))), 1e-9)))
    lo, hi = np.clip(np.arange(n) - half, 0, n - 1), np.clip(np.arange(n) + half, 0, n - 1)
    return np.asarray(np.hypot(*(xy[hi] - xy[lo]).T) / np.maximum(t[hi] - t[lo], 1e-9))


def hesitations(t: FloatArray, xy: FloatArray, stops: FloatArray, done_at: float | None) -> tuple[int, float]:
    """(episodes, seconds) of hesitation; `stops` (K, 2): where the person's task steps counted."""
    speed = smoothed_speed(t, xy)
    moving = speed >= MOVING_MPS
    if not moving.any():
        return 0, 0.0
    slow = speed < SLOW_FRACTION * float(np.percentile(speed[moving], CRUISE_PERCENTILE))
    walking = np.zeros(len(t), dtype=bool)
    started = np.flatnonzero(~slow)
    if len(started):
        walking[started[0] :] = True
    if done_at is not None:
        walking &= t <= done_at
    stops = np.asarray(stops, dtype=float).reshape(-1, 2)
    if len(stops):
        near = (
            np.min(np.hypot(xy[:, None, 0] - stops[None, :, 0], xy[:, None, 1] - stops[None, :, 1]), axis=1)
            < STOP_NEAR_M
        )
        walking &= ~near
    run = np.concatenate([[False], walking & slow, [False]]).astype(np.int8)
    edges = np.flatnonzero(np.diff(run))
    starts, ends = edges[::2], edges[1::2]  # [start, end) index ranges of slow walking
    lengths = t[np.minimum(ends, len(t) - 1)] - t[starts]
    kept = lengths >= MIN_S - 1e-9
    return int(np.sum(kept)), float(np.sum(lengths[kept]))
