"""`haven repair`: rebuild the bags their recorder never closed (killed, or stopped by a full disk).

`haven run` does the same at the end of a trial whose recorder died; `haven repair` is for the
sessions left behind otherwise (a machine that lost power, an older run). The session's
metrics.json is then recomputed from the repaired bag (flagged not valid: the bag was repaired),
and session.json notes the repair.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from haven_scenarios.conduct.outcomes import NO_OUTCOME, repair_bag, repair_record
from haven_scenarios.record.repair import Repaired, needs_repair
from haven_scenarios.record.report import session_folders
from haven_scenarios.record.session import METRICS_FILE, SESSION_FILE, analyse, session_info, write_json
from haven_scenarios.tools.commands.common import fail


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = sub.add_parser(
        "repair", help="rebuild the bags of sessions whose recorder died (metadata.yaml and footer from the MCAP data)"
    )
    p.add_argument(
        "paths", nargs="+", type=Path, metavar="SESSION", help="session folders, folders of sessions, or bag folders"
    )
    p.set_defaults(func=repair_cmd)


def _rescore(folder: Path, done: Repaired) -> None:
    """A session's metrics.json again from its repaired bag, and the repair in session.json."""
    metrics, _, _ = analyse(folder)
    write_json(folder / METRICS_FILE, metrics)
    info = session_info(folder)
    if (folder / SESSION_FILE).exists() and not info:
        return  # an unreadable session.json is left as it is
    info["bag_repaired"] = repair_record(done)
    if info.get("outcome", NO_OUTCOME) == NO_OUTCOME:  # haven run itself died: the recording says how far it got
        info["outcome"] = f"{NO_OUTCOME}; the repaired recording ends: {metrics['end_reason']}"
    info.update(end_reason=metrics["end_reason"], duration_s=metrics["duration_s"], valid=metrics["valid"])
    write_json(folder / SESSION_FILE, info)


def _bags(paths: list[Path]) -> list[tuple[Path, Path | None]]:
    """(bag folder, its session folder or None) for every path: bag folders as given, session
    folders and folders of sessions through their `bag`."""
    out: list[tuple[Path, Path | None]] = []
    for p in paths:
        if any(p.glob("*.mcap")) or any(p.glob("*.mcap.damaged")):
            out.append((p, p.parent if (p.parent / SESSION_FILE).is_file() and p.name == "bag" else None))
        else:
            out += [(folder / "bag", folder) for folder in session_folders([p]) if (folder / "bag").is_dir()]
    return out


def repair_cmd(args: argparse.Namespace) -> int:
    """Every damaged bag among the paths repaired; exit 1 if one could not be, 2 for a path that is
    not there or holds no bag."""
    missing = [p for p in args.paths if not p.exists()]
    if missing:
        return fail(f"{missing[0]}: no such session folder or bag")
    bags = _bags(list(args.paths))
    if not bags:
        return fail(f"no bags in {', '.join(map(str, args.paths))}")
    failed = 0
    for bag, folder in bags:
        if not needs_repair(bag):
            print(f"haven: {bag}: a complete bag, nothing to repair")
            continue
        done = repair_bag(bag)
        if done is None:
            failed += 1
        elif folder is not None:
            try:
                _rescore(folder, done)
            except OSError as e:
                print(
                    f"haven: {folder}: the bag is repaired but the "
                    f"session files could not be updated: {e.strerror or e}",
                    file=sys.stderr,
                )
                failed += 1
    return 1 if failed else 0
