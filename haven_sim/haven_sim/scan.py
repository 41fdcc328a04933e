"""2-D laser scanner by vectorised ray casting (numpy) against wall edges and human circles.

Readings follow REP-117: +inf for no return within range_max, -inf for a return nearer than range_min.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from haven_sim.geometry import FloatArray, Pose2D


@dataclass(frozen=True)
class ScanParams:
    beams: int = 360
    range_min_m: float = 0.12
    range_max_m: float = 3.5
    rate_hz: float = 10.0
    noise_std_m: float = 0.0

    @property
    def angle_min(self) -> float:
        return -math.pi

    @property
    def angle_increment(self) -> float:
        return 2.0 * math.pi / self.beams

    @property
    def angle_max(self) -> float:
        return self.angle_min + self.angle_increment * (self.beams - 1)


class LaserScanner:
    """Ray casting by angular intervals: each wall edge facing the scanner, and each human circle,
    covers a contiguous run of beams, so only those (beam, object) pairs are intersected. Edges must
    come from counter-clockwise polygons, as `World.edges()` gives them: a ray enters a solid only
    through an edge that faces the scanner."""

    def __init__(self, params: ScanParams, edges: FloatArray, seed: int | None = None) -> None:
        self.params = params
        angles = params.angle_min + params.angle_increment * np.arange(params.beams)
        # Beam directions in the scanner frame, repeated once for runs that wrap past angle_max.
        self._cos2 = np.tile(np.cos(angles), 2)
        self._sin2 = np.tile(np.sin(angles), 2)
        self._rng = np.random.default_rng(seed)
        self.set_edges(edges)

    def set_edges(self, edges: FloatArray) -> None:
        e = np.asarray(edges, dtype=float).reshape(-1, 4)
        self._a = e[:, 0:2].copy()
        self._b = e[:, 2:4].copy()
        self._xmin = np.minimum(e[:, 0], e[:, 2])
        self._xmax = np.maximum(e[:, 0], e[:, 2])
        self._ymin = np.minimum(e[:, 1], e[:, 3])
        self._ymax = np.maximum(e[:, 1], e[:, 3])

    def _beam_runs(self, start: FloatArray, sweep: FloatArray) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
        """(beam, object) pairs for every beam whose angle lies in [start, start + sweep], as indices
        into a doubled ring of 2 * beams so that runs crossing angle_max need no wrap-around."""
        p = self.params
        f0 = np.mod(start - p.angle_min, 2.0 * np.pi) / p.angle_increment
        k0 = np.ceil(f0 - 1e-9).astype(np.intp)
        counts = np.floor(f0 + sweep / p.angle_increment + 1e-9).astype(np.intp) - k0 + 1
        np.maximum(counts, 0, out=counts)
        owner = np.repeat(np.arange(len(start)), counts)
        beams = np.arange(len(owner)) + np.repeat(k0 - np.cumsum(counts) + counts, counts)
        return beams, owner

    def scan(self, pose: Pose2D, circles: FloatArray | None = None) -> FloatArray:
        """Ranges for a scanner at `pose`; circles are rows (x, y, radius) of other bodies."""
        p = self.params
        rmax = p.range_max_m
        ring = np.full(2 * p.beams, np.inf)
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        cos2, sin2 = self._cos2, self._sin2

        # Edges in the scanner frame; keep those facing the scanner whose bounding box is within range.
        near = (self._xmin <= pose.x + rmax) & (self._xmax >= pose.x - rmax)
        near &= (self._ymin <= pose.y + rmax) & (self._ymax >= pose.y - rmax)
        a = self._a[near] - (pose.x, pose.y)
        b = self._b[near] - (pose.x, pose.y)
        ax, ay = c * a[:, 0] + s * a[:, 1], c * a[:, 1] - s * a[:, 0]
        bx, by = c * b[:, 0] + s * b[:, 1], c * b[:, 1] - s * b[:, 0]
        ex, ey = bx - ax, by - ay
        cross = ax * ey - ay * ex  # < 0: the scanner sees the edge's outer side; b -> a runs counter-clockwise
        front = cross < -1e-12
        if front.any():
            ax, ay, bx, by, ex, ey, cross = ax[front], ay[front], bx[front], by[front], ex[front], ey[front], cross[front]
            start = np.arctan2(by, bx)
            sweep = np.mod(np.arctan2(ay, ax) - start, 2.0 * np.pi)
            beams, owner = self._beam_runs(start, sweep)
            t = cross[owner] / (cos2[beams] * ey[owner] - sin2[beams] * ex[owner])
            np.minimum.at(ring, beams, t)

        if circles is not None and len(circles):
            cc = np.asarray(circles, dtype=float).reshape(-1, 3)
            mx, my, r = cc[:, 0] - pose.x, cc[:, 1] - pose.y, cc[:, 2]
            dist = np.hypot(mx, my)
            seen = (dist > r) & (dist - r <= rmax)
            if seen.any():
                mx, my, r, dist = mx[seen], my[seen], r[seen], dist[seen]
                lx, ly = c * mx + s * my, c * my - s * mx
                half = np.arcsin(r / dist)
                beams, owner = self._beam_runs(np.arctan2(ly, lx) - half, 2.0 * half)
                proj = cos2[beams] * lx[owner] + sin2[beams] * ly[owner]
                disc = np.maximum(proj * proj - (dist[owner] ** 2 - r[owner] ** 2), 0.0)
                np.minimum.at(ring, beams, proj - np.sqrt(disc))

        ranges: FloatArray = np.minimum(ring[: p.beams], ring[p.beams :])
        if p.noise_std_m > 0.0:
            finite = np.isfinite(ranges)
            ranges[finite] += self._rng.normal(0.0, p.noise_std_m, int(finite.sum()))
        ranges[ranges > rmax] = np.inf
        ranges[ranges < p.range_min_m] = -np.inf
        return ranges
