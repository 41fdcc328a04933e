"""Bags their recorder never closed: repaired into proper rosbag2 bags that readers we did not write
open (rosbags' AnyReader, the mcap library's reader with the summary), with every message the
damaged file still holds, the topics' types and QoS, and a note that they were repaired.

Bags are written with our BagWriter (as the recorder writes them, flushed as it flushes) and then
damaged the way a killed recorder or a full disk leaves them: metadata.yaml gone, the MCAP file cut
(no summary, no footer, a chunk cut in half). A full disk during the repair is made honestly,
without root: the repair runs in a child process whose file size limit (RLIMIT_FSIZE, set in
preexec_fn) is below the repaired bag's size; Python ignores SIGXFSZ, so the write fails with EFBIG
as it would with ENOSPC on a full disk.
"""

import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from mcap.reader import make_reader
from rosbags.highlevel import AnyReader
from rosbags.interfaces import Qos, QosDurability, QosHistory, QosLiveliness, QosReliability, QosTime
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.typesys import Stores, get_typestore
from rosbags.typesys.msg import get_types_from_msg

from haven_scenarios.record.bag import (
    REPAIRED_KEY,
    TYPESTORE,
    BagWriter,
    custom_data,
    lost_messages,
    readable,
    recovered_records,
)
from haven_scenarios.record.repair import Repaired, RepairError, needs_repair, repair

pytestmark = pytest.mark.integration

FOREVER = QosTime(2**31 - 1, 0)
LATCHED = Qos(
    QosHistory.KEEP_LAST,
    1,
    QosReliability.RELIABLE,
    QosDurability.TRANSIENT_LOCAL,
    FOREVER,
    FOREVER,
    QosLiveliness.AUTOMATIC,
    FOREVER,
    False,
)
STRING, UINT32 = TYPESTORE.types["std_msgs/msg/String"], TYPESTORE.types["std_msgs/msg/UInt32"]


def text(s):
    return bytes(TYPESTORE.serialize_cdr(STRING(data=s), "std_msgs/msg/String"))


def number(n):
    return bytes(TYPESTORE.serialize_cdr(UINT32(data=n), "std_msgs/msg/UInt32"))


def write_bag(bag, n=2000, flush_every=100, lost=None):
    """A bag as the recorder writes it: a latched topic, a stream, chunks flushed as it goes;
    returns what was written, in order: (topic, stamp ns, CDR bytes)."""
    written = []
    with BagWriter(bag) as w:
        w.add_topic("/map_name", "std_msgs/msg/String", [LATCHED])
        w.add_topic("/count", "std_msgs/msg/UInt32")
        written.append(("/map_name", 0, text("small_test")))
        w.write(*written[-1])
        for i in range(n):
            written.append(("/count", 1_000_000 * (i + 1), number(i)))
            w.write(*written[-1])
            if (i + 1) % flush_every == 0:
                w.flush()
        w.close(lost=lost)
    return written


def kill(bag, keep=0.6):
    """A recorder killed mid-write: no metadata.yaml, the MCAP file cut inside a chunk."""
    (bag / "metadata.yaml").unlink()
    mcap = bag / "bag.mcap"
    data = mcap.read_bytes()
    mcap.write_bytes(data[: int(len(data) * keep)])
    return mcap.read_bytes()


def read_with_rosbags(bag):
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        connections = {c.topic: c for c in reader.connections}
        return connections, [(c.topic, t, bytes(raw)) for c, t, raw in reader.messages()]


def read_with_mcap(bag):
    with open(bag / "bag.mcap", "rb") as f:
        reader = make_reader(f)
        summary = reader.get_summary()
        messages = [(c.topic, m.log_time, bytes(m.data)) for _, c, m in reader.iter_messages()]
    return summary, messages


