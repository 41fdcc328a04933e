"""The README's Figure 3 picture: the shipped hallway (seed 0, every cue on so the projected path
shows, and the simulated person, seeing it, keeps to their side early), the moment the robot has
decided to pass the person and lit its turn signal, before the curve begins; with both tracks
through the pass. Prints what the picture shows, measured.

usage: python bench/figure3.py [--seed 0] [--out haven_scenarios/doc/figure3_pass.png]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from haven_scenarios.record.timeline import Timeline
from haven_scenarios.run.trial import Trial
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.events import EventKind
from haven_viz.cues import Toggles
from haven_viz.render import render_scene
from haven_viz.world_markers import body_markers, world_markers

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--out", default=str(ROOT / "haven_scenarios" / "doc" / "figure3_pass.png"))
    args = ap.parse_args()
    trial = Trial(load_scenario("hallway"), args.seed, Toggles())
    rec, viz = trial.recording, trial.viz
    moment = None
    while trial.director.ended is None and trial.sim.sim.time < 400.0:
        trial.loop.step()
        passed = rec.first(EventKind.REPLANNED)
        if (
            moment is None
            and passed is not None
            and viz.state is not None
            and viz.state.turn_signal != 0
            and viz.robot is not None
        ):
            side = passed["side"]
            humans = {h: p for h, p in viz.humans.items()}
            markers = viz.cues.frame(
                viz.robot, [(p.x, p.y) for p in humans.values()], viz.battery, viz.thought, viz.toggles
            ).markers
            moment = (trial.sim.sim.time, side, markers + body_markers(viz.robot, humans), passed)
    result = trial.run()
    assert moment is not None, "no pass in this trial"
    when, side, markers, passed = moment
    m = result.metrics
    tl = Timeline.of(rec, *rec.window())
    t0 = rec.window()[0]  # type: ignore[index]
    span = (tl.t > passed.stamp - t0 - 4.0) & (tl.t < passed.stamp - t0 + 14.0)
    trails = {"robot": (tl.robot_xy[span], "tab:blue"), "person (h1)": (tl.humans["h1"][span], "tab:red")}
    x = float(np.mean(tl.robot_xy[span, 0]))
    lead, closest = m["pass_signal_lead_s_median"], m["min_human_centre_distance_m"]
    title = (
        f"Figure 3: an oncoming person {passed['gap_m']:.1f} m ahead "
        "(who has seen the projected path and keeps to their side);\n"
        f"the robot lights its {side} signal, curves {side} {lead:.1f} s later, "
        f"and passes {closest:.2f} m from them (centre to centre)"
    )
    k = int(np.argmin(np.hypot(*(tl.humans["h1"] - tl.robot_xy).T)))
    points = [(*tl.humans["h1"][k], "h1 when passed", "tab:red"), (*tl.robot_xy[k], "robot then", "tab:blue")]
    view = (x - 5.5, -0.2, x + 5.5, 4.2)
    out = render_scene(
        trial.scenario.world, world_markers(trial.scenario.world) + markers, args.out, title, trails, points, view=view
    )
    print(
        f"pass at t={passed.stamp - t0:.1f} s, side {side}, "
        f"signal lead {lead} s, planned clearance {passed['clearance_m']} m"
    )
    print(f"closest approach {closest} m centre to centre; picture at t={when - t0:.1f} s: {out}")


if __name__ == "__main__":
    main()
