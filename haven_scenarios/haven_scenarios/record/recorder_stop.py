"""The rule for a recorder that did not end cleanly while a recorded trial stopped.

When a trial ends, `haven run` stops the nodes with SIGTERM and, after a grace of 5 s, SIGKILL
(run/supervisor.py). The recorder exits with code 0 only after it has closed its bag (the last
messages written, the MCAP summary and footer, metadata.yaml: nodes/recorder.py), so a clean exit
is its own evidence. A recorder that did not exit cleanly (killed by SIGKILL on a loaded machine
while it was still closing, or ended by an error) may or may not have finished its bag, so:

    A session whose recorder did not exit cleanly is valid only if its bag is verified complete:
    1. whole: metadata.yaml is there, every MCAP file has its summary and footer, and the message
       count in metadata.yaml equals the count in the MCAP summaries (nothing written after the
       summary, nothing missing from it); a bag rebuilt by a repair is not whole (what its
       recorder still held in memory is lost);
    2. through the trial's end: `trial_end` is recorded, and every state stream the metrics rest on
       (/odom; /humans where the trial has people) has a message stamped at or after it (less the
       validity check's MAX_GAP_S), as the recorder itself waits for before it says it has the end.

session.json records what happened as `recorder_stop`: how the recorder ended (`exit`, `code`),
whether its bag was verified complete (`bag_verified`) and why not (`why`). `analyse` applies the
rule from that record, so `haven report` rescoring the session reaches the same verdict.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import yaml
from mcap.reader import make_reader

from haven_scenarios.record.bag import REPAIRED_KEY, custom_data
from haven_scenarios.record.timeline import Recording
from haven_scenarios.record.validity import MAX_GAP_S
from haven_sim.common.events import EventKind

KEY = "recorder_stop"  # in session.json
CLOSED = (
    "closed by the recorder (a clean exit: it exits 0 only after writing the footer, the summary and metadata.yaml)"
)


def _summary_count(mcap: Path) -> int | None:
    """The messages the MCAP file's summary counts; None without a summary and footer."""
    try:
        with mcap.open("rb") as f:
            summary = make_reader(f).get_summary()
    except Exception:
        return None
    if summary is None or summary.statistics is None:
        return None
    return int(summary.statistics.message_count)


def bag_whole(bag: Path) -> str:
    """ "" if the bag is whole as its recorder closes it (rule 1), else why not, in a few words."""
    files = sorted(bag.glob("*.mcap"))
    if not files:
        return "no MCAP file"
    try:
        meta = yaml.load((bag / "metadata.yaml").read_text(), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
        listed = int(meta["rosbag2_bagfile_information"]["message_count"])
    except FileNotFoundError:
        return "no metadata.yaml"
    except (OSError, KeyError, TypeError, ValueError, yaml.YAMLError):
        return "metadata.yaml unreadable"
    counted = 0
    for mcap in files:
        n = _summary_count(mcap)
        if n is None:
            return f"{mcap.name} has no summary and footer"
        counted += n
    if counted != listed:
        return f"metadata.yaml counts {listed} messages, the MCAP summary {counted}"
    if REPAIRED_KEY in custom_data(bag):
        return "rebuilt by a repair (what the recorder still held was lost)"
    return ""


def through_end(rec: Recording) -> str:
    """ "" if the recording covers the trial through `trial_end` (rule 2), else why not."""
    end = rec.first(EventKind.TRIAL_END)
    if end is None:
        return "no trial_end recorded"
    streams = {"/odom": [t for t, _ in rec.odom], **({"/humans": [t for t, _ in rec.humans]} if rec.humans else {})}
    for name, stamps in streams.items():
        last = max(stamps, default=None)
        if last is None:
            return f"no {name} recorded"
        if last < end.stamp - MAX_GAP_S - 1e-9:
            return f"{name} recorded only to {end.stamp - last:.2f} s before trial_end"
    return ""


def verdict(code: int, bag: Path, rec: Recording) -> str:
    """Why the bag of a recorder that ended with `code` is not verified complete ("" if it is)."""
    return "" if code == 0 else bag_whole(bag) or through_end(rec)


def record(exit_text: str, code: int, during: str, why: str | None = None) -> dict[str, Any]:
    """session.json's `recorder_stop`: how the recorder ended (`during`: "while stopping", or
    "during the trial" when its death ended it) and, once judged (`why` not None), whether its bag
    was verified complete."""
    out: dict[str, Any] = {"exit": exit_text, "code": code, "during": during}
    if why is not None:
        out.update(bag_verified=not why, why=why or (CLOSED if code == 0 else "whole, and recorded through trial_end"))
    return out


def judged(stop: Mapping[str, Any], bag: Path, rec: Recording) -> dict[str, Any]:
    """A `record` not judged yet, judged: with whether the bag was verified complete, and why not."""
    return record(stop["exit"], stop["code"], stop["during"], verdict(stop["code"], bag, rec))


def problem(info: Mapping[str, Any], bag: Path, rec: Recording) -> str:
    """The session's validity reason under the rule ("" if none): from session.json's `recorder_stop`
    (sessions from before it, and batch sessions, have none: nothing to judge)."""
    stop = info.get(KEY)
    if not isinstance(stop, Mapping) or not isinstance(stop.get("code"), int):
        return ""
    why = verdict(stop["code"], bag, rec)
    said = f"{stop.get('exit', 'the recorder did not exit cleanly')} {stop.get('during', 'while stopping')}"
    return f"{said}, and its bag is not verified complete: {why}" if why else ""