def test_a_killed_recorders_bag_is_rebuilt_and_opens_in_readers_we_did_not_write(tmp_path):
    bag = tmp_path / "bag"
    written = write_bag(bag)
    damaged = kill(bag)
    assert needs_repair(bag) and not readable(bag)
    held = [(c.topic, t, d) for c, t, d in recovered_records(bag / "bag.mcap")]
    assert 0.5 * len(written) < len(held) < 0.7 * len(written)
    assert held == written[: len(held)]  # every whole message before the cut, in order

    done = repair(bag)
    assert done.messages == len(held) and done.topics == 2 and not done.skipped
    assert sorted(p.name for p in bag.iterdir()) == ["bag.mcap", "bag.mcap.damaged", "metadata.yaml"]
    assert (bag / "bag.mcap.damaged").read_bytes() == damaged  # the original, kept as it was
    assert not needs_repair(bag) and readable(bag)

    connections, messages = read_with_rosbags(bag)
    assert sorted(messages, key=lambda m: m[1]) == sorted(held, key=lambda m: m[1])
    assert (
        connections["/count"].msgtype == "std_msgs/msg/UInt32"
        and connections["/map_name"].msgtype == "std_msgs/msg/String"
    )
    assert [q.durability for q in connections["/map_name"].ext.offered_qos_profiles] == [QosDurability.TRANSIENT_LOCAL]
    assert connections["/count"].digest == TYPESTORE.hash_rihs01("std_msgs/msg/UInt32")
    summary, messages = read_with_mcap(bag)
    assert summary is not None and summary.statistics.message_count == len(held)
    assert sorted(messages, key=lambda m: m[1]) == sorted(held, key=lambda m: m[1])
    note = json.loads(custom_data(bag)[REPAIRED_KEY])
    assert note["messages"] == len(held) and note["from"] == ["bag.mcap"]


def message_ends(data):
    """Where each message record of an MCAP file ends, found by walking the format's records
    (opcode, length) ourselves: chunks (rosbags writes them uncompressed) and the records in them."""
    ends, pos = [], 8  # after the magic
    while pos + 9 <= len(data):
        op, n = data[pos], int.from_bytes(data[pos + 1 : pos + 9], "little")
        body = pos + 9
        if op == 0x06:  # a chunk: start, end, size (8 each), crc (4), compression (string), records (length, bytes)
            inner = body + 28 + 4 + int.from_bytes(data[body + 28 : body + 32], "little") + 8
            while inner < body + n:
                m = int.from_bytes(data[inner + 1 : inner + 9], "little")
                if data[inner] == 0x05:
                    ends.append(inner + 9 + m)
                inner += 9 + m
        pos = body + n
    return ends


@pytest.mark.parametrize("keep", [0.02, 0.33, 0.5, 0.77, 0.999])
def test_every_whole_message_before_the_cut_is_kept_wherever_it_falls(tmp_path, keep):
    bag = tmp_path / "bag"
    written = write_bag(bag, n=500, flush_every=200)  # three chunks: the cut falls in one of them
    ends = message_ends((bag / "bag.mcap").read_bytes())
    assert len(ends) == len(written)
    cut = len(kill(bag, keep))
    done = repair(bag)
    _, messages = read_with_rosbags(bag)
    assert done.messages == sum(1 for e in ends if e <= cut)  # exactly the messages whose record is whole
    assert messages == written[: done.messages]


def test_a_recorder_killed_outright_loses_only_what_it_had_not_flushed(tmp_path):
    """A child writes a bag, flushes (as the recorder does every second), writes more, and is
    killed with SIGKILL before it can close the bag."""
    bag = tmp_path / "bag"
    script = textwrap.dedent(f"""
        import os, signal
        from pathlib import Path
        from haven_scenarios.record.bag import TYPESTORE, BagWriter
        U = TYPESTORE.types["std_msgs/msg/UInt32"]
        w = BagWriter(Path({str(bag)!r})).__enter__()
        w.add_topic("/count", "std_msgs/msg/UInt32")
        for i in range(1000):
            w.write("/count", i, bytes(TYPESTORE.serialize_cdr(U(data=i), "std_msgs/msg/UInt32")))
            if i == 699:
                w.flush()
        os.kill(os.getpid(), signal.SIGKILL)
    """)
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert r.returncode == -signal.SIGKILL, r.stderr
    assert needs_repair(bag)
    assert repair(bag).messages == 700
    _, messages = read_with_rosbags(bag)
    assert [t for _, t, _ in messages] == list(range(700))


