"""Publishers from outside the suite on the topics a trial rests on: seen by the recorder, judged
by the session's validity.

The recorder notes every publisher of every topic it records (`PublisherLog`: node name and
endpoint GID, first and last seen in sim time) and keeps the log in the bag's metadata
(custom_data `haven.publishers`). A publisher is the suite's when its node is one the run started
(`Declared.nodes`) and that node writes the topic (`WRITERS`); a second publisher under one of our
names is another suite's (two suites on one domain). Any other publisher on a topic the suite reads
or the metrics read (`watched`) is from outside; seen before the trial ends, it makes the session not
valid, unless the run declared the topic open to outside input, or the suite ignored it: on the
lockstep clock a node of the suite takes no message from outside on a topic the suite writes
(`runtime/suite_messages.py`; each says how many in `outside_input` events), so there only an
outside publisher on a topic the metrics read from the bag (`METRIC_TOPICS`) counts; the others are
noted (`outside_publishers`).
The topics a run may declare open:
- always open: /haven/estop (anyone may stop the robot; the mux logs each `cmd_source` change) and
  /haven/trial_control (the researcher's start, stop, abort; the end reason says which);
- the outputs of our nodes a run leaves out (`--without planner`: the user's planner publishes
  /plan and /haven/wait), and the velocity of each teleoperated person (`--teleop`);
- what the run allows with `--allow TOPIC` (a teleop node on /cmd_vel_teleop, RViz goals on
  /goal_pose, a researcher's thought text on /haven/wizard_thought).
"""

from __future__ import annotations

import fnmatch
import json
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field

from haven_sim.common import nodes, topics

# The topics the metrics read from a recording (record/timeline.py's Recording): an outsider's
# messages there are in the bag, whatever the suite made of them.
METRIC_TOPICS = (topics.ODOM, topics.HUMANS, topics.BATTERY, topics.CUE_STATE, topics.PLAN, topics.EVENTS)

# The ROS names of the suite's nodes (haven_sim/common/nodes.py).
SIM, MUX, PLANNER, CONTROLLER, VIZ, SCENARIO, WEB, RECORDER = (
    n.name
    for n in (
        nodes.SIM,
        nodes.MUX,
        nodes.PLANNER,
        nodes.CONTROLLER,
        nodes.VIZ,
        nodes.SCENARIO,
        nodes.WEB,
        nodes.RECORDER,
    )
)
EVERY_NODE = frozenset({SIM, MUX, PLANNER, CONTROLLER, VIZ, SCENARIO, WEB})


def _t(name: str) -> str:
    return "/" + name.lstrip("/")


# Topic (a glob for the per-person ones) -> the suite's nodes that publish it: the components'
# outputs (test_outsiders.py holds the table to them) and the web pages' allow-lists (web/access.py).
WRITERS: Mapping[str, frozenset[str]] = {
    **{
        _t(t): frozenset({SIM})
        for t in (topics.CLOCK, topics.MAP, topics.ODOM, topics.BATTERY, topics.HUMANS, topics.human_pose("*"))
    },
    _t(topics.CMD_VEL): frozenset({MUX}),
    _t(topics.CMD_VEL_NAV): frozenset({CONTROLLER}),
    _t(topics.CMD_VEL_TELEOP): frozenset({WEB}),  # the console's Wizard-of-Oz driving
    _t(topics.GOAL): frozenset({SCENARIO}),
    _t(topics.PLAN): frozenset({PLANNER}),
    _t(topics.WAIT): frozenset({PLANNER}),
    _t(topics.THOUGHT): frozenset({SCENARIO}),
    _t(topics.WIZARD_THOUGHT): frozenset({WEB}),
    _t(topics.EVENTS): EVERY_NODE,
    _t(topics.REMOVE_OBSTRUCTION): frozenset({SCENARIO}),
    _t(topics.CANCEL_GOAL): frozenset(),  # (`haven sim`'s Nav2 servers, which a trial does not run)
    _t(topics.TRIAL_STATUS): frozenset({SCENARIO}),
    _t(topics.TRIAL_CONTROL): frozenset({WEB}),
    _t(topics.ESTOP): frozenset(),
    _t(topics.AR_MARKERS): frozenset({VIZ}),  # (what the participants' pages show)
    _t(topics.WORLD_MARKERS): frozenset({VIZ}),
    _t(topics.CUE_STATE): frozenset({VIZ}),
    _t(topics.human_cmd_vel("*")): frozenset({SCENARIO, WEB}),
}
ALWAYS_OPEN = (_t(topics.ESTOP), _t(topics.TRIAL_CONTROL))
UNNAMED = nodes.UNNAMED


