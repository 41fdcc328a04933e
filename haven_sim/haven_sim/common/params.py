"""One source of parameters: the core's frozen config dataclasses.

Each node's configuration is a dataclass whose leaf fields are its ROS parameters (name = field name,
default = field default, `doc` in the field metadata); a field holding another config dataclass is
flattened into the same namespace (so shared pieces such as the motion style appear once in each
node that uses them, under the same names). Nodes declare their parameters from these classes,
batch mode builds the same classes from the same parameter file, and the shipped haven.yaml is
generated from them (`render_params_file`), so a default is written in exactly one place.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

import yaml

from haven_sim.common.yaml_file import file_label, read_yaml

T = TypeVar("T")
ParamValue = bool | int | float | str | list[str]
WILDCARD = "/**"  # a ROS parameter-file section that applies to every node


class ParamsError(ValueError):
    """A parameter value or a parameter file is invalid; the message is one line for the user."""


@dataclass(frozen=True)
class Bounds:
    """A number parameter's allowed values, declared with it (`param(..., bounds=...)`): checked when
    a config is made (`check_bounds`) and given to ROS as the parameter's range where both ends
    are set (`ros_range`)."""

    low: float | None = None
    high: float | None = None
    low_open: bool = False  # low itself is not allowed
    high_open: bool = False

    def problem(self, value: float) -> str | None:
        """None if `value` is allowed, else what it must be ("must be positive", "must be within 0..1")."""
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            return "must be a finite number"
        low_ok = self.low is None or (value > self.low if self.low_open else value >= self.low)
        high_ok = self.high is None or (value < self.high if self.high_open else value <= self.high)
        return None if low_ok and high_ok else self.rule()

    def rule(self) -> str:
        """What an allowed value is, in words."""
        if self.high is None and self.low == 0:
            return "must be positive" if self.low_open else "must not be negative"
        if self.high is None:
            return f"must be {'more than' if self.low_open else 'at least'} {self.low:g}"
        if self.low is None:
            return f"must be {'less than' if self.high_open else 'at most'} {self.high:g}"
        if not self.low_open and not self.high_open:
            return f"must be within {self.low:g}..{self.high:g}"
        return (
            f"must be within {'(' if self.low_open else '['}{self.low:g}, {self.high:g}{')' if self.high_open else ']'}"
        )


POSITIVE = Bounds(0.0, low_open=True)
NOT_NEGATIVE = Bounds(0.0)
FRACTION = Bounds(0.0, 1.0)


def param(default: Any, doc: str, bounds: Bounds | None = None) -> Any:
    """A parameter field with its one-line documentation (written into haven.yaml) and, for a
    number, the values it may take."""
    return dataclasses.field(
        default=default, metadata={"doc": doc, **({"bounds": bounds} if bounds is not None else {})}
    )


def check_bounds(config: Any) -> None:
    """ValueError (one line, naming the field) for a field outside its declared bounds: called by
    each config's __post_init__, so a config made in code is checked like one from a parameter file."""
    for f in dataclasses.fields(config):
        bounds = f.metadata.get("bounds")
        if bounds is not None:
            value = getattr(config, f.name)
            problem = bounds.problem(value)
            if problem is not None:
                raise ValueError(f"{f.name} {problem}, got {value!r}")


def ros_range(bounds: Bounds | None) -> tuple[float, float] | None:
    """The (from, to) of the ROS parameter descriptor's range: only where both ends are declared
    (ROS ranges are closed; an open end is checked by `Bounds.problem`, the range only shows it)."""
    if bounds is None or bounds.low is None or bounds.high is None:
        return None
    return bounds.low, bounds.high


def bounds_of(cls: type[Any]) -> dict[str, Bounds]:
    """Parameter name -> its declared bounds, for the parameters that have some."""
    return {name: f.metadata["bounds"] for name, f in _leaves(cls) if "bounds" in f.metadata}


def group(cls: type[T], prefix: str = "") -> Any:
    """A field holding a nested config dataclass: its fields join the node's parameters, their
    names prefixed with `prefix` (e.g. the battery's `capacity_m` is the sim's `battery_capacity_m`)."""
    return dataclasses.field(default_factory=cls, metadata={"prefix": prefix})


def _is_group(f: dataclasses.Field[Any]) -> bool:
    return f.default_factory is not dataclasses.MISSING and dataclasses.is_dataclass(f.default_factory)


def _is_param(f: dataclasses.Field[Any]) -> bool:
    """Fields marked `internal` are set by code, not by a parameter."""
    return not f.metadata.get("internal", False)


