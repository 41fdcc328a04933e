"""Shared by the benchmark scripts."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

OUT = Path(__file__).resolve().parent / "out"


def save(rows: Any, path: str | Path) -> None:
    """Write the raw results as JSON next to the printed table (bench/out/ is not committed)."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(rows, indent=2))
    print(f"wrote {out}")
