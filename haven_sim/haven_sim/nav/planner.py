"""Any-angle shortest paths on an occupancy grid, like the NavMesh paths HAVEN's robot followed.

The grid (ours from the world file, or any nav_msgs/OccupancyGrid) is inflated by the robot radius
plus a safety margin with a square kernel, which keeps axis-aligned walls axis-aligned. The convex
corners of the inflated obstacles are the nodes of a visibility graph; line of sight is tested by
sampling the inflated grid. All-pairs shortest paths between the nodes are computed once per map,
so a query only tests what the start and the goal can see and picks the best pair of nodes.

Bounded for any map the loader takes (up to 4,000 x 4,000 cells): the inflation and the corners are
linear in the cells; the graph is built at the first plan that needs it, and only while the node
pairs times the map's diagonal in half cells (`sight_work`, an upper bound on the grid samples the
line-of-sight tests take) is at most `MAX_SIGHT_WORK` and the nodes at most `MAX_PLANNER_NODES`;
past either, that plan is refused in one line (`graph_problem`), and `check_plannable` refuses such
a world where it is validated. Line of sight is tested `MAX_SIGHT_SAMPLES` samples at a time.
Measured (`bench/map_bounds.py`, 2026-12-01, 2 vCPUs at load ~4, each in its own process): at the
cap, 100 corners on a 100 m map at 0.025 m took 2.3 s to the first plan, 236 MB peak; 297 corners
on a 10 m one 1.9 s, 188 MB; the loader's largest pillar map (9,504 boxes, 38,000 corners) is
refused by the world check in 0.5 s, and a plan on it in 2 ms after 0.5 s of inflation (211 MB).
The shipped worlds have 4 to 36 corners (a few ms of sight work).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from enum import StrEnum
from typing import Protocol, overload

import numpy as np
import numpy.typing as npt

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import FloatArray, Point
from haven_sim.common.params import NOT_NEGATIVE, Bounds, config, param
from haven_sim.robots.fields import from_robot
from haven_sim.sim.occupancy import OccupancyGridData, rasterise
from haven_sim.sim.world import World, WorldError

BoolGrid = npt.NDArray[np.bool_]

MAX_PLANNER_NODES = 1000  # convex corners (Floyd-Warshall: N steps over N x N; ~20 MB at the cap)
MAX_SIGHT_WORK = 60_000_000  # corner pairs x the map's diagonal in half cells (`sight_work`): ~2 s, see above
MAX_SIGHT_SAMPLES = 2_000_000  # grid samples tested at a time for line of sight (~100 MB of temporaries)


@config
class PlannerParams:
    safety_margin_m: float = param(0.05, "added to the body radius when inflating the map", NOT_NEGATIVE)
    snap_radius_m: float = param(0.3, "a start or goal this close to free space is moved onto it", NOT_NEGATIVE)
    occupied_threshold: int = param(50, "map cells at or above this are obstacles", Bounds(1, 100))
    unknown_is_obstacle: bool = param(True, "map cells of -1 (unknown) are obstacles")
    # The body to plan for (not a parameter: the robot's footprint, or a participant for their walks).
    body_radius_m: float = from_robot("radius_m")

    @property
    def inflation_m(self) -> float:
        return self.body_radius_m + self.safety_margin_m


class PlanFailure(StrEnum):
    """Why a plan could not be made (the `failure` of a `plan_refused` event): the kinds Nav2's
    planner server reports (nav2_msgs/action/ComputePathToPose's error codes), so a Nav2 client
    is told the same."""

    START_OUTSIDE_MAP = "start_outside_map"
    GOAL_OUTSIDE_MAP = "goal_outside_map"
    START_OCCUPIED = "start_occupied"
    GOAL_OCCUPIED = "goal_occupied"
    NO_VALID_PATH = "no_valid_path"
    UNKNOWN = "unknown"  # (a lab's planner that failed otherwise)


class PlanningError(Exception):
    """A goal that cannot be reached; the message is the reason, for the user and the events."""

    def __init__(self, reason: str, failure: PlanFailure = PlanFailure.NO_VALID_PATH) -> None:
        super().__init__(reason)
        self.failure = failure


def sight_work(nodes: int, grid: OccupancyGridData) -> int:
    """An upper bound on the grid samples the visibility graph tests: every pair of nodes, each
    sampled every half cell over at most the map's diagonal."""
    return nodes * (nodes - 1) // 2 * (math.ceil(2.0 * math.hypot(grid.width, grid.height)) + 1)


def graph_problem(nodes: int, grid: OccupancyGridData, params: PlannerParams) -> str | None:
    """Why the visibility graph of a map with `nodes` corners is not built (one line), or None."""
    work = sight_work(nodes, grid)
    if nodes <= MAX_PLANNER_NODES and work <= MAX_SIGHT_WORK:
        return None
    return (
        f"the map has {nodes:,} corners for the built-in planner (obstacles inflated by {params.inflation_m:.2f} m), "
        f"more than it takes on a {grid.width * grid.resolution_m:g} m x {grid.height * grid.resolution_m:g} m map "
        f"(at most {MAX_PLANNER_NODES:,}, and corner pairs x the map's diagonal in half "
        f"cells at most {MAX_SIGHT_WORK:,}): merge small obstacles or use a coarser map"
    )


def inflate_square(occupied: BoolGrid, cells: int) -> BoolGrid:
    """Every cell within `cells` (Chebyshev distance) of an occupied cell."""
    out = occupied.copy()
    for axis in (0, 1):
        src = out.copy()
        for k in range(1, cells + 1):
            if axis == 0:
                out[k:, :] |= src[:-k, :]
                out[:-k, :] |= src[k:, :]
            else:
                out[:, k:] |= src[:, :-k]
                out[:, :-k] |= src[:, k:]
    return out


def convex_corners(blocked: BoolGrid) -> npt.NDArray[np.intp]:
    """(row, col) of free cells diagonally next to an obstacle corner that sticks out toward them."""
    h, w = blocked.shape
    pad = np.ones((h + 2, w + 2), dtype=bool)
    pad[1:-1, 1:-1] = blocked
    free = ~pad[1:-1, 1:-1]
    found = np.zeros((h, w), dtype=bool)
    for dr in (-1, 1):
        for dc in (-1, 1):
            diag = pad[1 + dr : h + 1 + dr, 1 + dc : w + 1 + dc]
            side_r = pad[1 + dr : h + 1 + dr, 1 : w + 1]
            side_c = pad[1 : h + 1, 1 + dc : w + 1 + dc]
            found |= free & diag & ~side_r & ~side_c
    return np.argwhere(found)


def inflated(grid: OccupancyGridData, params: PlannerParams) -> tuple[BoolGrid, int, BoolGrid]:
    """The map's obstacle cells, the inflation in cells, and the inflated obstacles."""
    occupied = grid.data >= params.occupied_threshold
    if params.unknown_is_obstacle:
        occupied |= grid.data < 0
    cells = math.ceil(params.inflation_m / grid.resolution_m)
    return occupied, cells, inflate_square(occupied, cells)


def check_plannable(world: World, source: str) -> None:
    """Refuse (WorldError, one line naming the world) a world whose map the built-in planner would
    not take, for the default robot's body or a person's: checked where a world is validated to run
    (`haven validate`, `world show`, `run`, `batch`, `sim`, scenario files), in linear time."""
    grid = rasterise(world)
    for params in (PlannerParams(), PlannerParams(body_radius_m=HUMAN_BODY.radius_m)):
        problem = graph_problem(len(convex_corners(inflated(grid, params)[2])), grid, params)
        if problem is not None:
            raise WorldError(f"{source}: world {world.name}: {problem}")


@dataclass(frozen=True)
class Plan:
    points: list[Point]  # start, corners..., goal (start/goal possibly snapped onto free space)
    length_m: float


class Planner(Protocol):
    """What the navigator, the mission executive and the simulated participants need of a planner."""

    def plan(self, start: Point, goal: Point) -> Plan: ...

    def is_free(self, x: float, y: float) -> bool: ...

    def hard_clear(self, pts: FloatArray) -> bool: ...

    @overload
    def free_run(self, start: Point, direction: Point, max_m: float = 10.0) -> float: ...

    @overload
    def free_run(self, start: Point, direction: FloatArray, max_m: float = 10.0) -> FloatArray: ...


class GridPlanner:
    """The visibility-graph planner (the default and only built-in `Planner`)."""

    def __init__(self, grid: OccupancyGridData, params: PlannerParams | None = None) -> None:
        self.grid = grid
        self.params = params or PlannerParams()
        self.occupied, self.cells, self.blocked = inflated(grid, self.params)
        # Without the safety margin: what the robot's body itself must not touch (for arcs).
        self.hard_blocked = inflate_square(self.occupied, math.ceil(self.params.body_radius_m / grid.resolution_m))
        rc = convex_corners(self.blocked)
        self.nodes = self._centres(rc)  # (N, 2) world coordinates
        self._step = grid.resolution_m / 2.0
        self._graph: tuple[FloatArray, npt.NDArray[np.intp]] | None = None  # (dist, next_hop), at the first plan

    # -- geometry helpers ------------------------------------------------------------------------
    def _centres(self, rc: npt.NDArray[np.intp]) -> FloatArray:
        g = self.grid
        return np.column_stack(
            [g.origin_x + (rc[:, 1] + 0.5) * g.resolution_m, g.origin_y + (rc[:, 0] + 0.5) * g.resolution_m]
        ).astype(float)

    def is_free(self, x: float, y: float) -> bool:
        r, c = self.grid.cell_of(x, y)
        return 0 <= r < self.grid.height and 0 <= c < self.grid.width and not bool(self.blocked[r, c])

    def _cells_of(self, pts: FloatArray) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], npt.NDArray[np.bool_]]:
        g = self.grid
        cols = np.floor((pts[:, 0] - g.origin_x) / g.resolution_m).astype(np.intp)
        rows = np.floor((pts[:, 1] - g.origin_y) / g.resolution_m).astype(np.intp)
        inside = (rows >= 0) & (rows < g.height) & (cols >= 0) & (cols < g.width)
        return rows, cols, inside

    def hard_clear(self, pts: FloatArray) -> bool:
        """True if the robot's body (no safety margin) fits at every point."""
        rows, cols, inside = self._cells_of(np.asarray(pts, dtype=float).reshape(-1, 2))
        return bool(inside.all() and not self.hard_blocked[rows, cols].any())

    @overload
    def free_run(self, start: Point, direction: Point, max_m: float = 10.0) -> float: ...

    @overload
    def free_run(self, start: Point, direction: FloatArray, max_m: float = 10.0) -> FloatArray: ...

    def free_run(self, start: Point, direction: Point | FloatArray, max_m: float = 10.0) -> float | FloatArray:
        """How far one can go from `start` along the unit vector `direction` before hitting an
        obstacle of the map (not inflated); given an (N, 2) array of directions, the N distances,
        cast in one numpy pass (a simulated participant looks for walls in 16 directions a tick)."""
        dirs = np.asarray(direction, dtype=float).reshape(-1, 2)
        g = self.grid
        step = g.resolution_m / 2.0
        s = np.arange(0.0, max_m + step, step)
        # (rays, samples) cells of start + direction * s, x and y apart (the same numbers as (rays, samples, 2) points)
        cols = np.floor((dirs[:, :1] * s + start[0] - g.origin_x) / g.resolution_m).astype(np.intp)
        rows = np.floor((dirs[:, 1:] * s + start[1] - g.origin_y) / g.resolution_m).astype(np.intp)
        inside = (rows >= 0) & (rows < g.height) & (cols >= 0) & (cols < g.width)
        hit = ~inside
        hit[inside] = self.occupied[rows[inside], cols[inside]]
        runs = np.where(hit.any(axis=1), s[hit.argmax(axis=1)], max_m)
        return runs if isinstance(direction, np.ndarray) else float(runs[0])

    def visible(self, a: FloatArray, b: FloatArray) -> npt.NDArray[np.bool_]:
        """Line of sight for each segment a[i] -> b[i] (arrays (M, 2)) through the inflated grid,
        sampled every half cell, at most `MAX_SIGHT_SAMPLES` samples at a time (bounded memory)."""
        a = np.asarray(a, dtype=float).reshape(-1, 2)
        b = np.asarray(b, dtype=float).reshape(-1, 2)
        counts = np.maximum(2, np.ceil(np.hypot(*(b - a).T) / self._step).astype(np.intp) + 1)
        out = np.zeros(len(a), dtype=bool)
        lo, ends = 0, np.cumsum(counts)
        while lo < len(a):
            hi = max(lo + 1, int(np.searchsorted(ends, ends[lo] - counts[lo] + MAX_SIGHT_SAMPLES, side="right")))
            out[lo:hi] = self._visible(a[lo:hi], b[lo:hi], counts[lo:hi])
            lo = hi
        return out

    def _visible(self, a: FloatArray, b: FloatArray, counts: npt.NDArray[np.intp]) -> npt.NDArray[np.bool_]:
        seg = np.repeat(np.arange(len(a)), counts)
        first = np.cumsum(counts) - counts
        frac = (np.arange(len(seg)) - np.repeat(first, counts)) / np.repeat(counts - 1, counts)
        pts = a[seg] + (b - a)[seg] * frac[:, None]
        rows, cols, inside = self._cells_of(pts)
        hit = np.ones(len(seg), dtype=bool)
        hit[inside] = self.blocked[rows[inside], cols[inside]]
        return ~np.logical_or.reduceat(hit, first)

    def _all_pairs(self) -> None:
        """Visibility between every pair of nodes, then Floyd-Warshall with next-hop tracking (in
        place: row and column k do not change in step k)."""
        n = len(self.nodes)
        problem = graph_problem(n, self.grid, self.params)
        if problem is not None:
            raise PlanningError(problem)
        dist = np.full((n, n), np.inf)
        np.fill_diagonal(dist, 0.0)
        if n > 1:
            i, j = np.triu_indices(n, 1)
            ok = self.visible(self.nodes[i], self.nodes[j])
            i, j = i[ok], j[ok]
            d = np.hypot(*(self.nodes[i] - self.nodes[j]).T)
            dist[i, j] = d
            dist[j, i] = d
        nxt = np.where(np.isfinite(dist), np.arange(n)[None, :], -1)
        for k in range(n):
            via = dist[:, k, None] + dist[None, k, :]
            better = via < dist
            if better.any():
                np.copyto(dist, via, where=better)
                np.copyto(nxt, nxt[:, k, None].copy(), where=better)
        self._graph = (dist, nxt)

    @property
    def dist(self) -> FloatArray:
        """Shortest distances between the nodes (the graph is built at the first plan)."""
        if self._graph is None:
            self._all_pairs()
        assert self._graph is not None
        return self._graph[0]

    @property
    def next_hop(self) -> npt.NDArray[np.intp]:
        if self._graph is None:
            self._all_pairs()
        assert self._graph is not None
        return self._graph[1]

    def _snap(self, p: Point, what: str) -> Point:
        g = self.grid
        x, y = p
        r, c = g.cell_of(x, y)
        if not (0 <= r < g.height and 0 <= c < g.width):
            raise PlanningError(f"{what} ({x:.2f}, {y:.2f}) is outside the map", PlanFailure(f"{what}_outside_map"))
        if not self.blocked[r, c]:
            return p
        k = math.ceil(self.params.snap_radius_m / g.resolution_m)
        r0, r1, c0, c1 = max(0, r - k), min(g.height, r + k + 1), max(0, c - k), min(g.width, c + k + 1)
        free = np.argwhere(~self.blocked[r0:r1, c0:c1])
        if len(free):
            pts = self._centres(free + np.array((r0, c0)))  # (the window's cells, back in the grid's rows and columns)
            d = np.hypot(pts[:, 0] - x, pts[:, 1] - y)
            best = int(np.argmin(d))
            if d[best] <= self.params.snap_radius_m:
                return (float(pts[best, 0]), float(pts[best, 1]))
        inside = f"{what} ({x:.2f}, {y:.2f}) is inside an obstacle or within {self.params.inflation_m:.2f} m of one"
        raise PlanningError(inside, PlanFailure(f"{what}_occupied"))

    # -- queries ---------------------------------------------------------------------------------
    def plan(self, start: Point, goal: Point) -> Plan:
        s = self._snap(start, "start")
        g = self._snap(goal, "goal")
        sa, ga = np.array([s], dtype=float), np.array([g], dtype=float)
        if self.visible(sa, ga)[0]:
            return self._finish(start, [s, g], goal)
        n = len(self.nodes)
        if n == 0:
            raise PlanningError(f"goal ({goal[0]:.2f}, {goal[1]:.2f}) is not reachable from the start")
        dist = self.dist  # (built now, or refused past the caps before any sight is tested)
        vis = self.visible(np.vstack([np.repeat(sa, n, 0), np.repeat(ga, n, 0)]), np.vstack([self.nodes, self.nodes]))
        vs, vg = np.flatnonzero(vis[:n]), np.flatnonzero(vis[n:])
        if len(vs) == 0 or len(vg) == 0:
            who = "start" if len(vs) == 0 else "goal"
            raise PlanningError(
                f"{who} ({(s if who == 'start' else g)[0]:.2f}, {(s if who == 'start' else g)[1]:.2f}) sees no way out"
            )
        ds = np.hypot(*(self.nodes[vs] - sa).T)
        dg = np.hypot(*(self.nodes[vg] - ga).T)
        total = ds[:, None] + dist[np.ix_(vs, vg)] + dg[None, :]
        flat = int(np.argmin(total))
        if not np.isfinite(total.flat[flat]):
            raise PlanningError(f"goal ({goal[0]:.2f}, {goal[1]:.2f}) is not reachable from the start")
        i, j = vs[flat // len(vg)], vg[flat % len(vg)]
        pts = [s]
        while i != j:
            pts.append((float(self.nodes[i, 0]), float(self.nodes[i, 1])))
            i = self.next_hop[i, j]
        pts += [(float(self.nodes[j, 0]), float(self.nodes[j, 1])), g]
        return self._finish(start, pts, goal)

    @staticmethod
    def _finish(start: Point, pts: list[Point], goal: Point) -> Plan:
        """Put the true start back in front (a robot nudged against a wall starts there) and drop
        repeated points."""
        out: list[Point] = [start]
        for p in pts:
            if math.hypot(p[0] - out[-1][0], p[1] - out[-1][1]) > 1e-9:
                out.append(p)
        length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in itertools.pairwise(out))
        return Plan(out, length)
