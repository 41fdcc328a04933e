"""Session folders without starting ROS: a batch trial recorded into a bag the way the recorder
writes one (the suite's topic table, CDR, rosbag2 MCAP), then read back, moved, damaged, reported.
The bag's receive times are made late and jittered, as a loaded recorder's are: the metrics must
come from the header stamps and agree with the batch trial's own."""

import csv
import json
import random
import shutil

import pytest
from rclpy.serialization import serialize_message

from haven_scenarios.record.bag import BagWriter, read_recording
from haven_scenarios.record.report import report_csv
from haven_scenarios.record.session import analyse, trajectory_picture, write_inputs, write_json
from haven_scenarios.run.trial import Trial
from haven_scenarios.study.scenario import load_scenario
from haven_sim.nodes import wire
from haven_sim.nodes.wire import type_name
from haven_viz.nodes.conversions import viz_specs

pytestmark = pytest.mark.integration

TABLE = {**wire.specs(), **viz_specs()}


def record_batch_trial(folder, name="shared_room", seed=0, delay_s=0.4):
    """A session folder as `haven run` leaves it, from a batch trial: scenario, world and params
    copies, session.json, and a bag whose receive times lag the header stamps by up to `delay_s`."""
    scenario = load_scenario(name)
    trial = Trial(scenario, seed)
    rng = random.Random(seed)
    messages = []
    trial.loop.observers.append(messages.append)
    result = trial.run()
    folder.mkdir(parents=True)
    write_inputs(folder, scenario, "{}\n")
    write_json(
        folder / "session.json",
        {"scenario": name, "seed": seed, "participant": "sim", "condition": "all", "humans": ["h1"]},
    )
    with BagWriter(folder / "bag") as bag:
        for m in messages:
            topic = "/" + m.topic
            spec = TABLE[m.topic]
            bag.add_topic(topic, type_name(spec.msg_type))
            received = m.stamp + rng.uniform(0.0, delay_s)
            bag.write(topic, int(received * 1e9), bytes(serialize_message(spec.encode(m.data, m.stamp))))
    return result


@pytest.fixture(scope="module")
def session(tmp_path_factory):
    folder = tmp_path_factory.mktemp("study") / "shared_room_sim_1"
    return folder, record_batch_trial(folder)


def test_metrics_from_a_late_jittered_bag_equal_the_batch_trials(session):
    """Defect: metrics sampled on the recorder's receive stamps (up to 0.4 s late under load)."""
    folder, batch = session
    metrics, world, _rec = analyse(folder)
    assert world is not None and metrics["valid"], metrics["invalid_reasons"]
    for key, value in batch.metrics.items():
        if key not in ("condition", "session", "condition_segments"):
            assert metrics[key] == value, key
    assert metrics["condition_segments"] == batch.metrics["condition_segments"]


def test_a_moved_study_folder_still_reads_and_pictures(session, tmp_path):
    """Defect: sessions loaded their scenario from an absolute path, so a moved folder failed."""
    folder, batch = session
    moved = tmp_path / "archive" / folder.name
    shutil.copytree(folder, moved)
    metrics, world, rec = analyse(moved)
    assert metrics["valid"] and metrics["robot_path_length_m"] == batch.metrics["robot_path_length_m"]
    assert trajectory_picture(moved, world, rec, "moved").stat().st_size > 20_000


def test_report_turns_damaged_sessions_into_flagged_rows(session, tmp_path):
    """Defect: `haven report` aborted with a traceback and wrote no CSV when one session had a
    truncated MCAP or no metadata.yaml (a recorder killed with SIGKILL)."""
    folder, batch = session
    good = tmp_path / "study" / "a_good"
    shutil.copytree(folder, good)
    cut = tmp_path / "study" / "b_killed"
    shutil.copytree(folder, cut)
    (cut / "bag" / "metadata.yaml").unlink()
    mcap = next((cut / "bag").glob("*.mcap"))
    data = mcap.read_bytes()
    mcap.write_bytes(data[: len(data) * 2 // 3])  # no footer, no summary, a record cut in half
    empty = tmp_path / "study" / "c_empty"
    (empty / "bag").mkdir(parents=True)
    (empty / "session.json").write_text("{not json")
    no_world = tmp_path / "study" / "d_no_world"  # a whole bag, but the world copy is gone
    shutil.copytree(folder, no_world)
    (no_world / "world.yaml").unlink()
    out = tmp_path / "report.csv"
    rows = report_csv([tmp_path / "study"], out)
    read = list(csv.DictReader(out.open()))
    assert [r["session"] for r in read] == ["a_good", "b_killed", "c_empty", "d_no_world"] and len(rows) == 4
    assert read[0]["valid"] == "True" and read[0]["robot_path_length_m"] == str(batch.metrics["robot_path_length_m"])
    assert read[1]["valid"] == "False" and "recovered from its MCAP data" in read[1]["invalid_reasons"]
    assert read[2]["valid"] == "False" and "holds no MCAP file" in read[2]["invalid_reasons"]
    assert "no scenario.yaml and no world.yaml in the session" in read[2]["invalid_reasons"]
    assert read[3]["valid"] == "False" and read[3]["invalid_reasons"].startswith("no world.yaml in the session")
    # Without the world the person's columns keep their id (from session.json), with what the bag says.
    assert read[3]["h1_path_length_m"] == read[0]["h1_path_length_m"]


def test_a_bag_without_footer_gives_back_what_it_holds(session, tmp_path):
    folder, _ = session
    cut = tmp_path / "bag"
    shutil.copytree(folder / "bag", cut)
    (cut / "metadata.yaml").unlink()
    mcap = next(cut.glob("*.mcap"))
    data = mcap.read_bytes()
    mcap.write_bytes(data[: len(data) // 2])
    rec, note = read_recording(cut, ["h1"])
    whole, _ = read_recording(folder / "bag", ["h1"])
    assert note.startswith("bag recovered") and 0.3 * len(whole.odom) < len(rec.odom) < 0.7 * len(whole.odom)
    in_order = sorted(whole.odom, key=lambda s: s[0])  # (the reader of a whole bag gives receive order)
    assert rec.odom == in_order[: len(rec.odom)]  # exactly the messages before the cut


def test_session_json_is_read_as_data_never_trusted(session, tmp_path):
    folder, _ = session
    odd = tmp_path / "odd"
    shutil.copytree(folder, odd)
    (odd / "session.json").write_text(json.dumps(["a", "list"]))
    metrics, _, _ = analyse(odd)
    assert metrics["valid"] and metrics["session"] == "odd"