def _leaves(cls: type[Any], prefix: str = "") -> list[tuple[str, dataclasses.Field[Any]]]:
    """(parameter name, field) of every leaf; names must be unique within a node."""
    out: list[tuple[str, dataclasses.Field[Any]]] = []
    for f in dataclasses.fields(cls):
        if _is_group(f):
            out += _leaves(f.default_factory, prefix + f.metadata.get("prefix", ""))  # type: ignore[arg-type]
        elif _is_param(f):
            out.append((prefix + f.name, f))
    names = [n for n, _ in out]
    if len(set(names)) != len(names):
        raise ParamsError(f"{cls.__name__}: parameter names repeat: {sorted({n for n in names if names.count(n) > 1})}")
    return out


def flatten(config: Any, prefix: str = "") -> dict[str, ParamValue]:
    """Parameter name -> value of a config instance (nested groups flattened)."""
    out: dict[str, ParamValue] = {}
    for f in dataclasses.fields(config):
        value = getattr(config, f.name)
        if _is_group(f):
            out.update(flatten(value, prefix + f.metadata.get("prefix", "")))
        elif _is_param(f):
            out[prefix + f.name] = list(value) if isinstance(value, tuple) else value
    return out


def docs(cls: type[Any]) -> dict[str, str]:
    return {name: str(f.metadata.get("doc", "")) for name, f in _leaves(cls)}


def defaults(cls: type[Any]) -> dict[str, ParamValue]:
    return flatten(cls())


def _coerce(name: str, value: Any, default: Any, where: str) -> Any:
    def fail(expected: str) -> ParamsError:
        shown = repr(value) if len(repr(value)) < 60 else repr(value)[:57] + "..."
        return ParamsError(f"{where}{name}: must be {expected}, got {shown}")

    if isinstance(default, bool):
        if not isinstance(value, bool):
            raise fail("true or false")
        return value
    if isinstance(default, int):
        if isinstance(value, bool) or not isinstance(value, int):
            raise fail("an integer")
        return value
    if isinstance(default, float):
        if isinstance(value, str):  # ROS reads `1e-3` (YAML 1.1 has no such float) as a double: so does this
            value = _ros_double(value)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise fail("a finite number")
        return float(value)
    if isinstance(default, str):
        if not isinstance(value, str):
            raise fail("a string")
        return value
    if isinstance(default, (tuple, list)):
        if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
            raise fail("a list of strings")
        return tuple(v for v in value if v)
    raise fail(type(default).__name__)  # pragma: no cover - configs use the types above


def _ros_double(text: str) -> float | str:
    """A string as rcl's parameter-file parser reads an unquoted scalar it could not type otherwise:
    a double when the whole of it is one (`1e-3`, `1E9`), else the string."""
    try:
        return float(text) if text.strip() == text and text else text
    except ValueError:
        return text


def build(cls: type[T], values: Mapping[str, Any], where: str = "", prefix: str = "") -> T:
    """An instance of `cls` with `values` (parameter name -> value) replacing defaults; unknown
    names are ignored (a parameter file serves several nodes), wrong types refused in one line."""
    kwargs: dict[str, Any] = {}
    for f in dataclasses.fields(cls):  # type: ignore[arg-type]
        name = prefix + f.name
        if _is_group(f):
            kwargs[f.name] = build(f.default_factory, values, where, prefix + f.metadata.get("prefix", ""))  # type: ignore[arg-type]
        elif name in values and _is_param(f):
            kwargs[f.name] = _coerce(name, values[name], f.default, where)
            bounds = f.metadata.get("bounds")
            problem = bounds.problem(kwargs[f.name]) if bounds is not None else None
            if problem is not None:
                raise ParamsError(f"{where}{name} {problem}, got {kwargs[f.name]!r}")
    try:
        return cls(**kwargs)
    except ParamsError:
        raise
    except ValueError as e:
        raise ParamsError(f"{where}{e}") from None


def load_params_file(path: str | Path) -> dict[str, dict[str, Any]]:
    """A ROS 2 parameter file as {node name: {parameter: value}} (without the ros__parameters level),
    read as any file a user hands us (`read_yaml`: a regular file of at most 1 MiB of UTF-8,
    bounded nesting and aliases, no key given twice), so a hostile one is refused in one line."""
    return params_of(read_yaml(path, "parameter file", ParamsError), file_label(path))


def node_key(key: Any) -> str:
    """A parameter file's node key as the node's name: "/sim_node", "/**/sim_node" and a namespaced
    "/robot1/sim_node" all name sim_node; "/**" (or "**") is the section for every node."""
    text = str(key)
    if text.strip("/") == "**":
        return WILDCARD
    return text.rstrip("/").rsplit("/", 1)[-1]