def test_a_stale_metadata_file_is_kept_and_its_custom_data_carried_over(tmp_path):
    bag = tmp_path / "bag"
    written = write_bag(bag, lost={"/count": 3})
    mcap = bag / "bag.mcap"
    mcap.write_bytes(mcap.read_bytes()[:-200])  # the footer gone, metadata.yaml still there
    old_metadata = (bag / "metadata.yaml").read_text()
    assert needs_repair(bag)
    done = repair(bag)
    assert done.messages == len(written)  # every chunk was whole
    assert (bag / "metadata.yaml.damaged").read_text() == old_metadata
    assert lost_messages(bag) == {"/count": 3} and REPAIRED_KEY in custom_data(bag)


def test_a_type_this_ros_does_not_know_is_rebuilt_from_its_recorded_definition(tmp_path):
    definition = "string name\nuint32 n\n"
    store = get_typestore(Stores.EMPTY)
    store.register(get_types_from_msg(definition, "lab_msgs/msg/Thing"))
    bag = tmp_path / "bag"
    with Writer(bag, version=9, storage_plugin=StoragePlugin.MCAP) as w:
        conn = w.add_connection("/thing", "lab_msgs/msg/Thing", typestore=store)
        for i in range(20):
            w.write(
                conn,
                i,
                bytes(store.serialize_cdr(store.types["lab_msgs/msg/Thing"](name=f"t{i}", n=i), "lab_msgs/msg/Thing")),
            )
    kill(bag, keep=0.97)
    done = repair(bag)
    assert done.messages == 20 and not done.skipped
    with AnyReader([bag]) as reader:  # the type comes from the bag itself
        (c,) = reader.connections
        assert c.digest == store.hash_rihs01("lab_msgs/msg/Thing")
        assert [reader.deserialize(raw, c.msgtype).name for _, _, raw in reader.messages()] == [
            f"t{i}" for i in range(20)
        ]


def _limit_file_size(limit):
    def apply():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    return apply


