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


def report_csv(paths: Sequence[Path], out: Path) -> list[dict[str, Any]]:
    rows = [csv_row(analyse(folder)[0]) for folder in session_folders(paths)]
    keys: list[str] = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    out.parent.mkdir(parents=True, exist_ok=True)
    with out.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(rows)
    return rows
