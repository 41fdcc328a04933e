"""A lab's plugins that fail, installed as a lab's are (a distribution with entry points, written
into a folder put on PYTHONPATH: nothing is built or pip-installed), for the tests that every
plugin call is contained (haven_sim/common/contain.py).

Participant models `raiser`, `hanger` and `stuck` walk as HAVEN's walker for FAIL_AFTER_S of their
trial, then raise, hang for good, or hang where no exception can reach them (as C code would);
`dawdler` walks as the walker but takes DAWDLE_S of wall time over each step, so a batch trial lasts
seconds on any machine (a test can stop one while it runs); the
metric `flaky` raises or hangs as LAB_METRIC says (`raise`, `hang`; anything else: a column of its
own), so one installation serves every case."""

from __future__ import annotations

import os
from pathlib import Path

FAIL_AFTER_S = 1.0
DAWDLE_S = 0.01
MODULE = """
import os
import signal
import time

from haven_scenarios.study.participants import Walker

FAIL_AFTER_S = {fail_after}
DAWDLE_S = {dawdle}


class _Failing(Walker):
    started = None

    def command(self, now, *args, **kwargs):
        self.started = now if self.started is None else self.started
        if now - self.started >= FAIL_AFTER_S:
            self.fail()
        return super().command(now, *args, **kwargs)


class Raiser(_Failing):
    def fail(self):
        raise RuntimeError("the lab's model broke\\nsecond line")


class Dawdler(Walker):
    def command(self, *args, **kwargs):
        time.sleep(DAWDLE_S)
        return super().command(*args, **kwargs)


class Hanger(_Failing):
    def fail(self):
        while True:
            try:
                time.sleep(3600)
            except Exception:  # (a plugin that swallows what it can: the deadline still ends it)
                pass


class Stuck(_Failing):  # (stuck where no exception can land, signals blocked: as C code that never returns)

    def fail(self):
        signal.pthread_sigmask(signal.SIG_BLOCK, signal.valid_signals())
        time.sleep(3600)


def flaky(data):
    mode = os.environ.get("LAB_METRIC", "")
    if mode == "raise":
        raise ValueError("no numbers today")
    if mode == "hang":
        while True:
            pass
    return {{"flaky_ok": 1}}
"""
ENTRY_POINTS = """\
[haven.participants]
raiser = lab_failing:Raiser
hanger = lab_failing:Hanger
stuck = lab_failing:Stuck
dawdler = lab_failing:Dawdler

[haven.metrics]
flaky = lab_failing:flaky
"""
# A short hallway trial (a minute of simulated time at most; the robot's first room only).
SCENARIO = """\
name: short_hallway
world: hallway
kind: hallway
timeout_s: 60
condition: [turn_signals]
robot:
  route: [B]
humans:
  - {{id: h1, model: {model}, route: [B, A], speed_mps: 1.0}}
"""
# Short deadlines, as a lab would set them in a parameter file ("/**": every node, and batch mode);
# still far above what HAVEN's own take on a machine at load 60 (where our `people` metric took over 1 s).
PARAMS = """\
/**:
  ros__parameters:
    plugin_deadline_participants_s: 1.0
    plugin_deadline_metrics_s: 10.0
"""


def install(folder: Path) -> dict[str, str]:
    """The failing plugins in `folder` (created); the environment that sees them."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "lab_failing.py").write_text(MODULE.format(fail_after=FAIL_AFTER_S, dawdle=DAWDLE_S))
    info = folder / "lab_failing-0.1.dist-info"
    info.mkdir(exist_ok=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: lab-failing\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(ENTRY_POINTS)
    path = os.pathsep.join([str(folder), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return {**os.environ, "PYTHONPATH": path, "LAB_METRIC": ""}
