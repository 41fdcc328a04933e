"""2-D laser scanner by vectorised ray casting (numpy) against wall edges and human circles.

Readings follow REP-117: +inf for no return within range_max, -inf for a return nearer than range_min.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from haven_sim.common.geometry import FloatArray, Pose2D
from haven_sim.common.params import NOT_NEGATIVE, config, param
from haven_sim.robots.fields import from_robot


@config
class ScanParams:
    # The robot's lidar (robot file: lidar): beams over 360 degrees, nearer than range_min reads -inf
    # and nothing within range_max +inf (REP-117), at rate_hz of sim time.
    beams: int = from_robot("lidar.beams")
    range_min_m: float = from_robot("lidar.range_min_m")
    range_max_m: float = from_robot("lidar.range_max_m")
    rate_hz: float = from_robot("lidar.rate_hz")
    noise_std_m: float = param(0.0, "Gaussian range noise", NOT_NEGATIVE)

    def __post_init__(self) -> None:
        if not self.range_min_m < self.range_max_m:
            raise ValueError(
                f"scan_range_min_m must be less than scan_range_max_m, got {self.range_min_m} and {self.range_max_m}"
            )

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
    covers a contiguous run of beams, so only those (beam, object) pairs are intersected.

    Edges must come from counter-clockwise polygons, as `World.edges()` gives them: a ray enters a
    solid only through an edge that faces the scanner. Candidate edges are looked up in a grid of
    range_max-sized cells (built lazily), so large maps cost no more per scan than small ones.
    """

    def __init__(self, params: ScanParams, edges: FloatArray, seed: int | None = None) -> None:
        self.params = params
        angles = params.angle_min + params.angle_increment * np.arange(params.beams)
        # Beam directions in the scanner frame, repeated once for runs that wrap past angle_max.
        self._cos2 = np.tile(np.cos(angles), 2)
        self._sin2 = np.tile(np.sin(angles), 2)
        self._inv_inc = 1.0 / params.angle_increment
        self._count = np.arange(params.beams + 1)
        self._ring = np.empty(2 * params.beams)
        self._rng = np.random.default_rng(seed)
        self.set_edges(edges)

    def set_edges(self, edges: FloatArray) -> None:
        e = np.asarray(edges, dtype=float).reshape(-1, 4)
        self._edges = e
        self._lo = np.minimum(e[:, 0:2], e[:, 2:4])
        self._hi = np.maximum(e[:, 0:2], e[:, 2:4])
        self._cells: dict[tuple[int, int], tuple[npt.NDArray[Any], ...]] = {}

    def _candidates(self, x: float, y: float) -> tuple[npt.NDArray[Any], ...]:
        """Edges that can be within range_max of any point of the cell holding (x, y)."""
        size = self.params.range_max_m
        key = (math.floor(x / size), math.floor(y / size))
        cell = self._cells.get(key)
        if cell is None:
            x0, y0 = key[0] * size - size, key[1] * size - size
            x1, y1 = x0 + 3 * size, y0 + 3 * size
            near = (self._lo[:, 0] <= x1) & (self._hi[:, 0] >= x0) & (self._lo[:, 1] <= y1) & (self._hi[:, 1] >= y0)
            e = self._edges[near]
            a = e[:, 0] + 1j * e[:, 1]
            b = e[:, 2] + 1j * e[:, 3]
            # Per edge, as complex numbers: end points, the conjugate unit direction, and the
            # angle of the inward normal (to the left of a counter-clockwise edge).
            cell = (a, b, np.conj(b - a) / np.abs(b - a), np.angle(1j * (b - a)))
            self._cells[key] = cell
        return cell

    def _runs(
        self, start: FloatArray, sweep: FloatArray, skip: npt.NDArray[np.bool_] | None
    ) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp]]:
        """(beam, object) pairs for every beam whose index (a float: beam steps from beam 0) lies in
        [start, start + sweep]; start >= 0. Beams index a doubled ring (0 .. 2 * beams) so a run
        crossing angle_max needs no wrap-around."""
        k0 = (start + (1.0 - 1e-9)).astype(np.intp)  # ceil, for start >= 0
        counts = (start + sweep + (1.0 + 1e-9)).astype(np.intp) - k0  # floor(end) - ceil(start) + 1 >= 0
        if skip is not None:
            counts[skip] = 0
        lanes = self._count[: counts.max()] if len(counts) else self._count[:0]
        owner, offset = np.nonzero(lanes < counts[:, None])
        return k0[owner] + offset, owner

    def scan(
        self, pose: Pose2D, circles: Sequence[tuple[float, float, float]] | FloatArray | None = None
    ) -> FloatArray:
        """Ranges for a scanner at `pose`; circles are (x, y, radius) of other bodies."""
        p = self.params
        rmax = p.range_max_m
        two_pi = 2.0 * math.pi
        ring = self._ring
        ring.fill(np.inf)
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        base = pose.yaw + p.angle_min  # world angle of beam 0
        cos2, sin2, inv_inc = self._cos2, self._sin2, self._inv_inc

        a, b, conj_unit, inward = self._candidates(pose.x, pose.y)
        if len(a):
            here = complex(pose.x, pose.y)
            za, zb = a - here, b - here
            # Distance from the scanner to each edge's line, positive on the edge's outer side:
            # only those edges face the scanner, and from there b -> a runs counter-clockwise.
            h = (za * conj_unit).imag
            fa = np.arctan2(za.imag, za.real) * inv_inc  # angles in beam steps
            fb = np.arctan2(zb.imag, zb.real) * inv_inc
            start = np.mod(fb - base * inv_inc, p.beams)
            beams, owner = self._runs(start, np.mod(fa - fb, p.beams), h < 1e-12)
            if len(beams):
                # A beam at world angle phi meets the line at h / cos(phi - inward normal angle).
                t = h[owner] / np.cos(beams * p.angle_increment + (base - inward)[owner])
                np.minimum.at(ring, beams, t)

        if circles is not None and len(circles):
            # Few people are ever in range: pick them out in plain Python before going to numpy.
            seen = []
            for cx, cy, cr in circles:
                dx, dy = cx - pose.x, cy - pose.y
                d = math.hypot(dx, dy)
                if cr < d <= rmax + cr:
                    seen.append((c * dx + s * dy, c * dy - s * dx, cr, d))  # centre in the scanner frame
            if seen:
                lx, ly, r, dist = np.array(seen).T
                half = np.arcsin(r / dist)
                start = np.mod(np.arctan2(ly, lx) - half - p.angle_min, two_pi) * inv_inc
                beams, owner = self._runs(start, 2.0 * half * inv_inc, None)
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
