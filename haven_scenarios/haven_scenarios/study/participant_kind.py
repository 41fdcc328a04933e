"""What a simulated participant model is: the plugin kind `haven.participants` (a class or function
that makes a `Participant`), and a participant made by its model's name."""

from __future__ import annotations

import inspect
from collections.abc import Sequence
from typing import Any, Protocol, cast

from haven_scenarios.study.participants import Participant, Stop
from haven_scenarios.study.person import PersonParams
from haven_sim.common import contain, plugins
from haven_sim.nav.planner import Planner


class ParticipantFactory(Protocol):
    """A `haven.participants` plugin: a class or function that makes a simulated participant."""

    def __call__(
        self, human_id: str, stops: Sequence[Stop], planner: Planner, speed_mps: float, seed: int, params: PersonParams
    ) -> Participant: ...


def accept_plugin(name: str, value: Any) -> ParticipantFactory:
    """A `haven.participants` plugin (haven_sim/common/plugins.py): a class or factory."""
    wanted = "a class or function taking (human_id, stops, planner, speed_mps, seed, params)"
    if not callable(value):
        raise ValueError(f"is not a participant model: {wanted}")
    try:
        inspect.signature(value).bind("h1", [], None, 1.0, 0, None)
    except TypeError as e:
        raise ValueError(f"is not a participant model: {wanted} ({e})") from None
    except ValueError:  # (no signature to read: a builtin; it is tried when a trial makes one)
        pass
    return cast(ParticipantFactory, value)


def make_walker(
    model: str,
    human_id: str,
    stops: Sequence[Stop],
    planner: Planner,
    speed_mps: float,
    seed: int,
    params: PersonParams | None = None,
) -> Participant:
    """A simulated participant of the named model (the names a scenario file uses): a plugin of
    kind `participants` (ours: walker, blocker and yielder, in pyproject.toml), a class or factory that
    takes these arguments and returns a `Participant`. One that raises or overruns its deadline:
    `contain.PluginFailed` (its trial ends, not valid)."""
    factory = plugins.registry("participants").get(model)
    made: Participant = contain.call(
        "participants", model, factory, human_id, stops, planner, speed_mps, seed, params or PersonParams()
    )
    return made
