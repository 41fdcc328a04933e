"""The rule for a recorder that did not exit cleanly while the trial stopped (record/recorder_stop.py):
the session is valid only if its bag is verified complete (whole: metadata.yaml, MCAP summary and
footer, equal message counts, not repaired; and recorded through trial_end), and session.json says so.

Bags are written with our BagWriter as the recorder writes them (/odom at 50 Hz, /haven/events
with trial_start and trial_end), then left as a recorder killed while stopping leaves them:
complete (it was killed after it closed the bag), or cut (killed while closing: no metadata.yaml,
the MCAP file without its summary), or closed early (the streams end before trial_end).
"""

import json

import numpy as np

from haven_scenarios.record import recorder_stop
from haven_scenarios.record.bag import TYPESTORE, BagWriter, read_recording
from haven_scenarios.record.repair import repair
from haven_scenarios.record.session import SESSION_FILE, analyse
from haven_sim.common.events import EventKind, Source, event

T = TYPESTORE.types
KILLED = {"exit": "recorder was killed by SIGKILL", "code": -9, "during": "while stopping"}


def odometry(stamp: float, x: float) -> bytes:
    sec, nanosec = int(stamp), round((stamp - int(stamp)) * 1e9)
    header = T["std_msgs/msg/Header"](stamp=T["builtin_interfaces/msg/Time"](sec=sec, nanosec=nanosec), frame_id="odom")
    pose = T["geometry_msgs/msg/Pose"](
        position=T["geometry_msgs/msg/Point"](x=x, y=0.0, z=0.0),
        orientation=T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0),
    )
    zero = T["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=0.0)
    msg = T["nav_msgs/msg/Odometry"](
        header=header,
        child_frame_id="base_footprint",
        pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose, covariance=np.zeros(36)),
        twist=T["geometry_msgs/msg/TwistWithCovariance"](
            twist=T["geometry_msgs/msg/Twist"](linear=zero, angular=zero), covariance=np.zeros(36)
        ),
    )
    return bytes(TYPESTORE.serialize_cdr(msg, "nav_msgs/msg/Odometry"))


def text(data: str) -> bytes:
    return bytes(TYPESTORE.serialize_cdr(T["std_msgs/msg/String"](data=data), "std_msgs/msg/String"))


def write_trial(bag, end_s=4.0, odom_until_s=None):
    """A 4 s trial as the recorder writes it (flushed once a second of it); /odom up to `odom_until_s` (default: past
    the end)."""
    until = end_s + 0.04 if odom_until_s is None else odom_until_s
    with BagWriter(bag) as w:
        w.add_topic("/odom", "nav_msgs/msg/Odometry")
        w.add_topic("/haven/events", "std_msgs/msg/String")
        w.write(
            "/haven/events", 0, text(event(EventKind.TRIAL_START, 0.0, Source.SCENARIO, seq=1, scenario="s").to_json())
        )
        for i in range(round(until / 0.02) + 1):
            w.write("/odom", i * 20_000_000, odometry(i * 0.02, 0.01 * i))
            if i % 50 == 49:
                w.flush()
        end = event(EventKind.TRIAL_END, end_s, Source.SCENARIO, seq=2, reason="completed")
        w.write("/haven/events", int(end_s * 1e9), text(end.to_json()))


def cut(bag, keep=0.7):
    """Killed while closing: metadata.yaml not written yet, the MCAP file without its summary and footer."""
    (bag / "metadata.yaml").unlink()
    mcap = bag / "bag.mcap"
    mcap.write_bytes(mcap.read_bytes()[: int(mcap.stat().st_size * keep)])


def judge(bag, stop=KILLED):
    rec, _ = read_recording(bag)
    return recorder_stop.problem({recorder_stop.KEY: stop}, bag, rec), recorder_stop.judged(stop, bag, rec)


def test_a_complete_bag_keeps_a_killed_recorders_session_valid_and_session_json_says_it_was_verified(tmp_path):
    write_trial(tmp_path / "bag")
    reason, stop = judge(tmp_path / "bag")
    assert reason == ""
    assert stop == {**KILLED, "bag_verified": True, "why": "whole, and recorded through trial_end"}


def test_a_cut_bag_makes_it_not_valid_and_so_does_its_repair(tmp_path):
    bag = tmp_path / "bag"
    write_trial(bag)
    cut(bag)
    reason, stop = judge(bag)
    assert (
        reason
        == "recorder was killed by SIGKILL while stopping, and its bag is not verified complete: no metadata.yaml"
    )
    assert stop["bag_verified"] is False and stop["why"] == "no metadata.yaml"
    repair(bag)  # (as `haven run` does at once: a proper bag again, but what the recorder held is lost)
    assert judge(bag)[0].endswith(
        "its bag is not verified complete: rebuilt by a repair (what the recorder still held was lost)"
    )


def test_a_bag_closed_before_the_streams_reached_trial_end_is_not_verified(tmp_path):
    write_trial(tmp_path / "bag", end_s=4.0, odom_until_s=3.0)
    assert judge(tmp_path / "bag")[0].endswith(
        "its bag is not verified complete: /odom recorded only to 1.00 s before trial_end"
    )


def test_an_mcap_summary_that_disagrees_with_metadata_is_not_whole(tmp_path):
    bag = tmp_path / "bag"
    write_trial(bag)
    meta = bag / "metadata.yaml"
    n = len(read_recording(bag)[0].odom) + 2
    top = f"\n  message_count: {n}\n"  # (the bag's own count, beside the file's and each topic's)
    assert top in meta.read_text()
    meta.write_text(meta.read_text().replace(top, f"\n  message_count: {n + 5}\n"))
    assert recorder_stop.bag_whole(bag) == f"metadata.yaml counts {n + 5} messages, the MCAP summary {n}"


def test_a_clean_exit_is_its_own_evidence_and_a_session_without_the_record_is_not_judged(tmp_path):
    bag = tmp_path / "bag"
    write_trial(bag, odom_until_s=3.0)
    clean = {"exit": "recorder exited with code 0", "code": 0, "during": "while stopping"}
    reason, stop = judge(bag, clean)
    assert reason == "" and stop["bag_verified"] is True and stop["why"].startswith("closed by the recorder")
    rec, _ = read_recording(bag)
    assert recorder_stop.problem({}, bag, rec) == ""  # (a batch session, or one from before the rule)


def test_haven_report_rescoring_the_session_reaches_the_same_verdict(tmp_path):
    """`analyse` (what `haven run` and `haven report` score a session with) applies the rule from session.json."""
    folder = tmp_path / "session"
    write_trial(folder / "bag")
    cut(folder / "bag")
    (folder / SESSION_FILE).write_text(json.dumps({"scenario": "s", recorder_stop.KEY: KILLED}))
    metrics, _, _ = analyse(folder)
    said = "recorder was killed by SIGKILL while stopping, and its bag is not verified complete: no metadata.yaml"
    assert metrics["valid"] is False and said in metrics["invalid_reasons"]