def test_a_full_disk_during_the_repair_leaves_the_damaged_bag_as_it_was(tmp_path):
    bag = tmp_path / "bag"
    write_bag(bag, n=4000)
    damaged = kill(bag, keep=0.9)
    script = (
        "import sys; from pathlib import Path; from haven_scenarios.tools.cli import main; "
        "sys.exit(main(['repair', sys.argv[1]]))"
    )
    r = subprocess.run(
        [sys.executable, "-c", script, str(bag)],
        capture_output=True,
        text=True,
        timeout=120,
        preexec_fn=_limit_file_size(len(damaged) // 2),
    )
    assert r.returncode == 1 and "Traceback" not in r.stderr
    (line,) = r.stderr.strip().splitlines()
    assert (
        line.startswith(f"haven: {bag}: could not write the repaired bag: File too large") and "left as it was" in line
    )
    assert sorted(p.name for p in bag.iterdir()) == ["bag.mcap"] and (bag / "bag.mcap").read_bytes() == damaged
    assert needs_repair(bag)
    assert repair(bag).messages > 0  # with room on the disk, the same bag repairs


def test_nothing_to_repair_in_a_whole_bag_or_an_empty_folder(tmp_path):
    bag = tmp_path / "bag"
    write_bag(bag, n=10)
    assert not needs_repair(bag)
    empty = tmp_path / "empty"
    empty.mkdir()
    assert not needs_repair(empty)
    with pytest.raises(RepairError, match="no MCAP file"):
        repair(empty)


def test_an_interrupted_repair_can_be_run_again(tmp_path):
    """A repair cut short after it renamed the damaged file but before it moved the new bag in
    (power lost): the damaged original is still the source."""
    bag = tmp_path / "bag"
    written = write_bag(bag, n=300)
    kill(bag, keep=0.8)
    shutil.move(bag / "bag.mcap", bag / "bag.mcap.damaged")
    os.makedirs(bag / ".repairing" / "bag")
    assert needs_repair(bag)
    done = repair(bag)
    _, messages = read_with_rosbags(bag)
    assert messages == written[: done.messages] and done.messages > 0
    assert sorted(p.name for p in bag.iterdir()) == ["bag.mcap", "bag.mcap.damaged", "metadata.yaml"]


@pytest.fixture(scope="module")
def killed_session(tmp_path_factory):
    """A session folder as `haven run` leaves it when its recorder was killed mid-trial (from a
    batch trial recorded the recorder's way: test_sessions.record_batch_trial)."""
    from test_sessions import record_batch_trial

    folder = tmp_path_factory.mktemp("study") / "hallway_sim_1"
    record_batch_trial(folder, "hallway")
    kill(folder / "bag", keep=0.7)
    return folder


def test_haven_repair_rebuilds_a_session_and_report_includes_it_flagged(killed_session, tmp_path, capsys):
    from haven_scenarios.record.report import report_csv
    from haven_scenarios.tools.cli import main

    study = tmp_path / "study"
    folder = study / killed_session.name
    shutil.copytree(killed_session, folder)
    assert main(["repair", str(study)]) == 0
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line.startswith(f"haven: repaired {folder / 'bag'}: ") and "kept as bag.mcap.damaged" in line
    info = json.loads((folder / "session.json").read_text())
    assert info["bag_repaired"]["messages"] > 1000 and info["bag_repaired"]["kept"] == ["bag.mcap.damaged"]
    assert info["outcome"].startswith("unknown") and info["valid"] is False  # (haven run never wrote one)
    metrics = json.loads((folder / "metrics.json").read_text())
    assert metrics["valid"] is False and metrics["invalid_reasons"][0].startswith(
        "bag repaired: its recorder did not close it"
    )
    row = report_csv([study], tmp_path / "report.csv")[0]
    assert row["valid"] is False and "bag repaired" in row["invalid_reasons"]
    assert row["robot_path_length_m"] > 5.0  # the repaired data is in the row
    assert main(["repair", str(folder)]) == 0
    assert "a complete bag, nothing to repair" in capsys.readouterr().out
    by_bag = study / "by_bag"  # a session's bag folder named directly: the session is updated too
    shutil.copytree(killed_session, by_bag)
    assert main(["repair", str(by_bag / "bag")]) == 0 and "bag_repaired" in json.loads(
        (by_bag / "session.json").read_text()
    )
    capsys.readouterr()
    assert main(["repair", str(tmp_path / "nothing")]) == 2
    assert capsys.readouterr().err.strip() == f"haven: error: {tmp_path / 'nothing'}: no such session folder or bag"


def test_session_json_says_how_the_run_ended():
    from haven_scenarios.conduct.outcomes import Ended, exit_text, outcome
    from haven_scenarios.run.supervisor import Exited

    assert exit_text("recorder", -signal.SIGKILL) == "recorder was killed by SIGKILL"
    assert (
        exit_text("planner", 1) == "planner exited with code 1"
        and exit_text("sim", -99) == "sim was killed by signal 99"
    )
    done = Repaired(Path("bag"), 812, 21, (Path("bag/bag.mcap.damaged"),))
    cases = [
        (Ended(Exited("scenario", 0), recorder_code=0), "completed", None, "completed"),
        (
            Ended(Exited("recorder", -9), recorder_code=-9),
            "interrupted",
            done,
            "cut short: recorder was killed by SIGKILL; bag repaired (812 messages recovered)",
        ),
        (Ended(Exited("planner", 1), recorder_code=0), "interrupted", None, "cut short: planner exited with code 1"),
        (Ended(None, recorder_code=0), "interrupted", None, "interrupted (stopped by a signal)"),
        (
            Ended(None, timed_out=True, recorder_code=0),
            "interrupted",
            None,
            "cut short: the trial did not end within 360 s (wall)",
        ),
        (
            Ended(Exited("scenario", 0), recorder_code=-9),
            "completed",
            done,
            "completed; recorder was killed by SIGKILL while stopping; bag repaired (812 messages recovered)",
        ),
        (None, None, None, "interrupted: haven run stopped before the nodes were stopped in order"),
    ]
    for ended, reason, repaired, said in cases:
        assert outcome(ended, reason, repaired, 360.0) == said
