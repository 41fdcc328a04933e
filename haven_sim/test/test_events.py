"""Typed events: every kind round-trips, anything malformed is refused in one line, and no event
kind is spelt as a string outside haven_sim/common/events.py."""

import json
import re
from pathlib import Path

import pytest

from haven_sim.common.events import Event, EventError, EventKind, Source, event


def test_round_trip_through_json():
    e = event(EventKind.REPLANNED, 12.34567, Source.PLANNER, side="left", human=[1.0, 2.0])
    back = Event.from_json(e.to_json())
    assert back == Event(EventKind.REPLANNED, 12.3457, "planner", {"side": "left", "human": [1.0, 2.0]})
    assert json.loads(e.to_json())["type"] == "replanned" and back["side"] == "left"


@pytest.mark.parametrize(
    "text,why",
    [
        ("not json", "not JSON"),
        ("[1, 2]", "must be a JSON object"),
        ('{"type": "replanned"}', "stamp must be a finite number"),
        ('{"type": "teleported", "stamp": 1}', "unknown event type 'teleported'"),
        ('{"type": ["x"], "stamp": 1}', "unknown event type"),
        ('{"type": "gem_collected", "stamp": 1, "gem": "g"}', "missing by"),
        ('{"type": "gem_collected", "stamp": 1, "gem": {"a": 1}, "by": "h1"}', "gem must be a string"),
        ('{"type": "trial_end", "stamp": NaN, "reason": "x"}', "stamp must be a finite number"),
        ("[" * 60000, "not JSON"),
        ('{"type": "reset", "stamp": 1, "pad": "' + "x" * 70000 + '"}', "larger than"),
    ],
)
def test_malformed_events_are_refused_in_one_line(text, why):
    with pytest.raises(EventError, match=re.escape(why)) as info:
        Event.from_json(text)
    assert "\n" not in str(info.value) and len(str(info.value)) < 200


ENUM_MEMBER = re.compile(r"^\s+[A-Z_]+ = ")  # another enum's member that shares a word ("waiting" state)


def test_no_event_kind_is_spelt_as_a_string_outside_the_events_module():
    root = Path(__file__).resolve().parents[2]
    kinds = {k.value for k in EventKind}
    pattern = re.compile(r"""["']([a-z_]+)["']""")
    offenders = [
        f"{path.relative_to(root)}:{n}: {word}"
        for path in root.glob("haven_*/haven_*/**/*.py")
        if path.name != "events.py"
        for n, line in enumerate(path.read_text().splitlines(), 1)
        for word in pattern.findall(line)
        if word in kinds and not line.lstrip().startswith("#") and not ENUM_MEMBER.match(line)
    ]
    assert offenders == []
