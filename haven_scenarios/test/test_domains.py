"""The lab's range of ROS domains (`--domains A-B`, HAVEN_DOMAINS): a suite never takes a domain
outside it, whichever suites already run; checked at the layer that chooses (run/domains.py),
with the domains' locks held by other processes, as other suites hold them. The graph probe (a
subprocess with rclpy) is replaced by one that sees no node: the locks alone decide here."""

import subprocess
import sys

import pytest

from haven_scenarios.run import domains
from haven_scenarios.run.domains import DomainBusy, DomainRange, claim_domain, parse_domains
from haven_scenarios.tools.cli import main

HOLD = """
import sys
from haven_scenarios.run.domains import lock_path
from haven_scenarios.run.locks import FileLock
held = [FileLock(lock_path(int(d)), "haven run (another suite)").acquire() for d in sys.argv[1:]]
print("held", flush=True)
sys.stdin.read()
"""


@pytest.fixture
def lab(tmp_path, monkeypatch):
    """Locks in a folder of this test's own (no suite of anyone else's on this machine counts);
    `hold(*ids)` holds those domains' locks in another process until the test ends."""
    monkeypatch.setenv("HAVEN_LOCK_DIR", str(tmp_path))
    monkeypatch.setattr(domains, "nodes_on", lambda *a, **k: [])
    holders = []

    def hold(*ids):
        p = subprocess.Popen(
            [sys.executable, "-c", HOLD, *map(str, ids)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True
        )
        holders.append(p)
        assert p.stdout.readline() == "held\n"

    yield hold
    for p in holders:
        p.stdin.close()
        p.wait(timeout=10)


def test_a_second_and_a_third_suite_stay_inside_the_range(lab):
    env = {"ROS_DOMAIN_ID": "0"}  # (the inherited domain lies outside the range)
    lab_range = parse_domains("30-39")
    first = claim_domain(None, env, domains=lab_range)
    assert first.domain_id == 30 and first.moved_from == (0, "outside --domains 30-39")
    first.release()
    lab(30)  # the first suite runs on (in another process)
    second = claim_domain(None, env, domains=lab_range)
    second.release()
    lab(31)
    third = claim_domain(None, env, domains=lab_range)
    assert (second.domain_id, third.domain_id) == (31, 32)
    third.release()
    lab(*range(32, 40))
    with pytest.raises(DomainBusy) as busy:
        claim_domain(None, env, domains=lab_range)
    assert str(busy.value).startswith("no free ROS domain in --domains 30-39: ") and "\n" not in str(busy.value)


def test_the_inherited_domain_inside_the_range_is_kept_and_the_environment_gives_the_range(lab):
    got = claim_domain(None, {"ROS_DOMAIN_ID": "35", "HAVEN_DOMAINS": "30-39"})
    assert (got.domain_id, got.moved_from) == (35, None)
    got.release()
    lab(35)
    moved = claim_domain(None, {"ROS_DOMAIN_ID": "35", "HAVEN_DOMAINS": "30-39"})
    assert (
        moved.domain_id == 30 and moved.moved_from[0] == 35 and "another HAVEN suite runs on it" in moved.moved_from[1]
    )
    moved.release()
    flag_wins = claim_domain(None, {"ROS_DOMAIN_ID": "35", "HAVEN_DOMAINS": "30-39"}, domains=DomainRange(50, 52))
    assert flag_wins.domain_id == 50 and flag_wins.moved_from == (35, "outside --domains 50-52")


def test_an_explicit_domain_outside_the_range_and_a_bad_range_are_refused_in_one_line(lab):
    with pytest.raises(DomainBusy, match=r"^--domain-id 12 is outside --domains 30-39: choose one inside it"):
        claim_domain(12, {}, domains=parse_domains("30-39"))
    with pytest.raises(DomainBusy, match=r"^--domain-id 12 is outside HAVEN_DOMAINS 30-39: "):
        claim_domain(12, {"HAVEN_DOMAINS": "30-39"})
    with pytest.raises(
        DomainBusy,
        match=(
            r"^HAVEN_DOMAINS: expected A-B, ROS domain ids 0..232 "
            r"\(e.g. 30-39\), got 'thirty' \(in the environment\)$"
        ),
    ):
        claim_domain(None, {"HAVEN_DOMAINS": "thirty"})
    assert claim_domain(33, {}, domains=parse_domains("30-39")).domain_id == 33
    assert parse_domains(" 7 ") == DomainRange(7, 7)


@pytest.mark.parametrize(
    "text, says",
    [
        ("39-30", "argument --domains: 39-30: 39 is above 30"),
        ("30-300", "argument --domains: 30-300: 300 is not a ROS domain id (0..232)"),
        ("-3", "argument --domains: expected A-B, ROS domain ids 0..232 (e.g. 30-39), got '-3'"),
        ("30-39-40", "argument --domains: expected A-B"),
    ],
)
def test_a_bad_domains_option_is_one_line_before_anything_starts(text, says, capsys):
    with pytest.raises(SystemExit) as e:
        main(["run", "--domains", text])
    err = capsys.readouterr().err
    assert e.value.code == 2 and says in err and "Traceback" not in err


def test_haven_run_says_in_one_line_when_no_domain_of_the_range_is_free(lab, tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("HAVEN_DOMAINS", "40-41")
    lab(40, 41)
    code = main(["run", "hallway", "--sessions", str(tmp_path / "s")])
    err = capsys.readouterr().err
    said = (
        "no free ROS domain in HAVEN_DOMAINS 40-41: each runs another "
        "HAVEN suite or other ROS nodes (widen the range, or stop one)"
    )
    assert code == 2 and err == f"haven: error: {said}\n"
    assert not (tmp_path / "s").exists()  # nothing started, nothing written


def test_serve_hands_the_range_to_every_participants_runner_and_refuses_one_smaller_than_its_capacity(
    tmp_path, monkeypatch
):
    from haven_scenarios import api
    from haven_scenarios.conduct.online_study import open_server
    from haven_scenarios.conduct.recorded_trial import TrialError

    study = tmp_path / "study.yaml"
    study.write_text("name: d\nscenarios: [hallway]\nconditions: {none: [none]}\nparticipants: 2\n")
    server = open_server(str(study), tmp_path / "st", port=0, capacity=2, domains="30-39")
    try:
        seat = server.seats.join("PANEL_1")
        argv = server.runner_argv(seat)
        assert argv[argv.index("--domains") + 1] == "30-39"
        # the session key is not on the command line (`ps` shows it to anyone)
        assert not any(seat.key in a for a in argv)
    finally:
        server.server.stop()
    with pytest.raises(
        ValueError,
        match=r"^--domains 30-30: fewer ROS domains than --capacity 2 \(each participant's trial takes one\)$",
    ):
        open_server(str(study), tmp_path / "st", port=0, capacity=2, domains="30-30")
    monkeypatch.setenv("HAVEN_DOMAINS", "39-30")
    with pytest.raises(ValueError, match=r"^HAVEN_DOMAINS: 39-30: 39 is above 30 \(in the environment\)$"):
        open_server(str(study), tmp_path / "st", port=0)
    with pytest.raises(TrialError, match=r"^domains: expected A-B"):
        api.recorded_trial("hallway", domains="all of them")
