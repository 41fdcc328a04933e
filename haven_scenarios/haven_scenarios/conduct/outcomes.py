"""How a recorded trial ended, in words and in its session folder; and a bag its recorder never
closed, repaired."""

from __future__ import annotations

import signal
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_scenarios.record import recorder_stop
from haven_scenarios.record.repair import Repaired, RepairError, needs_repair, repair
from haven_scenarios.record.session import SESSION_FILE, write_json
from haven_scenarios.run.supervisor import Exited
from haven_sim.common import nodes

NO_OUTCOME = "unknown: haven run ended before it wrote the outcome"


# After a stop signal, how long the recorder may take to have the trial's end on every stream: a
# moment (the scenario node has made sure the recorder has trial_end before it exits; the trial is
# over and runs again, and on the lockstep clock the simulator takes no further step without the
# scenario, so the streams would never get there).
STOPPED_END_WAIT_S = 0.25


def exit_text(name: str, code: int) -> str:
    """How a node process ended, for a person: "recorder was killed by SIGKILL", "planner exited with code 1"."""
    if code < 0:
        try:
            return f"{name} was killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"{name} was killed by signal {-code}"
    return f"{name} exited with code {code}"


@dataclass(frozen=True)
class Ended:
    """How the supervised trial ended."""

    exited: Exited | None  # the node whose exit ended it (None: a stop signal or the time limit)
    timed_out: bool = False  # the time limit passed
    recorder_code: int | None = None  # the recorder's exit code once everything stopped
    questionnaires: str | None = None  # how the questionnaires after it ended (conduct/after_trial.py)

    def recorder_stop(self) -> dict[str, Any] | None:
        """session.json's `recorder_stop`, not judged yet (record/recorder_stop.py); None if no recorder ran."""
        code = self.recorder_code
        if code is None:
            return None
        during = (
            "during the trial" if self.died is not None and self.died.name == nodes.RECORDER.key else "while stopping"
        )
        return recorder_stop.record(exit_text("recorder", code), code, during)

    @property
    def stopped(self) -> bool:
        """A stop signal (Ctrl-C, SIGTERM, ...) ended it."""
        return self.exited is None and not self.timed_out

    @property
    def died(self) -> Exited | None:
        """The node that ended the trial by exiting when it should not have."""
        e = self.exited
        return e if e is not None and (e.name not in nodes.ENDS_TRIAL or e.code != 0) else None


def outcome(ended: Ended | None, end_reason: str | None, repaired: Repaired | None, limit_s: float) -> str:
    """session.json's `outcome`: how the run ended, in words (also when it ended by an exception)."""
    if ended is None:
        text = "interrupted: haven run stopped before the nodes were stopped in order"
    elif ended.died is not None:
        text = f"cut short: {exit_text(ended.died.name, ended.died.code)}"
    elif ended.timed_out:
        text = f"cut short: the trial did not end within {limit_s:.0f} s (wall)"
    elif ended.exited is None:
        text = "interrupted (stopped by a signal)"
    else:
        text = end_reason or "unknown: the metrics were not computed"
    code = ended.recorder_code if ended is not None else None
    if code not in (None, 0) and not (
        ended is not None and ended.died is not None and ended.died.name == nodes.RECORDER.key
    ):
        text += f"; {exit_text('recorder', code)} while stopping"
    if repaired is not None:
        text += f"; bag repaired ({repaired.messages} messages recovered)"
    return text


def summary(metrics: dict[str, Any], wall_s: float) -> str:
    """The one line `haven run` prints about a trial's outcome."""
    if metrics["duration_s"] is None:
        return f"haven: {metrics['end_reason']} before the trial started ({wall_s:.0f} s wall)"
    finished = metrics.get("robot_time_to_finish_s")
    robot = f"robot finished at {finished} s" if finished is not None else "robot did not finish"
    return (
        f"haven: {metrics['end_reason']} in {metrics['duration_s']} s of sim time ({wall_s:.0f} s wall): {robot}, "
        f"closest approach {metrics.get('min_human_centre_distance_m')} m, {metrics.get('waits')} wait(s), "
        f"{metrics.get('replans')} re-plan(s), {metrics.get('human_contacts')} contact(s)"
    )


def write_outcome(folder: Path, info: dict[str, Any]) -> None:
    """session.json with the run's outcome; a full disk is said in one line (the outcome with it)."""
    try:
        write_json(folder / SESSION_FILE, info)
    except OSError as e:
        print(
            f"haven: error: cannot write {folder / SESSION_FILE}: {e.strerror or e} (outcome: {info['outcome']})",
            file=sys.stderr,
        )


def repair_bag(bag: Path, how: str = "haven repair") -> Repaired | None:
    """Repair `bag` if it needs it, saying so in one line on stderr; None if it did not need it or
    could not be repaired (then the line says why, and the damaged files are left as they were)."""
    if not needs_repair(bag):
        return None
    try:
        done = repair(bag, how)
    except RepairError as e:
        print(f"haven: {e}", file=sys.stderr)
        return None
    print(f"haven: {done.line()}", file=sys.stderr)
    return done


def repair_record(done: Repaired) -> dict[str, object]:
    """What session.json says about a repair."""
    return {
        "messages": done.messages,
        "topics": done.topics,
        "kept": [str(p.relative_to(done.bag)) for p in done.kept],
        "skipped": done.skipped,
    }
