"""Telling the suite's messages from outside ones on the lockstep clock (runtime/suite_messages.py):
a reader handles exactly what its tick announces, whatever else comes on the same topic."""

from haven_sim.runtime.suite_messages import Expected, InputLimit, OutsideInputs, Queue, digest


def raw(text: str) -> bytes:
    return text.encode()


def test_expected_names_each_readers_messages_and_only_the_newest_of_a_state_stream():
    e = Expected()
    e.reads("planner", ["goal_pose", "odom"])
    e.reads("controller", ["odom", "plan"])
    e.sent("odom", [digest(raw("o1"))])
    e.sent("odom", [digest(raw("o2"))])
    e.sent("goal_pose", [digest(raw("g1")), digest(raw("g2"))])
    e.sent("scan", [digest(raw("s"))])  # read by no participant
    assert e.take("planner") == {"odom": [digest(raw("o2"))], "goal_pose": [digest(raw("g1")), digest(raw("g2"))]}
    assert e.take("planner") == {}
    assert e.take("controller") == {"odom": [digest(raw("o2"))]}


def test_a_flood_on_the_same_topic_neither_delays_nor_displaces_the_suites_goal():
    q = Queue("goal_pose")
    flood = [raw(f"outside {k}") for k in range(1000)]
    q.add([*flood[:500], raw("ours"), *flood[500:]])
    assert not q.missing([digest(raw("ours"))])
    ours, outside = q.split([digest(raw("ours"))])
    # the rest waits one act: it may be another participant's of this step
    assert ours == [raw("ours")] and outside == []
    q.add([raw("late ours")])
    ours, outside = q.split([digest(raw("late ours"))])
    assert ours == [raw("late ours")] and outside == flood


def test_an_announced_message_that_never_came_is_given_up_once_and_dropped_if_it_comes():
    q = Queue("plan", settle=0)
    assert q.missing([digest(raw("p1"))]) == {digest(raw("p1")): 1}
    q.give_up(q.missing([digest(raw("p1"))]))
    q.add([raw("p1"), raw("p2")])
    assert q.split([digest(raw("p2"))]) == ([raw("p2")], [])  # the late p1 is neither ours now nor outside


def test_a_state_stream_hands_over_its_newest_announced_message():
    q = Queue("odom", settle=1)
    q.add([raw("o1"), raw("x"), raw("o2"), raw("y")])
    assert q.split([digest(raw("o2"))]) == ([raw("o2")], [raw("y")])
    assert q.entries == []


def test_outside_messages_are_ignored_on_owned_topics_unless_opened_and_limited_elsewhere():
    o = OutsideInputs(
        owned=frozenset({"/goal_pose", "/plan"}), opened=frozenset({"/plan"}), limit=InputLimit(rate_hz=10.0, burst=5)
    )
    assert o.take("goal_pose", [raw("g")] * 7, now=1.0) == [] and o.ignored["/goal_pose"] == 7
    assert o.take("odom", [raw("o")], now=1.0) == []  # a state stream is never taken from outside
    teleop = [raw(f"t{k}") for k in range(8)]
    assert o.take("cmd_vel_teleop", teleop, now=1.0) == teleop[-5:]  # the newest, up to the burst
    assert o.take("cmd_vel_teleop", teleop, now=1.2) == teleop[-2:]  # 10 a second
    assert o.take("plan", [raw("p")], now=1.2) == [raw("p")]  # opened by the run
    assert o.limit.dropped["/cmd_vel_teleop"] == 9 and o.taken["/cmd_vel_teleop"] == 7