def params_of(data: Any, label: str) -> dict[str, dict[str, Any]]:
    """A parameter file's document as {node name: {parameter: value}}; ParamsError (naming the
    file, `label`) where it is not shaped like one."""
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise ParamsError(f"{label}: a parameter file maps node names to 'ros__parameters'")
    out: dict[str, dict[str, Any]] = {}
    for node, section in data.items():
        params = section.get("ros__parameters") if isinstance(section, dict) else None
        if not isinstance(params, dict):
            raise ParamsError(f"{label}: {node}: needs a 'ros__parameters' mapping")
        out.setdefault(node_key(node), {}).update(params)
    return out


def check_names(params: Mapping[str, Mapping[str, Any]], known: Mapping[str, Mapping[str, Any]], label: str) -> None:
    """Refuse what no node would read: a node section of no known node, a parameter a node does not
    have (both with the nearest known name), and any number that is not finite (NaN, inf, or an
    integer beyond a float's range), each in one line naming file, node and key. `known` maps each
    node name to its parameters' defaults (the wildcard section may hold any node's parameter);
    a value of the wrong type is left to `build`, which names the node and key."""
    every = {name: default for names in known.values() for name, default in names.items()}
    for node, values in params.items():
        if node != WILDCARD and node not in known:
            raise ParamsError(
                f"{label}: {shown(node)}: no such node{_nearest(node, known)} (nodes: {', '.join(known)})"
            )
        names = every if node == WILDCARD else known[node]
        for name, value in values.items():
            if not isinstance(name, str) or name not in names:
                raise ParamsError(f"{label}: {shown(node)}: {shown(name)}: no such parameter{_nearest(name, names)}")
            # (a boolean: build says "true or false")
            bad = None if isinstance(names[name], bool) else _not_finite(value)
            if bad is not None:
                raise ParamsError(f"{label}: {shown(node)}: {name}: must be a finite number, got {bad}")


def shown(key: Any) -> str:
    text = str(key)
    return text if text.isprintable() and 0 < len(text) <= 40 else repr(text)[:40]


def _nearest(name: Any, names: Iterable[str]) -> str:
    close = difflib.get_close_matches(str(name), list(names), n=1, cutoff=0.6)
    return f" (did you mean {close[0]}?)" if close else ""


def _not_finite(value: Any) -> str | None:
    """How a value shows that is a number but not a finite one (in a list, too), else None."""
    for v in value if isinstance(value, list) else [value]:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            continue
        try:
            finite = math.isfinite(float(v))
        except OverflowError:
            finite = False
        if not finite:
            return str(v) if isinstance(v, float) else "an integer beyond a float's range"
    return None


def node_values(params_file: Mapping[str, Mapping[str, Any]], node: str) -> dict[str, Any]:
    """The values a node gets from a loaded parameter file: the wildcard section, then its own."""
    return {**params_file.get(WILDCARD, {}), **params_file.get(node, {})}


def _yaml_value(value: Any) -> str:
    if isinstance(value, float) and value == math.pi:
        return "3.141592653589793"
    return yaml.safe_dump(value, default_flow_style=True).strip().removesuffix("\n...").strip()


def render_params_file(
    nodes: Sequence[tuple[str, type[Any]]],
    shared: Sequence[type[Any]] = (),
    header: str = "",
    values: Mapping[str, Mapping[str, Any]] | None = None,
) -> str:
    """A ROS 2 parameter file with every node's parameters, their docs, and their defaults (or the
    `values` given per node name, the shared ones under WILDCARD). Groups in `shared` go once under
    the wildcard section; a node whose shared value differs repeats it in its own section."""
    shared_names = {n for cls in shared for n, _ in _leaves(cls)}
    given = values or {}
    common = {k: v for cls in shared for k, v in defaults(cls).items()} | dict(given.get(WILDCARD, {}))
    lines = [f"# {h}".rstrip() for h in header.splitlines()] if header else []

    def section(node: str, leaves: list[tuple[str, dataclasses.Field[Any]]], values: Mapping[str, Any]) -> None:
        lines.append(f"{node}:" if node != WILDCARD else f'"{WILDCARD}":')
        lines.append("  ros__parameters:")
        for name, f in leaves:
            doc = f.metadata.get("doc", "")
            entry = f"    {name}: {_yaml_value(values[name])}"
            lines.append(f"{entry:<44} # {doc}" if doc else entry)
        lines.append("")

    if shared:
        section(WILDCARD, [leaf for cls in shared for leaf in _leaves(cls)], common)
    for node, cls in nodes:
        own = defaults(cls) | dict(given.get(node, {}))
        section(node, [(n, f) for n, f in _leaves(cls) if n not in shared_names or own[n] != common[n]], own)
    return "\n".join(lines).rstrip() + "\n"
