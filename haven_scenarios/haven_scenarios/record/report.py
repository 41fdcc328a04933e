"""`haven report`: one CSV row per session, recomputed from the recordings.

A session that cannot be read (a bag without metadata, a truncated MCAP, a missing scenario copy)
still gets its row, with `valid` false and the reason; nothing aborts the report.
"""

from __future__ import annotations

import csv
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from haven_scenarios.record.session import analyse
from haven_sim.common import atomic

NOT_IN_CSV = ("condition_segments",)  # nested: in metrics.json only
# The design columns come first, as a statistics package expects them (then the metrics).
FIRST = ("session", "trial", "participant", "condition", "seed", "scenario", "end_reason", "valid")


def csv_row(metrics: dict[str, Any]) -> dict[str, Any]:
    """A metrics dict as a flat CSV row (lists joined with "; ", nested structures left out)."""
    keys = [k for k in FIRST if k in metrics] + [k for k in metrics if k not in FIRST and k not in NOT_IN_CSV]
    return {k: ("; ".join(map(str, metrics[k])) if isinstance(metrics[k], list) else metrics[k]) for k in keys}


def session_folders(paths: Sequence[Path]) -> list[Path]:
    """Session folders among `paths`, also inside folders that hold sessions (a study folder)."""
    out = []
    for p in paths:
        if (p / "bag").is_dir() or (p / "session.json").exists():
            out.append(p)
        elif p.is_dir():
            out += sorted(q for q in p.iterdir() if (q / "bag").is_dir() or (q / "session.json").exists())
    return out


def write_table(path: Path, rows: Sequence[dict[str, Any]], first: Sequence[str] = ()) -> None:
    """A CSV of `rows` under the union of their columns (`first`, then as first seen), written whole
    to a temporary file and renamed over `path`: a reader never sees half a table."""
    keys = dict.fromkeys(first)
    for r in rows:
        keys.update(dict.fromkeys(r))
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic.replacing(path) as tmp, tmp.open("w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=list(keys))
        writer.writeheader()
        writer.writerows(rows)


def report_csv(paths: Sequence[Path], out: Path) -> list[dict[str, Any]]:
    rows = [csv_row(analyse(folder)[0]) for folder in session_folders(paths)]
    write_table(out, rows)
    return rows


def save_png(fig: Any, out: Path) -> Path:
    """A matplotlib figure as a PNG, written whole (a reader never sees half a picture); the figure is closed."""
    import matplotlib.pyplot as plt

    try:
        with atomic.replacing(out) as tmp:
            fig.savefig(tmp, dpi=100, format="png")
    finally:
        plt.close(fig)
    return out
