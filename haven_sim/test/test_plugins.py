"""Plugins by name (common/plugins.py): ours come through entry points like anybody's; a broken
plugin is one line and leaves the others working."""

from __future__ import annotations

from typing import Any

import pytest
from fake_plugins import Entry

from haven_sim.common import plugins


class Model:
    def __init__(self, *args: Any) -> None:
        self.args = args


def test_a_broken_plugin_is_one_line_and_the_others_still_work():
    reg = plugins.load(
        "participants",
        [
            Entry("shy", "lab.people:Shy", "lab_people", Model),
            Entry("walker", "lab.people:Walker", "lab_people", Model),  # taken by ours, whatever the order
            Entry("walker", "haven_scenarios.study.participants:Walker", "haven_scenarios", Model),
            Entry("broken", "lab.people:Broken", "lab_people", ImportError("No module named 'lab.missing'\nmore")),
            Entry("number", "lab.people:NUMBER", "lab_people", 3),
            Entry("Bad-Name", "lab.people:Bad", "lab_people", Model),
        ],
    )
    assert reg.names() == ["shy", "walker"] and reg.items["walker"].package == "haven_scenarios"
    assert len(reg.problems) == 4 and all("\n" not in p for p in reg.problems)
    said = "\n".join(reg.problems)
    assert (
        "haven.participants walker (lab.people:Walker, from lab_people): the name is taken by haven_scenarios" in said
    )
    assert (
        "haven.participants broken (lab.people:Broken, from lab_people): "
        "does not load: ImportError: No module named 'lab.missing'" in said
    )
    assert "haven.participants number (lab.people:NUMBER, from lab_people): is not a participant model" in said
    assert "Bad-Name" in said and "lower-case letters" in said
    assert isinstance(reg.get("shy")(1, 2), Model)
    with pytest.raises(plugins.PluginError, match=r"^unknown participant model 'sly' \(known: shy, walker\)$"):
        reg.get("sly")
    with pytest.raises(plugins.PluginError, match="unknown plugin kind"):
        plugins.load("gadgets", [])


class Later(Model):
    haven_plugin_api = plugins.PLUGIN_API + 1  # written for a plugin API this HAVEN does not have yet


class Today(Model):
    haven_plugin_api = plugins.PLUGIN_API


def test_a_plugin_written_for_a_newer_plugin_api_is_left_out_saying_so():
    reg = plugins.load(
        "participants",
        [
            Entry("later", "lab.people:Later", "lab_people", Later),
            Entry("today", "lab.people:Today", "lab_people", Today),
            Entry("odd", "lab.people:Odd", "lab_people", type("Odd", (Model,), {"haven_plugin_api": "1"})),
        ],
    )
    assert reg.names() == ["today"]
    now, later = plugins.PLUGIN_API, plugins.PLUGIN_API + 1
    assert (
        reg.left_out["later"]
        == f"written for HAVEN's plugin API {later}; this HAVEN has version {now} (upgrade HAVEN, or the plugin)"
    )
    assert "plugin API 1;" in reg.left_out["odd"]  # (a version is a whole number)


def test_an_item_can_build_on_one_registered_before_it_while_the_registry_loads(tmp_path):
    """A lab's robot file that extends a catalogue robot: accepting it reads the robots registry,
    which is the one being loaded (the items so far), not a second load of it."""
    ours = plugins.registry("robots")
    mine = tmp_path / "slow_bot.yaml"
    mine.write_text(
        "extends: turtlebot2\nname: slow_bot\nmotion: {cruise_speed_mps: 0.3}\n"
        "sources: {motion.cruise_speed_mps: ours}\n"
    )
    entries = [
        *(Entry(p.name, p.target, p.package, p.value) for p in ours),
        Entry("slow_bot", "lab:SLOW", "lab_robots", str(mine)),
    ]
    reg = plugins.load("robots", entries)
    assert reg.problems == []
    assert reg.get("slow_bot").motion.cruise_speed_mps == 0.3
    assert reg.get("slow_bot").limits == reg.get("turtlebot2").limits
