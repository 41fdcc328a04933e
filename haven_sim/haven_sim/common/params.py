"""One source of parameters: the core's frozen configs, declared as pydantic dataclasses.

Each node's configuration is a `config` class whose leaf fields are its ROS parameters: name =
field name; default, description and bounds in the field's pydantic `Field` (`param`); read-only
unless declared `runtime`. A field holding another config is flattened into the same namespace
(`group`), so shared pieces such as the motion style appear once in each node that uses them,
under the same names. pydantic checks every value (type, bounds, finiteness) whether the config
is made in code, from a parameter file or from a node's declared parameters; nodes declare their
parameters and descriptors from the same fields (nodes/component_node.declare_config), and the
shipped haven.yaml is generated from them (`render_params_file`), so a default is written once.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NamedTuple, TypeVar, dataclass_transform

import pydantic
import pydantic.dataclasses
import yaml
from pydantic.fields import FieldInfo

from haven_sim.common.yaml_file import file_label, read_yaml

T = TypeVar("T")
ParamValue = bool | int | float | str | list[str]
WILDCARD = "/**"  # a ROS parameter-file section that applies to every node

# Strict: a parameter's type is its declared one (an integer is no boolean, a string no number;
# an integer is a float, as in ROS). Values that are not configs (a robot description) are taken as given.
CONFIG = pydantic.ConfigDict(strict=True, allow_inf_nan=False, arbitrary_types_allowed=True)


class ParamsError(ValueError):
    """A parameter value or a parameter file is invalid; the message is one line for the user."""


class FieldError(ParamsError):
    """A config field's value was refused: `field` (the field's name), `rule` (what it must be),
    `value`; said "name: rule, got value" (as the files' schema says it), with the parameter's name
    when a node's config is built."""

    def __init__(self, field: str, rule: str, value: Any) -> None:
        self.field, self.rule, self.value = field, rule, value
        super().__init__(self.said(field))

    def said(self, name: str) -> str:
        return f"{name}: {self.rule}, got {_short(self.value)}"


@dataclass(frozen=True)
class Bounds:
    """A number parameter's allowed values, declared with it (`param(..., bounds=...)`): pydantic
    checks them (`constraints`), and ROS is given them as the parameter's range where both ends
    are set (`ros_range`)."""

    low: float | None = None
    high: float | None = None
    low_open: bool = False  # low itself is not allowed
    high_open: bool = False

    def constraints(self) -> dict[str, Any]:
        """The bounds as pydantic `Field` constraints (gt/ge/lt/le)."""
        out: dict[str, Any] = {}
        if self.low is not None:
            out["gt" if self.low_open else "ge"] = self.low
        if self.high is not None:
            out["lt" if self.high_open else "le"] = self.high
        return out

    @classmethod
    def of(cls, info: FieldInfo) -> Bounds | None:
        """The bounds a field was declared with (None: none)."""
        ends: dict[str, Any] = {}
        for m in info.metadata:  # (annotated_types' Gt, Ge, Lt, Le: one constraint each)
            for key, end, is_open in (
                ("gt", "low", True),
                ("ge", "low", False),
                ("lt", "high", True),
                ("le", "high", False),
            ):
                if getattr(m, key, None) is not None:
                    ends.update({end: float(getattr(m, key)), f"{end}_open": is_open})
        return cls(**ends) if ends else None

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

RUNTIME = "runtime"  # field metadata: the parameter may change while the node runs (else read-only)
INTERNAL = "internal"  # field metadata: set by code, not a parameter
PREFIX = "prefix"  # field metadata of a group: the prefix of its parameters' names


def param(default: Any, doc: str, bounds: Bounds | None = None, runtime: bool = False) -> Any:
    """A parameter field: its default, its one-line documentation (the ROS descriptor's and
    haven.yaml's), for a number the values it may take, and whether it may change while the node
    runs (`runtime`; the rest are read at start-up only, read-only in ROS)."""
    field = pydantic.Field(default, description=doc, **(bounds.constraints() if bounds else {}))
    return dataclasses.field(default=field, metadata={RUNTIME: runtime})


def internal(default: Any, bounds: Bounds | None = None, **metadata: Any) -> Any:
    """A config field set by code, not a parameter (still checked against `bounds`). Its default is
    handed out as it is (pydantic would deep-copy a default it does not know to be immutable)."""
    field = pydantic.Field(default_factory=lambda: default, **(bounds.constraints() if bounds else {}))
    return dataclasses.field(default=field, metadata={INTERNAL: True, **metadata})


def group(cls: type[T], prefix: str = "") -> Any:
    """A field holding a nested config: its fields join the node's parameters, their names
    prefixed with `prefix` (e.g. the battery's `capacity_m` is the sim's `battery_capacity_m`)."""
    return dataclasses.field(default_factory=cls, metadata={PREFIX: prefix})


_TYPE_RULES = {
    "bool_type": "must be true or false",
    "int_type": "must be an integer",
    "float_type": "must be a finite number",
    "finite_number": "must be a finite number",
    "string_type": "must be a string",
}


@dataclass_transform(frozen_default=True, field_specifiers=(dataclasses.field, pydantic.Field))
def config(cls: type[T]) -> type[T]:
    """A config class: a frozen pydantic dataclass (`CONFIG`) whose refusals are one line
    (`FieldError` naming the field; a `__post_init__`'s own ValueError as it said it)."""
    made = pydantic.dataclasses.dataclass(frozen=True, config=CONFIG)(cls)
    validated: Callable[..., None] = made.__init__

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        try:
            validated(self, *args, **kwargs)
        except pydantic.ValidationError as e:
            raise _one_line(made, e) from None

    __init__.__doc__ = validated.__doc__
    made.__init__ = __init__  # type: ignore[method-assign]
    return made  # type: ignore[return-value]


def _one_line(cls: type[Any], error: pydantic.ValidationError) -> ParamsError:
    first = error.errors(include_url=False)[0]
    if first["type"] == "value_error" and first.get("ctx", {}).get("error") is not None:  # (a __post_init__ said it)
        cause = first["ctx"]["error"]
        return cause if isinstance(cause, ParamsError) else ParamsError(str(cause))
    name = str(first["loc"][0]) if first["loc"] else cls.__name__
    info = fields_info(cls).get(name)
    value = first["input"]
    if info is not None and isinstance(info.default, tuple):
        return FieldError(name, "must be a list of strings", value)
    bounds = Bounds.of(info) if info is not None else None
    rule = _TYPE_RULES.get(first["type"]) or (bounds.rule() if bounds is not None else first["msg"].lower())
    return FieldError(name, rule, value)


def _short(value: Any) -> str:
    shown = repr(value)
    return shown if len(shown) < 60 else shown[:57] + "..."


def fields_info(cls: type[Any]) -> dict[str, FieldInfo]:
    """A config class's fields as pydantic sees them (default, description, constraints)."""
    return dict(getattr(cls, "__pydantic_fields__", {}))


def is_config(cls: Any) -> bool:
    return isinstance(cls, type) and pydantic.dataclasses.is_pydantic_dataclass(cls)


class Leaf(NamedTuple):
    """One parameter of a config class: its name in the node's namespace and its declaration."""

    name: str
    info: FieldInfo
    runtime: bool

    @property
    def doc(self) -> str:
        return self.info.description or ""

    @property
    def bounds(self) -> Bounds | None:
        return Bounds.of(self.info)


def _group_of(f: dataclasses.Field[Any]) -> type[Any] | None:
    factory = f.default_factory
    return factory if factory is not dataclasses.MISSING and is_config(factory) else None  # type: ignore[return-value]


def leaves(cls: type[Any], prefix: str = "") -> list[Leaf]:
    """Every parameter of a config class (groups flattened); names must be unique within a node."""
    out: list[Leaf] = []
    infos = fields_info(cls)
    for f in dataclasses.fields(cls):
        inner = _group_of(f)
        if inner is not None:
            out += leaves(inner, prefix + f.metadata.get(PREFIX, ""))
        elif not f.metadata.get(INTERNAL, False):
            out.append(Leaf(prefix + f.name, infos[f.name], bool(f.metadata.get(RUNTIME, False))))
    names = [leaf.name for leaf in out]
    if len(set(names)) != len(names):
        raise ParamsError(f"{cls.__name__}: parameter names repeat: {sorted({n for n in names if names.count(n) > 1})}")
    return out


def flatten(config: Any, prefix: str = "") -> dict[str, ParamValue]:
    """Parameter name -> value of a config instance (nested groups flattened)."""
    out: dict[str, ParamValue] = {}
    for f in dataclasses.fields(config):
        value = getattr(config, f.name)
        if _group_of(f) is not None:
            out.update(flatten(value, prefix + f.metadata.get(PREFIX, "")))
        elif not f.metadata.get(INTERNAL, False):
            out[prefix + f.name] = list(value) if isinstance(value, tuple) else value
    return out


def docs(cls: type[Any]) -> dict[str, str]:
    return {leaf.name: leaf.doc for leaf in leaves(cls)}


def ros_range(bounds: Bounds | None) -> tuple[float, float] | None:
    """The (from, to) of the ROS parameter descriptor's range: only where both ends are declared
    (ROS ranges are closed; an open end is checked by pydantic, the range only shows it)."""
    if bounds is None or bounds.low is None or bounds.high is None:
        return None
    return bounds.low, bounds.high


def defaults(cls: type[Any]) -> dict[str, ParamValue]:
    return flatten(cls())


def _as_declared(value: Any, default: Any) -> Any:
    """A parameter value as ROS hands it to a field of `default`'s type: a list (a string array) as
    the field's tuple, without the empty strings ROS needs for an empty array; a string that is
    wholly a number, for a float, as rcl's parameter-file parser reads an unquoted `1e-3` (YAML 1.1
    has no such float): a double."""
    if isinstance(default, tuple) and isinstance(value, list) and all(isinstance(v, str) for v in value):
        return tuple(v for v in value if v)
    if isinstance(default, float) and isinstance(value, str) and value.strip() == value and value:
        try:
            return float(value)
        except ValueError:
            return value
    return value


def build(cls: type[T], values: Mapping[str, Any], where: str = "", prefix: str = "") -> T:
    """An instance of `cls` with `values` (parameter name -> value) replacing defaults; unknown
    names are ignored (a parameter file serves several nodes), wrong values refused in one line
    naming the parameter (`where` before it)."""
    kwargs: dict[str, Any] = {}
    infos = fields_info(cls)
    for f in dataclasses.fields(cls):  # type: ignore[arg-type]
        name = prefix + f.name
        inner = _group_of(f)
        if inner is not None:
            kwargs[f.name] = build(inner, values, where, prefix + f.metadata.get(PREFIX, ""))
        elif name in values and not f.metadata.get(INTERNAL, False):
            kwargs[f.name] = _as_declared(values[name], infos[f.name].default)
    try:
        return cls(**kwargs)
    except FieldError as e:
        raise ParamsError(where + e.said(prefix + e.field)) from None
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


def check_names(
    params: Mapping[str, Mapping[str, Any]],
    known: Mapping[str, Mapping[str, Any]],
    label: str,
    elsewhere: Mapping[str, str] | None = None,
) -> None:
    """Refuse what no node would read: a node section of no known node, a parameter a node does not
    have (both with the nearest known name), and any number that is not finite (NaN, inf, or an
    integer beyond a float's range), each in one line naming file, node and key. `known` maps each
    node name to its parameters' defaults (the wildcard section may hold any node's parameter);
    a value of the wrong type is left to `build`, which names the node and key. `elsewhere`: names
    that are no parameter but are set in another file (name -> where), said instead of a near name."""
    every = {name: default for names in known.values() for name, default in names.items()}
    for node, values in params.items():
        if node != WILDCARD and node not in known:
            raise ParamsError(
                f"{label}: {shown(node)}: no such node{_nearest(node, known)} (nodes: {', '.join(known)})"
            )
        names = every if node == WILDCARD else known[node]
        for name, value in values.items():
            if isinstance(name, str) and name not in names and name in (elsewhere or {}):
                raise ParamsError(f"{label}: {shown(node)}: {name}: no such parameter: {elsewhere[name]}")  # type: ignore[index]
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
    shared_names = {leaf.name for cls in shared for leaf in leaves(cls)}
    given = values or {}
    common = {k: v for cls in shared for k, v in defaults(cls).items()} | dict(given.get(WILDCARD, {}))
    lines = [f"# {h}".rstrip() for h in header.splitlines()] if header else []

    def section(node: str, params: list[Leaf], values: Mapping[str, Any]) -> None:
        lines.append(f"{node}:" if node != WILDCARD else f'"{WILDCARD}":')
        lines.append("  ros__parameters:")
        for leaf in params:
            entry = f"    {leaf.name}: {_yaml_value(values[leaf.name])}"
            doc = f"{leaf.doc}, settable at run time" if leaf.runtime else leaf.doc
            lines.append(f"{entry:<44} # {doc}" if doc else entry)
        lines.append("")

    if shared:
        section(WILDCARD, [leaf for cls in shared for leaf in leaves(cls)], common)
    for node, cls in nodes:
        own = defaults(cls) | dict(given.get(node, {}))
        section(node, [p for p in leaves(cls) if p.name not in shared_names or own[p.name] != common[p.name]], own)
    return "\n".join(lines).rstrip() + "\n"
