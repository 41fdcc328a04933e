"""`haven run` when its recorder dies mid-trial: killed outright (SIGKILL), or stopped by a full disk.

The supervisor names the recorder and how it ended, session.json gets an outcome, the bag (no footer,
no metadata.yaml) is repaired at the end of the run from the MCAP data it holds, keeping every
message the file held when the recorder died; the repaired bag opens in rosbags' AnyReader and the
mcap library's reader (with its summary), and `haven report` reads it, flagged as repaired.

The recorder is found as a child of the `haven run` process (/proc/<pid>/task/*/children). The full
disk is made honestly without root: once the trial runs, the test lowers the recorder process's
file size limit (RLIMIT_FSIZE, with `resource.prlimit` on its pid) to a little above the bag's
current size; Python ignores SIGXFSZ, so the recorder's next write fails with EFBIG, as a write to a
full disk fails with ENOSPC, through the same code.
"""

import csv
import json
import os
import resource
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from mcap.reader import make_reader
from rclpy.qos import QoSProfile, ReliabilityPolicy
from ros_harness import tracebacks
from rosbags.highlevel import AnyReader
from rosgraph_msgs.msg import Clock

from haven_scenarios.record.bag import TYPESTORE, recovered_records

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]


def start_run(ros, tmp_path):
    """`haven run hallway` on the harness's domain; returns it and its session folder once the
    trial has run 2 s of sim time (however slowly this machine runs it) and the recorder has
    written some hundreds of messages to its file (it writes them out once a second)."""
    out, err = (tmp_path / "run.out").open("w"), (tmp_path / "run.err").open("w")
    argv = [
        *HAVEN,
        "run",
        "hallway",
        "--rtf",
        "2",
        "--sessions",
        str(tmp_path / "s"),
        "--domain-id",
        str(ros.domain_id),
    ]
    proc = subprocess.Popen(argv, env=ros.env, stdout=out, stderr=err, text=True, start_new_session=True)
    ros.procs.append(proc)
    clock = ros.collect(Clock, "/clock", QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
    started = lambda: any('"trial_start"' in p.read_text() for p in (tmp_path / "s").glob("*/events.jsonl"))  # noqa: E731
    assert ros.spin_until(started, timeout_s=90), "the trial never started"
    assert ros.spin_until(lambda: bool(clock) and clock[-1].clock.sec >= 2, timeout_s=60), "the clock never reached 2 s"
    (folder,) = (tmp_path / "s").iterdir()
    assert ros.spin_until(lambda: len(snapshot(folder / "bag", tmp_path)) > 300, timeout_s=60), (
        "the recorder wrote nothing out"
    )
    return proc, folder


def recorder_pid(proc):
    """The recorder among the children of the `haven run` process."""
    children = [int(c) for t in Path(f"/proc/{proc.pid}/task").glob("*/children") for c in t.read_text().split()]
    for pid in children:
        try:
            if b"haven_scenarios.nodes.recorder" in Path(f"/proc/{pid}/cmdline").read_bytes():
                return pid
        except OSError:
            continue
    raise AssertionError(f"no recorder among the children {children} of haven run")


def finished(proc, tmp_path):
    proc.wait(timeout=180)
    return proc.returncode, (tmp_path / "run.out").read_text(), (tmp_path / "run.err").read_text()


def snapshot(bag, tmp_path):
    """What the bag's MCAP file holds now: the messages a repair must keep (the file only grows)."""
    copy = tmp_path / "snapshot.mcap"
    copy.write_bytes((bag / "bag.mcap").read_bytes())
    return [(c.topic, t, d) for c, t, d in recovered_records(copy)]


def assert_repaired_and_readable(folder, kept):
    """A proper bag now (AnyReader; the mcap reader with the summary), holding first every
    message that was in the file before the recorder died, in the order recorded."""
    bag = folder / "bag"
    assert sorted(p.name for p in bag.iterdir()) == ["bag.mcap", "bag.mcap.damaged", "metadata.yaml"]
    info = json.loads((folder / "session.json").read_text())
    n = info["bag_repaired"]["messages"]
    assert n >= len(kept) > 100
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        topics = {c.topic: c.msgcount for c in reader.connections}
        assert sum(1 for _ in reader.messages()) == n
    assert topics["/odom"] > 50 and topics["/haven/events"] >= 1
    with open(bag / "bag.mcap", "rb") as f:
        reader = make_reader(f)
        assert reader.get_summary().statistics.message_count == n
        in_file = [(c.topic, m.log_time, bytes(m.data)) for _, c, m in reader.iter_messages(log_time_order=False)]
    assert in_file[: len(kept)] == kept
    return info


def assert_report_flags_it(folder, tmp_path):
    out = tmp_path / "report.csv"
    r = subprocess.run([*HAVEN, "report", str(folder), "--out", str(out)], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and "1 flagged not valid" in r.stdout, r.stderr
    (row,) = csv.DictReader(out.open())
    assert row["valid"] == "False" and "bag repaired: its recorder did not close it" in row["invalid_reasons"]
    assert float(row["robot_path_length_m"]) > 0.0  # the repaired data is in the report


def test_a_recorder_killed_mid_trial_is_named_and_its_bag_repaired(ros, tmp_path):
    proc, folder = start_run(ros, tmp_path)
    pid = recorder_pid(proc)
    kept = snapshot(folder / "bag", tmp_path)
    os.kill(pid, signal.SIGKILL)
    code, out, err = finished(proc, tmp_path)
    assert code == 1 and "haven: recorder was killed by SIGKILL; the trial was cut short" in err, err[-3000:]
    assert tracebacks(err) == []
    assert f"haven: repaired {folder / 'bag'}: " in err and f"haven: session in {folder}" in out
    info = assert_repaired_and_readable(folder, kept)
    assert (
        info["outcome"].startswith("cut short: recorder was killed by SIGKILL; bag repaired (")
        and info["valid"] is False
    )
    # (record/recorder_stop.py: never verified complete)
    repaired = "rebuilt by a repair (what the recorder still held was lost)"
    assert info["recorder_stop"] == {
        "exit": "recorder was killed by SIGKILL",
        "code": -9,
        "during": "during the trial",
        "bag_verified": False,
        "why": repaired,
    }
    assert_report_flags_it(folder, tmp_path)


def test_a_full_disk_stops_the_recorder_in_one_line_and_keeps_what_it_wrote(ros, tmp_path):
    proc, folder = start_run(ros, tmp_path)
    pid = recorder_pid(proc)
    bag = folder / "bag"
    limit = (bag / "bag.mcap").stat().st_size + 64_000
    resource.prlimit(pid, resource.RLIMIT_FSIZE, (limit, limit))
    kept = snapshot(bag, tmp_path)  # (after the limit: the file never grows past it)
    code, _out, err = finished(proc, tmp_path)
    assert code == 1 and tracebacks(err) == [], err[-3000:]
    said = [line for line in err.splitlines() if line.startswith("recorder: error:")]
    assert len(said) == 1 and said[0].startswith(
        f"recorder: error: cannot write {bag.resolve() / 'bag.mcap'}: File too large"
    ), err[-3000:]
    assert "haven: recorder exited with code 1; the trial was cut short" in err
    assert (bag / "bag.mcap.damaged").stat().st_size <= limit
    info = assert_repaired_and_readable(folder, kept)
    assert info["outcome"].startswith("cut short: recorder exited with code 1; bag repaired (")
    assert info["recorder_stop"]["code"] == 1 and info["recorder_stop"]["bag_verified"] is False
    assert_report_flags_it(folder, tmp_path)