def writers(topic: str) -> frozenset[str] | None:
    """The suite's publishers of `topic`, or None for a topic the suite and the metrics do not read
    (/scan, /tf: an outsider there changes nothing the trial rests on)."""
    found = WRITERS.get(topic)
    if found is not None:
        return found
    return next((w for pattern, w in WRITERS.items() if "*" in pattern and fnmatch.fnmatchcase(topic, pattern)), None)


def watched(topic: str) -> bool:
    return writers(topic) is not None


def allowable(topic: str) -> str | None:
    """None if a run may open `topic` to outside publishers (`--allow`), else why not: the
    simulator's topics and those the metrics read from the bag would mix another node's messages
    into the trial's own."""
    if not watched(topic):
        return "not a topic the suite or the metrics read"
    if topic.lstrip("/") in METRIC_TOPICS or SIM in (writers(topic) or ()):
        hint = " (your own planner: --without planner)" if topic == _t(topics.PLAN) else ""
        return f"the simulator's and the metrics' topics take no outside publisher{hint}"
    return None


def open_topics(without: Iterable[str] = (), teleop: Iterable[str] = (), allow: Iterable[str] = ()) -> tuple[str, ...]:
    """The topics a run declares open to outside publishers: ALWAYS_OPEN, the outputs of our nodes
    it leaves out (node names), the teleoperated people's velocity, and `allow`."""
    left_out = set(without)
    out = [*ALWAYS_OPEN, *(t for t, w in WRITERS.items() if w & left_out and "*" not in t)]
    out += [_t(topics.human_cmd_vel(h)) for h in teleop]
    out += [_t(t) for t in allow]
    return tuple(dict.fromkeys(out))


@dataclass
class Seen:
    """One publisher (endpoint) of one topic."""

    topic: str
    node: str
    gid: str
    first_s: float
    last_s: float

    def to_dict(self) -> dict[str, object]:
        return {
            "topic": self.topic,
            "node": self.node,
            "gid": self.gid,
            "first_s": round(self.first_s, 3),
            "last_s": round(self.last_s, 3),
        }


@dataclass
class PublisherLog:
    """Every publisher seen per topic, with when (sim time) it was first and last seen."""

    seen: dict[tuple[str, str], Seen] = field(default_factory=dict)  # (topic, gid) -> Seen

    def observe(self, topic: str, publishers: Iterable[tuple[str, str]], now_s: float) -> list[Seen]:
        """The publishers (node name, GID) of `topic` now; returns those seen for the first time with
        their node's name (DDS shows an endpoint before the name of its node: until then UNNAMED)."""
        new = []
        for node, gid in publishers:
            entry = self.seen.get((topic, gid))
            if entry is None:
                entry = self.seen[(topic, gid)] = Seen(topic, node, gid, now_s, now_s)
                if node != UNNAMED:
                    new.append(entry)
            elif entry.node == UNNAMED and node != UNNAMED:
                entry.node = node
                new.append(entry)
            entry.last_s = max(entry.last_s, now_s)
        return new

    def to_json(self) -> str:
        return json.dumps([s.to_dict() for s in self.seen.values()], sort_keys=True)

    @staticmethod
    def from_json(text: str) -> PublisherLog:
        """A log as kept in a bag; anything unreadable in it is left out."""
        log = PublisherLog()
        try:
            rows = json.loads(text)
        except ValueError:
            return log
        for r in rows if isinstance(rows, list) else []:
            try:
                s = Seen(str(r["topic"]), str(r["node"]), str(r["gid"]), float(r["first_s"]), float(r["last_s"]))
            except (KeyError, TypeError, ValueError):
                continue
            log.seen[(s.topic, s.gid)] = s
        return log


