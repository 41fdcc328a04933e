"""Hostile messages for any ROS message type, and a publisher that sends them on every topic a
running suite reads.

The messages are built by introspection of the message class, so every field of every type our
nodes subscribe to is covered without a list to keep up to date: each float field NaN, ±inf and
±1e308 on its own and all at once, each string field a set of hostile strings (not JSON, JSON of
the wrong shape, unhashable ids, 100k-deep nesting, a megabyte), each sequence empty and long,
each integer at its type's extremes, and an all-defaults message (zero quaternions, a 0 x 0 map
of resolution 0). An OccupancyGrid also gets a size that disagrees with its data.
"""

from __future__ import annotations

import array
import copy
import importlib
from collections.abc import Iterator
from typing import Any

FLOATS = (float("nan"), float("inf"), float("-inf"), 1e308, -1e308)
STRINGS = (
    "",
    "{",
    "not json",
    "[1, 2]",
    "null",
    '{"type": "trial_start"}',
    '{"type": "trial_start", "stamp": 1e999, "source": "x"}',
    '{"type": "gem_collected", "stamp": 1.0, "source": "x", "gem": ["g"], "by": {"a": 1}}',
    '{"type": "cue_toggled", "stamp": 1.0, "source": "x", "cue": "nope", "shown": "yes"}',
    '{"node": ["unhashable"], "ready": true, "period_ns": "x", "inputs": 5, "outputs": null}',
    '{"node": "controller", "step": [1], "sent": {"/cmd_vel_nav": "many"}}',
    '{"step": 1e308, "t_ns": "now", "step_ns": 0, "counts": [1]}',
    '{"toggles": [], "battery_level": "full", "path_markers": null, "turn_signal": {}, "thought": 1, "stamp": "x"}',
    "[" * 100_000,
    '{"a":' * 50_000 + "1" + "}" * 50_000,
    "x" * 1_000_000,
    "\x00\x01\x02 \u202e \ud7ff",
)
INT_RANGES = {
    "int8": (-128, 127),
    "uint8": (0, 255),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
LONG = 10_000  # elements in a "long" sequence
# A YAML alias bomb ("billion laughs"): 9^9 values in about 450 bytes.
BOMB = "l0: &l0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"l{i}: &l{i} [{', '.join([f'*l{i - 1}'] * 9)}]\n" for i in range(1, 9)
)


def refused(error: type[Exception], path: Any, load: Any, *needles: str) -> str:
    """The error `load(path)` raises for a hostile file: one short line naming the file, and each needle."""
    import pytest

    with pytest.raises(error) as e:
        load(path)
    msg = str(e.value)
    assert "\n" not in msg and len(msg) < 300 and msg.startswith(f"{path}: "), msg
    for needle in needles:
        assert needle in msg, msg
    return msg


def message_class(type_name: str) -> Any:
    """The rclpy class for 'nav_msgs/msg/Odometry'."""
    package, kind, name = type_name.split("/")
    return getattr(importlib.import_module(f"{package}.{kind}"), name)


def _leaves(msg: Any, prefix: str = "") -> Iterator[tuple[str, Any, str]]:
    """(dotted path, owning message, field type) of every field, nested messages opened."""
    for name, ftype in msg.get_fields_and_field_types().items():
        value = getattr(msg, name)
        if hasattr(value, "get_fields_and_field_types"):
            yield from _leaves(value, f"{prefix}{name}.")
        else:
            yield f"{prefix}{name}", msg, ftype


def _set(msg: Any, path: str, value: Any) -> Any:
    out = copy.deepcopy(msg)
    *parents, last = path.split(".")
    target = out
    for p in parents:
        target = getattr(target, p)
    setattr(target, last, value)
    return out


def _element(ftype: str) -> str:
    """'float64' for 'sequence<float64>', 'double[36]' -> 'double'."""
    if ftype.startswith("sequence<"):
        return ftype[len("sequence<") : -1].split(",")[0]
    return ftype.split("[")[0]


def _is_float(t: str) -> bool:
    return t in ("float", "double", "float32", "float64")


