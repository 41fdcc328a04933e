"""A world from a ROS map the test makes itself (haven_sim/test/map_maker.py: a map_server PGM +
YAML and an overlay), run as every mode runs a world: `haven batch`, and `haven run` recorded,
whose bag's /map is the source map, read with rosbags (a reader we did not write). The browser
trial on it is in test_web_browser.py."""

import csv
import json
import subprocess
import sys

import numpy as np
import pytest
from map_maker import ORIGIN, RESOLUTION, make_map_world, map_pixels

HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]


@pytest.mark.integration
def test_haven_batch_runs_a_world_made_from_a_ros_map(tmp_path):
    scenario = make_map_world(tmp_path / "map")
    out = tmp_path / "rows.csv"
    argv = [*HAVEN, "batch", str(scenario), "--seeds", "0-1", "--grid", "model=walker,yielder", "--out", str(out)]
    r = subprocess.run(argv, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-2000:]
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 4
    assert all(row["end_reason"] == "completed" and int(row["human_contacts"]) == 0 for row in rows), rows


@pytest.mark.integration
def test_haven_validate_takes_a_world_made_from_a_ros_map(tmp_path):
    scenario = make_map_world(tmp_path / "map")
    world = scenario.parent / "world.yaml"
    r = subprocess.run([*HAVEN, "validate", str(world), str(scenario)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and "(world test_map)" in r.stdout, r.stdout + r.stderr


LIBRARY = ("path_line", "projected_arrows", "light_ring")


@pytest.mark.ros
def test_haven_run_records_a_map_world_whose_map_is_the_source_map_and_the_library_cues(ros, tmp_path):
    """One recorded trial for two things: a world from a ROS map, and the cue library's markers and
    values in the bag (the condition names the three library cues)."""
    from rosbags.highlevel import AnyReader
    from test_ros_trial import assert_independent_score_agrees, haven_run, metrics_of, only_session

    scenario = make_map_world(tmp_path / "map")
    haven_run(ros, "run", str(scenario), "--condition", *LIBRARY, "--sessions", str(tmp_path / "s"))
    session = only_session(tmp_path / "s")
    metrics = metrics_of(session)
    assert metrics["end_reason"] == "completed" and metrics["condition"] == "+".join(LIBRARY)
    assert all(metrics[f"{cue}_shown_s"] > 0 for cue in LIBRARY), metrics
    # the session holds its map
    assert (session / "world_map.pgm").read_bytes() == (tmp_path / "map" / "map.pgm").read_bytes()
    assert_independent_score_agrees(session)
    with AnyReader([session / "bag"]) as reader:
        (conn,) = [c for c in reader.connections if c.topic == "/map"]
        maps = [reader.deserialize(raw, conn.msgtype) for _, _, raw in reader.messages(connections=[conn])]
        (ar,) = [c for c in reader.connections if c.topic == "/haven/ar_markers"]
        drawn = {
            m.ns
            for _, _, raw in reader.messages(connections=[ar])
            for m in reader.deserialize(raw, ar.msgtype).markers
            if m.action == 0
        }
        (state,) = [c for c in reader.connections if c.topic == "/haven/cue_state"]
        values = [
            json.loads(reader.deserialize(raw, state.msgtype).data)
            for _, _, raw in reader.messages(connections=[state])
        ]
    assert set(LIBRARY) <= drawn and not drawn & {"path_projection", "turn_signals"}, drawn
    assert any(v.get("path_line", 0) > 0 for v in values) and any(v.get("projected_arrows", 0) > 0 for v in values)
    # it blinked for a turn
    assert any(isinstance(v.get("light_ring"), dict) and v["light_ring"]["blink"] != 0 for v in values)
    assert maps
    info = maps[-1].info
    pixels = map_pixels()
    assert (info.width, info.height) == (pixels.shape[1], pixels.shape[0])
    assert info.resolution == pytest.approx(RESOLUTION) and (info.origin.position.x, info.origin.position.y) == ORIGIN
    # map_server's trinary values, rows bottom-up (map_io: data[width * (height - y - 1) + x])
    expected = np.where(pixels == 0, 100, np.where(pixels == 254, 0, -1))[::-1].ravel()
    assert (np.asarray(maps[-1].data, dtype=np.int8) == expected).all()