@dataclass(frozen=True)
class Declared:
    """What a run says of itself: the nodes it started (their names), the topics it opened, and
    whether it ran on the lockstep clock (which ignores outside messages on the suite's topics)."""

    nodes: frozenset[str]
    open: tuple[str, ...] = ALWAYS_OPEN
    lockstep: bool = False

    def ignores(self, topic: str) -> bool:
        """Whether the suite took no outside message on `topic` (on the lockstep clock, one it writes)."""
        w = writers(topic)
        return self.lockstep and w is not None and bool(w & self.nodes) and topic.lstrip("/") not in METRIC_TOPICS


def outsiders(log: PublisherLog, declared: Declared, with_open: bool = False) -> list[Seen]:
    """The publishers on watched topics that are not the suite's (in the order first seen), but on
    topics the run opened (unless `with_open`); the first publisher under one of our names is ours,
    a later one under the same name another suite's."""
    out = []
    ours_taken: set[tuple[str, str]] = set()
    for s in sorted(log.seen.values(), key=lambda s: (s.first_s, s.topic, s.gid)):
        w = writers(s.topic)
        if w is None or (s.topic in declared.open and not with_open):
            continue
        if s.node in w and s.node in declared.nodes and (s.topic, s.node) not in ours_taken:
            ours_taken.add((s.topic, s.node))
            continue
        out.append(s)
    return out


def describe(s: Seen, declared: Declared) -> str:
    """One line: who published where and when (trial time is up to the caller)."""
    twin = (
        " (a second publisher under one of our node names: another HAVEN suite on this ROS domain?)"
        if s.node in declared.nodes
        else ""
    )
    who = "a node whose name never became known" if s.node in (UNNAMED, "") else s.node
    return f"{s.topic}: published by {who} from outside the suite{twin}"


def before_end(s: Seen, window: tuple[float, float] | None) -> bool:
    """Whether a publisher was there before the trial ended (no trial: whenever it was there): one
    that went before the start can still have moved the robot the trial then starts from."""
    return window is None or s.first_s <= window[1] + 1e-6


def judge(log: PublisherLog, declared: Declared, window: tuple[float, float] | None) -> tuple[list[str], list[str]]:
    """(why the session is not valid; what is only noted): one line per outside publisher seen
    before the trial ended (noted: those the lockstep clock ignored, and those on topics the run opened)."""
    reasons, notes = [], []
    for s in outsiders(log, declared, with_open=True):
        if not before_end(s, window):
            continue
        if s.topic in declared.open:
            notes.append(f"{describe(s, declared)}, on a topic the run opened to it")
        elif declared.ignores(s.topic):
            notes.append(f"{describe(s, declared)}, ignored on the lockstep clock")
        else:
            reasons.append(describe(s, declared))
    return reasons, notes


def declared_of(info: Mapping[str, object]) -> Declared | None:
    """A session's declaration from its session.json (None for sessions from before it was kept)."""
    nodes, allowed = info.get("suite_nodes"), info.get("open_topics")
    if not isinstance(nodes, list) or not isinstance(allowed, list):
        return None
    return Declared(frozenset(str(n) for n in nodes), tuple(str(t) for t in allowed), info.get("clock") == "lockstep")


def suite_nodes(without: Sequence[str], web: bool) -> list[str]:
    """The node names a `haven run` starts (`without`: the names of those left out)."""
    return [*(n.name for n in nodes.TRIAL if n.name not in without), *([WEB] if web else [])]