def _variants(base: Any, path: str, ftype: str) -> Iterator[tuple[str, Any]]:
    elem = _element(ftype)
    fixed = "[" in ftype and not ftype.startswith("sequence")
    if ftype.startswith("sequence<") and "/" not in elem:
        yield f"{path}=[]", _set(base, path, [])
        if _is_float(elem):
            yield f"{path}=[nan]*{LONG}", _set(base, path, [float("nan")] * LONG)
        elif elem in INT_RANGES:
            yield f"{path}=[max]*{LONG}", _set(base, path, [INT_RANGES[elem][1]] * LONG)
        return
    if ftype.startswith("sequence<"):  # of messages: none, and many default ones
        yield f"{path}=[]", _set(base, path, [])
        yield (
            f"{path}=[default]*{LONG}",
            _set(base, path, [message_class(elem.replace("/", "/msg/", 1))() for _ in range(LONG)]),
        )
        return
    if fixed and _is_float(elem):
        n = len(getattr(_resolve(base, path), path.split(".")[-1]))
        for v in FLOATS[:2]:
            yield (
                f"{path}=[{v}]*{n}",
                _set(base, path, array.array("d", [v] * n) if elem in ("double", "float64") else [v] * n),
            )
        return
    if _is_float(elem):
        for v in FLOATS:
            yield f"{path}={v}", _set(base, path, v)
    elif elem in INT_RANGES:
        for v in INT_RANGES[elem]:
            yield f"{path}={v}", _set(base, path, v)
    elif elem == "string":
        for s in STRINGS:
            yield f"{path}={s[:30]!r}", _set(base, path, s)


def _resolve(msg: Any, path: str) -> Any:
    for p in path.split(".")[:-1]:
        msg = getattr(msg, p)
    return msg


def _all_floats(msg: Any, value: float) -> Any:
    out = copy.deepcopy(msg)
    for path, _, ftype in list(_leaves(out)):
        if _is_float(ftype):
            _set_in_place(out, path, value)
    return out


def _set_in_place(msg: Any, path: str, value: Any) -> None:
    *parents, last = path.split(".")
    for p in parents:
        msg = getattr(msg, p)
    setattr(msg, last, value)


def hostile_messages(type_name: str) -> Iterator[tuple[str, Any]]:
    """(description, message) pairs: every hostile variant of one message type."""
    cls = message_class(type_name)
    base = cls()
    yield "defaults", base
    for v in FLOATS:
        yield f"every float={v}", _all_floats(base, v)
    for path, _, ftype in list(_leaves(base)):
        yield from _variants(base, path, ftype)
    if type_name == "nav_msgs/msg/OccupancyGrid":
        for w, h, n in ((10, 10, 5), (2**31, 2**31, 4), (0, 0, 0), (3, 3, 9)):
            msg = cls()
            msg.info.width, msg.info.height, msg.info.resolution = w, h, 0.05 if n != 9 else float("nan")
            msg.data = [0] * n
            yield f"map {w}x{h} with {n} cells", msg


def subscribed_topics(node: Any, of_nodes: set[str]) -> dict[str, str]:
    """{topic: type} of every topic one of `of_nodes` (node names) subscribes to, from the graph."""
    found: dict[str, str] = {}
    for name, namespace in node.get_node_names_and_namespaces():
        if name in of_nodes:
            for topic, types in node.get_subscriber_names_and_types_by_node(name, namespace):
                found.setdefault(topic, types[0])
    return found


def publish_hostile(ros: Any, wanted: dict[str, str], spin_s: float = 0.002, keep: Any = None) -> int:
    """Publish every hostile variant (those `keep(topic, message)` keeps, if given) on every topic
    of `wanted` from the harness's node, with a QoS every reader matches (reliable, transient
    local); returns the number of messages sent."""
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    pubs = {t: ros.node.create_publisher(message_class(ty), t, qos) for t, ty in wanted.items()}
    for pub in pubs.values():
        ros.spin_until(lambda pub=pub: pub.get_subscription_count() > 0, 10.0)
    sent = 0
    for topic, type_name in sorted(wanted.items()):
        for _, msg in hostile_messages(type_name):
            if keep is not None and not keep(topic, msg):
                continue
            pubs[topic].publish(msg)
            sent += 1
            ros.spin_for(spin_s)
    for pub in pubs.values():
        ros.node.destroy_publisher(pub)
    return sent


HOSTILE_VALUES = (float("nan"), float("inf"), -1e308, "x" * 10_000, [1.0, float("nan")], True, -(2**63))


def set_hostile_parameters(ros: Any, node_name: str) -> tuple[int, list[str]]:
    """Try every hostile value on every parameter of a node (through its parameter services);
    returns (how many were tried, the names whose hostile value was accepted)."""
    from rclpy.parameter import Parameter
    from rclpy.parameter_client import AsyncParameterClient

    client = AsyncParameterClient(ros.node, node_name)
    assert client.wait_for_services(timeout_sec=30.0), f"{node_name} offers no parameter services"
    listed = client.list_parameters()
    ros.spin_until(listed.done, 30.0)
    names = [n for n in listed.result().result.names if n not in ("use_sim_time", "qos_overrides")]
    tried, accepted = 0, []
    for name in names:
        for value in HOSTILE_VALUES:
            future = client.set_parameters([Parameter(name, value=value)])
            assert ros.spin_until(future.done, 30.0), f"{node_name} did not answer a parameter request"
            tried += 1
            if future.result().results[0].successful:
                accepted.append(f"{name}={str(value)[:20]}")
    return tried, accepted
