"""Plugins by name: registries of the things a lab adds (participant models, questionnaires,
metrics, cues, path planners, mission behaviours and robots), filled from Python entry
points (groups `haven.<kind>`).

HAVEN's own items register exactly as a lab's package does, in its pyproject.toml::

    [project.entry-points."haven.participants"]
    hesitant = "my_lab.people:Hesitant"

A scenario file, a study file, a `--grid` axis or a command-line option names an item; batch mode
and every node look it up here, so both run the same code. A broken plugin (it does not import, it
is not what its kind needs, its name is taken, its import outlasts `plugin_deadline_load_s`) is left
out with one line naming it (`Registry.problems`, shown by `haven plugins`); it never breaks the
others. Every call into a plugin's code during a trial is contained the same way (common/contain.py).

Each kind's `accept_plugin` returns a typed item (a Protocol or a spec dataclass read from the
plugin), never changing the plugin itself. A plugin may say which version of this API it was written
for (`haven_plugin_api = 1`, an attribute of what its entry point names); one written for a newer
version than this HAVEN's (`PLUGIN_API`) is left out, saying so. CONTRIBUTING.md says when the
version changes and how long an old form keeps working.
"""

from __future__ import annotations

import importlib.metadata
import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from haven_sim.common import contain
from haven_sim.common.contain import first_line, singular

PLUGIN_API = 1  # the plugin API's version: a change that breaks a plugin written for it makes it 2
API_ATTRIBUTE = "haven_plugin_api"  # where a plugin says the version it was written for (default: this one)
GROUP_PREFIX = "haven."
NAME = re.compile(r"^[a-z][a-z0-9_]{0,39}$")  # what a scenario or study file can write unquoted


class PluginError(ValueError):
    """An unknown name (one line, with the known ones)."""


@dataclass(frozen=True)
class Plugin:
    kind: str
    name: str
    package: str  # the distribution that registered it
    target: str  # "module:attribute", as its entry point says
    value: Any


KINDS_GROUP = "haven.kinds"  # each HAVEN package registers the kinds it owns here: kind = module:accept_plugin


@cache
def kinds() -> dict[str, importlib.metadata.EntryPoint]:
    """Each plugin kind and where its `accept_plugin(name, value)` is (it returns the item to use,
    or raises ValueError saying in one line why it cannot be one; loaded when the kind's registry
    is). Each of HAVEN's packages registers the kinds it owns (entry point group `haven.kinds`), so
    this, the lowest package, names none of the packages above it; in package order (sim, viz,
    scenarios)."""
    rank = {name: i for i, name in enumerate(("haven-sim", "haven-viz", "haven-scenarios"))}
    entries = [e for e in importlib.metadata.entry_points(group=KINDS_GROUP) if _normal(_package(e)) in rank]
    return {e.name: e for e in sorted(entries, key=lambda e: (rank[_normal(_package(e))], e.name))}


def kind_named(text: str) -> str:
    """A plugin kind from its name, plural as its entry point group has it or singular (`cue` or
    `cues`); PluginError naming the known kinds otherwise."""
    known = kinds()
    found = text if text in known else f"{text}s"
    if found not in known:
        raise PluginError(f"unknown plugin kind {text!r} (known: {', '.join(known)})")
    return found


@dataclass
class Registry:
    kind: str
    items: dict[str, Plugin] = field(default_factory=dict)
    problems: list[str] = field(default_factory=list)  # one line per plugin left out
    left_out: dict[str, str] = field(default_factory=dict)  # a left-out plugin's name -> its problem

    def names(self) -> list[str]:
        return sorted(self.items)

    def __contains__(self, name: object) -> bool:
        return name in self.items

    def __iter__(self) -> Iterator[Plugin]:
        return iter(sorted(self.items.values(), key=lambda p: p.name))

    def get(self, name: str) -> Any:
        """The item registered as `name`; PluginError naming the known ones otherwise."""
        found = self.items.get(name)
        if found is None:
            raise PluginError(self.unknown(name))
        return found.value

    def unknown(self, name: str) -> str:
        """Why `name` is not an item: a plugin of that name left out (and why), or the known names."""
        if name in self.left_out:
            return f"{singular(self.kind)} {name!r} is installed but left out: {self.left_out[name]}"
        return f"unknown {singular(self.kind)} {name!r} (known: {', '.join(self.names()) or 'none'})"


# HAVEN's packages (normalised names): their items come first
OURS = frozenset({"haven-sim", "haven-viz", "haven-scenarios"})


def load(kind: str, entries: Iterable[importlib.metadata.EntryPoint]) -> Registry:
    """A registry of `kind` from entry points: HAVEN's own packages first (their names cannot be
    taken over), then the others in name order; each problem is one line."""
    known = kinds()
    if kind not in known:
        raise PluginError(f"unknown plugin kind {kind!r} (known: {', '.join(known)})")
    reg = Registry(kind)
    accept: Callable[[str, Any], Any] = known[kind].load()
    ordered = sorted(entries, key=lambda e: (_normal(_package(e)) not in OURS, _package(e), e.name))
    _loading[kind] = reg
    try:
        for entry in ordered:
            taken = _take(entry, reg, accept)
            if isinstance(taken, Plugin):
                reg.items[entry.name] = taken
            else:
                reg.problems.append(
                    f"{GROUP_PREFIX}{kind} {entry.name} ({entry.value}, from {_package(entry)}): {taken}"
                )
                reg.left_out.setdefault(entry.name, taken)
    finally:
        del _loading[kind]
    return reg


# A registry being loaded, by kind: what `registry` gives an item that builds on the ones before it
# while it is accepted (a lab's robot file that `extends: turtlebot2`), instead of loading it again.
_loading: dict[str, Registry] = {}


def _take(entry: importlib.metadata.EntryPoint, reg: Registry, accept: Callable[[str, Any], Any]) -> Plugin | str:
    """The entry as a registry item, or why not (one line)."""
    if not NAME.match(entry.name):
        return "a name must be lower-case letters, digits and _ (at most 40), starting with a letter"
    if entry.name in reg.items:
        return f"the name is taken by {reg.items[entry.name].package}"
    try:  # (within the load deadline: an import that hangs is left out as one that raises)
        value = contain.call("load", entry.name, entry.load)
    except contain.PluginFailed as e:
        return f"does not load: {e.error}"
    wanted = getattr(value, API_ATTRIBUTE, PLUGIN_API)
    if not isinstance(wanted, int) or isinstance(wanted, bool) or not 1 <= wanted <= PLUGIN_API:
        return (
            f"written for HAVEN's plugin API {str(wanted)[:20]}; "
            f"this HAVEN has version {PLUGIN_API} (upgrade HAVEN, or the plugin)"
        )
    try:
        value = accept(entry.name, value)
    except ValueError as e:
        return first_line(e) or "refused"
    return Plugin(reg.kind, entry.name, _package(entry), entry.value, value)


def _normal(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def _package(entry: importlib.metadata.EntryPoint) -> str:
    dist = entry.dist
    return dist.metadata["Name"] if dist is not None else "?"


def registry(kind: str) -> Registry:
    """The registry of `kind`, from the installed distributions' entry points (loaded once). While
    it loads, the items accepted so far (HAVEN's own first)."""
    loading = _loading.get(kind)
    return loading if loading is not None else _registry(kind)


@cache
def _registry(kind: str) -> Registry:
    return load(kind, importlib.metadata.entry_points(group=GROUP_PREFIX + kind))


def every() -> list[Registry]:
    return [registry(kind) for kind in kinds()]
