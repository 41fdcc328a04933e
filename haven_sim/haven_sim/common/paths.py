"""Reading any planner's path as HAVEN's rotate / arc / straight segments, from its geometry.

Our planner writes /plan in a convention (rotations in place as poses at one position with changing
yaw; arcs and straights sampled along the way); Nav2's planners do not: NavFn gives 5 cm poses with
identity orientations and the goal yaw on the last one, Smac noisy headings, ThetaStar straight legs
that meet at sharp corners. `read_path` reads them all the same way, from positions:

  * poses at one position with changing yaw: a rotation in place (the only thing yaws say mid-path);
  * the travel heading along the way, read from chords `SMOOTHING_M` long (so grid wiggle and
    jitter average out), turning faster than `MIN_ARC_CURVATURE` (radius under 2 m): an arc;
  * a turn packed into a corner (tighter than `CORNER_RADIUS_M`): an arc when HAVEN's motion style
    would drive it as one (up to its 60 deg), else a rotation in place at the corner;
  * the rest: straight;
  * a last pose whose yaw differs from the arrival heading by more than the style's facing
    tolerance: a final rotation to it (the goal yaw is honoured).

A path whose yaws agree with its geometry everywhere (ours: every step runs along the mean of its two
yaws) is read from the yaws as written. So the controller, the path projection's cubes and spheres
and the turn signals treat a swapped-in planner's path like ours.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum

import numpy as np

from haven_sim.common.geometry import FloatArray, Pose2D, wrap_angle

POSITION_EPS_M = 1e-3  # poses closer than this are at one position
YAW_EPS_RAD = math.radians(0.5)  # a smaller yaw change in place is no rotation
SMOOTHING_M = 0.3  # headings come from chords this long (NavFn's grid wiggle, noisy poses)
SAMPLE_M = 0.01  # the path is read at this spacing
MIN_ARC_CURVATURE = 0.5  # 1/m: turning faster than this (radius under 2 m) is an arc
CORNER_RADIUS_M = 0.1  # a turn tighter than this is a corner, not an arc
CONVENTION_SHARE = 0.9  # of steps whose yaws agree with the geometry, for a path to be read from its yaws


class SegmentKind(Enum):
    ROTATE = "rotate"
    ARC = "arc"
    STRAIGHT = "straight"


@dataclass(frozen=True)
class Segment:
    kind: SegmentKind
    start: int  # index of the first pose
    end: int  # index of the last pose (inclusive; a rotation at one pose has start == end)
    yaw: float = math.nan  # a rotation's final yaw


@dataclass(frozen=True)
class PathReading:
    segments: list[Segment]
    arcs: list[tuple[float, float]]  # where the path is an arc: (from, to) in arc length along it
    # per step (pose k to k+1): the travel heading (a step in place: the travel's before it, else after)
    headings: FloatArray


def read_path(poses: Sequence[Pose2D], rotate_above_rad: float, goal_tolerance_rad: float) -> PathReading:
    """The segments, arcs and travel headings of any pose list (ours or another planner's), for
    HAVEN's motion style (nav/motion_style.py): corners sharper than `rotate_above_rad` are
    rotations; a goal yaw within `goal_tolerance_rad` of the arrival needs none."""
    n = len(poses)
    headings = np.full(max(0, n - 1), np.nan)
    if n < 2:
        return PathReading([], [], headings)
    xy = np.array([(p.x, p.y) for p in poses], dtype=float)
    d = np.diff(xy, axis=0)
    lengths = np.hypot(d[:, 0], d[:, 1])
    cum = np.concatenate([[0.0], np.cumsum(lengths)])
    chords = np.arctan2(d[:, 1], d[:, 0])
    moved = lengths > POSITION_EPS_M
    goal = poses[-1].yaw
    if moved[-1]:  # the last pose's yaw is the goal's, not a travel heading
        poses = [*poses[:-1], Pose2D(poses[-1].x, poses[-1].y, float(chords[-1]))]
    kinds: list[SegmentKind | None] = [None] * (n - 1)  # per step
    corners: dict[int, float] = {}  # pose index -> yaw of a rotation at a corner
    arcs: list[tuple[float, float]] = []
    for k in range(n - 1):
        if not moved[k] and abs(wrap_angle(poses[k + 1].yaw - poses[k].yaw)) > YAW_EPS_RAD:
            kinds[k] = SegmentKind.ROTATE
    if _in_our_convention(poses, chords, lengths > SAMPLE_M):  # read exactly as written
        for k in map(int, np.flatnonzero(moved)):
            turned = abs(wrap_angle(poses[k + 1].yaw - poses[k].yaw)) > YAW_EPS_RAD
            kinds[k] = SegmentKind.ARC if turned else SegmentKind.STRAIGHT
            headings[k] = chords[k]
            if turned:
                arcs.append((float(cum[k]), float(cum[k + 1])))
    else:
        k = 0
        while k < n - 1:  # runs of moving steps
            if not moved[k]:
                k += 1
                continue
            j = k
            while j + 1 < n - 1 and moved[j + 1]:
                j += 1
            run_arcs = _read_run(xy[k : j + 2], k, rotate_above_rad, headings, corners)
            arcs += [(float(cum[k]) + a, float(cum[k]) + b) for a, b in run_arcs]
            for i in range(k, j + 1):
                on_arc = any(min(cum[i + 1], b) - max(cum[i], a) > 1e-9 for a, b in arcs)
                kinds[i] = SegmentKind.ARC if on_arc else SegmentKind.STRAIGHT
            k = j + 1
    segments = _segments(poses, kinds, corners)
    final = _final_heading(segments, headings)
    _fill_in_place(headings)
    if math.isfinite(goal) and math.isfinite(final) and abs(wrap_angle(goal - final)) > goal_tolerance_rad:
        segments.append(Segment(SegmentKind.ROTATE, n - 1, n - 1, goal))
    return PathReading(segments, _merged(arcs), headings)


def _merged(spans: list[tuple[float, float]]) -> list[tuple[float, float]]:
    out: list[tuple[float, float]] = []
    for a, b in sorted(spans):
        if out and a <= out[-1][1] + 1e-9:
            out[-1] = (out[-1][0], max(out[-1][1], b))
        else:
            out.append((a, b))
    return out


def _in_our_convention(poses: Sequence[Pose2D], chords: FloatArray, long: np.ndarray) -> bool:
    """The yaws agree with the path's geometry: nearly every step runs along the mean of its two
    yaws (true of straights and of circular arcs sampled at any spacing), as our planner writes;
    only where it bends a straight by less than its straight tolerance does a yaw jump. (Steps
    shorter than SAMPLE_M have no reliable heading of their own.)"""
    steps = [int(k) for k in np.flatnonzero(long)]
    agree = sum(
        abs(wrap_angle(float(chords[k]) - poses[k].yaw - 0.5 * wrap_angle(poses[k + 1].yaw - poses[k].yaw)))
        <= YAW_EPS_RAD
        for k in steps
    )
    return agree >= CONVENTION_SHARE * len(steps)


def _read_run(
    xy: FloatArray, offset: int, rotate_above: float, headings: FloatArray, corners: dict[int, float]
) -> list[tuple[float, float]]:
    """Steps offset .. offset+len(xy)-2 all move: their headings, the corners to rotate at, and the
    arcs (from, to along the run; a corner driven as an arc spans the chords around it)."""
    cum = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(xy, axis=0).T))])
    length = float(cum[-1])
    s = np.linspace(0.0, length, max(2, math.ceil(length / SAMPLE_M) + 1))
    pts = np.column_stack([np.interp(s, cum, xy[:, 0]), np.interp(s, cum, xy[:, 1])])
    w = max(1, round(SMOOTHING_M / (s[1] - s[0])))  # the chord length, in samples
    i = np.arange(len(s))

    def chord(a: np.ndarray, b: np.ndarray) -> FloatArray:
        """Heading of the chord between samples a and b (clamped to the run)."""
        a, b = np.clip(a, 0, len(s) - 1), np.clip(b, 0, len(s) - 1)
        same = a == b
        a, b = np.where(same, np.maximum(a - 1, 0), a), np.where(same, np.minimum(b + 1, len(s) - 1), b)
        d = pts[b] - pts[a]
        out: FloatArray = np.arctan2(d[:, 1], d[:, 0])
        return out

    heading = chord(i - w // 2, i + w // 2)  # the travel heading, averaged over a chord
    turn = np.array([wrap_angle(float(t)) for t in chord(i, i + w) - chord(i - w, i)])  # per sample
    step_mid = 0.5 * (cum[:-1] + cum[1:])
    headings[offset : offset + len(step_mid)] = heading[
        np.clip(np.round(step_mid / (s[1] - s[0])).astype(int), 0, len(s) - 1)
    ]
    arcs: list[tuple[float, float]] = []
    threshold = MIN_ARC_CURVATURE * w * (s[1] - s[0])
    sign = np.where(np.abs(turn) > threshold, np.sign(turn), 0.0)
    k = 0
    while k < len(s):  # stretches that turn one way
        if sign[k] == 0:
            k += 1
            continue
        j = k
        while j + 1 < len(s) and sign[j + 1] == sign[k]:
            j += 1
        total = wrap_angle(
            float(chord(np.array([j]), np.array([j + w]))[0] - chord(np.array([k - w]), np.array([k]))[0])
        )
        a, b = _turn_extent(
            s[k],
            s[j],
            k == 0,
            j == len(s) - 1,
            abs(total),
            float(np.max(np.abs(turn[k : j + 1]))),
            w * (s[1] - s[0]),
            threshold,
        )
        if b - a < CORNER_RADIUS_M * abs(total) and abs(total) > rotate_above:
            at = int(np.argmin(np.abs(cum - 0.5 * (a + b))))
            corners[offset + at] = wrap_angle(float(chord(np.array([j]), np.array([j + w]))[0]))
        elif b - a < CORNER_RADIUS_M * abs(total):
            c = 0.5 * (a + b)
            arcs.append((max(0.0, c - SMOOTHING_M / 2), min(length, c + SMOOTHING_M / 2)))
        else:
            arcs.append((float(a), float(b)))
        k = j + 1
    return arcs


def _turn_extent(
    lo: float, hi: float, at_start: bool, at_end: bool, total: float, peak: float, chord: float, threshold: float
) -> tuple[float, float]:
    """Where a turn lies, from the stretch [lo, hi] where the chords' turn exceeds `threshold`.

    The chords see a turn before it begins: by `d` ahead of an arc of curvature k the turn is
    k (chord - d)^2 / (2 chord), so the stretch reaches chord - sqrt(2 chord threshold / k) beyond
    each end, and an arc of length L that turns by `total` (k = total / L) gives a stretch
    L + 2 (chord - sqrt(2 chord threshold L / total)) long: solved here for L, centred on the
    stretch. A corner (L = 0) reads as a tiny arc. At the start or end of a run the turn may begin
    right there, and its other end is found from the peak (a long arc's: k chord)."""
    if at_start or at_end:
        k = max(peak / chord, 1e-9)
        reach = max(0.0, chord - math.sqrt(2.0 * chord * threshold / k))
        return (lo if at_start else lo + reach), (hi if at_end else hi - reach)
    q = math.sqrt(2.0 * chord * threshold / max(total, 1e-9))
    disc = q * q - (2.0 * chord - (hi - lo))
    length = (q + math.sqrt(disc)) ** 2 if disc > 0 else 0.0
    centre = 0.5 * (lo + hi)
    return centre - 0.5 * length, centre + 0.5 * length


def _segments(poses: Sequence[Pose2D], kinds: list[SegmentKind | None], corners: dict[int, float]) -> list[Segment]:
    segments: list[Segment] = []

    def add(kind: SegmentKind, start: int, end: int, yaw: float = math.nan) -> None:
        last = segments[-1] if segments else None
        if last is not None and last.kind is kind and last.end == start:
            segments[-1] = Segment(kind, last.start, end, yaw)
        else:
            segments.append(Segment(kind, start, end, yaw))

    for i, kind in enumerate(kinds):
        if i in corners:
            add(SegmentKind.ROTATE, i, i, corners[i])
        if kind is SegmentKind.ROTATE:
            add(kind, i, i + 1, poses[i + 1].yaw)
        elif kind is not None:
            add(kind, i, i + 1)
    return segments


def _final_heading(segments: list[Segment], headings: FloatArray) -> float:
    """The heading the path arrives with: its last rotation's yaw, or its last travel heading."""
    last = segments[-1] if segments else None
    if last is None:
        return math.nan
    if last.kind is SegmentKind.ROTATE:
        return last.yaw
    moving = np.flatnonzero(np.isfinite(headings))
    return float(headings[moving[-1]]) if len(moving) else math.nan


def _fill_in_place(headings: FloatArray) -> None:
    """Steps in place take the heading of the travel before them (after them, at the start)."""
    known = np.flatnonzero(np.isfinite(headings))
    if len(known) == 0:
        headings[:] = 0.0
        return
    before = np.maximum.accumulate(np.where(np.isfinite(headings), np.arange(len(headings)), -1))
    headings[:] = headings[np.where(before >= 0, before, known[0])]
