"""A top-down picture of one moment, drawn from the same marker data the viewers get.

Walls come from the world; everything else (gems, base, robot, humans, path projection, turn
arrow, thought bubble, battery bar) from `MarkerSpec`s, so the picture shows exactly the cues a
participant saw. Optional trails and labelled points let the scenario issue draw whole trials.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.patches import Circle, FancyArrow, Polygon, Rectangle
from matplotlib.transforms import Affine2D

from haven_sim.common import atomic
from haven_sim.common.geometry import FloatArray
from haven_sim.sim.world import World
from haven_viz.cues import BATTERY_NS, THOUGHT_NS
from haven_viz.markers import MarkerSpec, Shape
from haven_viz.world_markers import COLORS

# Drawing order: floor items, then path, then bodies, then what floats above.
_LAYER = {
    "gem_areas": 1,
    "charging_base": 1,
    "rooms": 2,
    "path_projection": 3,
    "gems": 4,
    "robot": 5,
    "humans": 5,
    "turn_signals": 6,
    BATTERY_NS: 7,
    THOUGHT_NS: 8,
    "human_names": 8,
}


# the people's tracks, in turn (the robot's: black)
PERSON_TRAILS = ("tab:red", "tab:orange", "tab:purple", "tab:brown")


def _rgb(c: Sequence[float]) -> tuple[float, float, float, float]:
    return (c[0], c[1], c[2], c[3])


def _draw(ax: Axes, m: MarkerSpec) -> None:
    x, y, _ = m.position
    z = 10 + _LAYER.get(m.ns, 5)
    color = _rgb(m.color)
    if m.shape is Shape.SPHERE and m.ns == THOUGHT_NS:
        return  # the bubble's backdrop: the text below gets a rounded box instead
    if m.ns == BATTERY_NS and m.shape is Shape.CUBE:
        # Seen from above the bar would sit on the robot: draw it just above the robot instead.
        w = m.scale[0]
        if m.id == 0:
            ax.add_patch(Rectangle((x - w / 2, y + 0.29), w, 0.1, facecolor="white", edgecolor="0.2", lw=0.6, zorder=z))
        else:
            ax.add_patch(Rectangle((x - w / 2, y + 0.3), w, 0.08, facecolor=color, edgecolor="none", zorder=z + 0.1))
        return
    if m.shape in (Shape.SPHERE, Shape.CYLINDER):
        edge = "black" if m.ns in ("path_projection", "robot", "humans") else "none"
        ax.add_patch(Circle((x, y), m.scale[0] / 2.0, facecolor=color, edgecolor=edge, lw=0.4, zorder=z))
    elif m.shape is Shape.CUBE:
        w, h = m.scale[0], m.scale[1]
        rect = Rectangle((x - w / 2, y - h / 2), w, h, facecolor=color, edgecolor="black", lw=0.4, zorder=z)
        rect.set_transform(Affine2D().rotate_around(x, y, m.yaw) + ax.transData)
        ax.add_patch(rect)
    elif m.shape is Shape.ARROW:
        length = m.scale[0]
        dx, dy = length * math.cos(m.yaw), length * math.sin(m.yaw)
        ax.add_patch(
            FancyArrow(
                x,
                y,
                dx,
                dy,
                width=m.scale[1],
                head_width=2.5 * m.scale[1],
                head_length=0.4 * length,
                length_includes_head=True,
                facecolor=color,
                edgecolor="black",
                lw=0.4,
                zorder=z,
            )
        )
    elif m.shape is Shape.TEXT_VIEW_FACING:
        size = max(5.0, 40.0 * m.scale[2])
        box = None
        if m.ns == THOUGHT_NS:
            box = {"boxstyle": "round,pad=0.4", "facecolor": "white", "edgecolor": "0.3", "alpha": 0.95}
            y += 0.8
        elif m.ns == BATTERY_NS:
            y += 0.5
            size, color = 6.0, (0.1, 0.1, 0.1, 1.0)
        ax.text(x, y, m.text, ha="center", va="center", fontsize=size, color=color, bbox=box, zorder=z)


# What the robot did, as symbols with a legend entry each (text labels would pile up on one spot).
EVENT_SYMBOLS = {
    "wait": ("s", "tab:blue"),
    "detour left": ("<", "tab:blue"),
    "detour right": (">", "tab:blue"),
    "to charge": ("D", "tab:cyan"),
    "contact": ("X", "red"),
}


def render_scene(
    world: World,
    markers: Sequence[MarkerSpec],
    out: str | Path,
    title: str = "",
    trails: Mapping[str, tuple[FloatArray, str]] | None = None,
    points: Sequence[tuple[float, float, str, str]] = (),
    removed: Sequence[str] = (),
    events: Sequence[tuple[float, float, str]] = (),
    view: tuple[float, float, float, float] | None = None,
) -> Path:
    """Draw and save a PNG. `trails`: label -> ((N, 2) xy, colour); `points`: (x, y, label, colour),
    labelled on the map; `events`: (x, y, kind) with a symbol per kind (EVENT_SYMBOLS), in the legend;
    `view`: (xmin, ymin, xmax, ymax) to show (default: the whole world)."""
    xmin, ymin, xmax, ymax = view or world.bounds()
    width, height = xmax - xmin, ymax - ymin
    scale = 9.0 / max(width, height)
    fig, ax = plt.subplots(figsize=(max(4.0, width * scale + 1.0), max(3.0, height * scale + 0.8)))
    ax.set_facecolor((0.97, 0.97, 0.95))
    for kind, shapes in (("wall", world.walls), ("obstacle", world.obstacles)):
        if shapes:  # (one collection: a world made from a map has thousands of wall boxes)
            ax.add_collection(
                PolyCollection(
                    [s.polygon for s in shapes], closed=True, facecolors=COLORS[kind], edgecolors="none", zorder=2
                )
            )
    for o in world.obstructions:
        if o.id not in removed:
            ax.add_patch(Polygon(o.shape.polygon, closed=True, facecolor=COLORS["obstruction"], hatch="//", zorder=2))
    for label, (xy, color) in (trails or {}).items():
        if len(xy):
            ax.plot(xy[:, 0], xy[:, 1], "-", color=color, lw=1.2, alpha=0.8, label=label, zorder=9)
    for x, y, label, color in points:
        ax.plot([x], [y], "o", color=color, ms=5, zorder=9.5)
        ax.annotate(label, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=6, color=color, zorder=9.5)
    shown: set[str] = set()
    for x, y, kind in events:
        symbol, color = EVENT_SYMBOLS.get(kind, ("o", "tab:blue"))
        ax.plot(
            [x], [y], symbol, color=color, ms=7, mec="white", mew=0.6, zorder=9.6, label=None if kind in shown else kind
        )
        shown.add(kind)
    for m in sorted(markers, key=lambda m: _LAYER.get(m.ns, 5)):
        _draw(ax, m)
    if world.charging_base is not None and any(m.ns == "charging_base" for m in markers):
        bx, by = world.charging_base.position
        ax.annotate("charging base", (bx, by), ha="center", va="center", fontsize=6, color="black", zorder=9.7)
    if trails or events:
        ax.legend(loc="best", fontsize=7, framealpha=0.8)  # (where it hides the least)
    ax.set_xlim(xmin - 0.3, xmax + 0.3)
    ax.set_ylim(ymin - 0.3, ymax + 0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m, map)")
    ax.set_ylabel("y (m, map)")
    if title:
        ax.set_title(title, fontsize=9)
    fig.tight_layout()
    path = Path(out)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        with atomic.replacing(path) as tmp:
            fig.savefig(tmp, dpi=150, format="png")
    finally:
        plt.close(fig)
    return path
