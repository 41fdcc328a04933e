"""Every metric of metrics.json and the report CSV: name, unit, definition, source (one table, also
rendered into the README). `<h>` stands for each person's id, `<zone>` for intimate / personal /
social. Times are seconds since `trial_start`; everything is computed over [trial_start, trial_end]
on one 0.02 s grid, robot and people interpolated onto it from their messages' header stamps."""

from __future__ import annotations

ZONES = {"intimate": 0.45, "personal": 1.2, "social": 3.6}  # Hall's proxemics, centre to centre

HUNAV = "HuNavSim evaluator (Pérez-Higueras et al. 2023)"
SEAN = "SEAN 2.0 (Tsoi et al. 2022)"
SOCNAV = "SocNavBench (Biswas et al. 2022)"
HALL = "Hall's proxemics, as in HuNavSim"
OURS = "HAVEN for ROS 2"

# name, unit, definition, source
METRICS: tuple[tuple[str, str, str, str], ...] = (
    ("scenario", "", "scenario name", OURS),
    ("end_reason", "", "completed, timeout, contact, battery_empty, stopped / aborted (researcher), interrupted (Ctrl-C, no trial_end)", OURS),
    ("duration_s", "s", "trial_end - trial_start", OURS),
    ("robot_time_to_finish_s", "s", "when the robot's task was done (task_done by robot)", HUNAV + ": time to reach goal"),
    ("robot_path_length_m", "m", "length of the robot's track", HUNAV),
    ("robot_time_not_moving_s", "s", "time with |v| < 0.01 m/s and |w| < 0.01 rad/s", HUNAV + " / " + SEAN),
    ("robot_speed_mean_mps", "m/s", "mean |v|", SOCNAV),
    ("robot_speed_max_mps", "m/s", "largest |v|", OURS),
    ("robot_accel_mean_mps2", "m/s^2", "mean |dv/dt|", SOCNAV),
    ("robot_accel_max_mps2", "m/s^2", "largest |dv/dt|", OURS),
    ("robot_jerk_mean_mps3", "m/s^3", "mean |d2v/dt2|", SOCNAV + ": over-acceleration"),
    ("cumulative_heading_change_rad", "rad", "sum of |heading changes| of the robot", HUNAV),
    ("path_efficiency", "", "planned length / driven length, summed over the goals the robot was given (1 = as planned)", SEAN),
    ("path_irregularity_rad", "rad", "the robot's turning beyond the turning of its first plan for each goal", SEAN),
    ("min_human_distance_m", "m", "closest approach of the robot to any person, centre to centre", HUNAV),
    ("min_human_surface_distance_m", "m", "the same between the bodies' surfaces (0 = touching)", OURS),
    ("avg_closest_human_distance_m", "m", "mean distance to the closest person, centre to centre", HUNAV),
    ("closest_intimate_pct", "%", "time the closest person is within 0.45 m", HALL),
    ("closest_personal_pct", "%", "time the closest person is 0.45-1.2 m away", HALL),
    ("closest_social_pct", "%", "time the closest person is 1.2-3.6 m away", HALL),
    ("closest_public_pct", "%", "time the closest person is farther than 3.6 m", HALL),
    ("human_contacts", "", "robot-person contact episodes (touches less than 0.5 s apart are one episode)", SEAN),
    ("human_contacts_robot_on_person", "", "episodes where the robot closed in faster", SEAN + " / " + HUNAV),
    ("human_contacts_person_on_robot", "", "episodes where the person closed in faster", SEAN + " / " + HUNAV),
    ("wall_contacts", "", "robot-wall contact episodes", OURS),
    ("waits", "", "times the robot waited for a person (waiting events)", OURS),
    ("wait_time_s", "s", "time spent waiting (waiting until resumed, a new plan or a detour)", OURS),
    ("replans", "", "detours around a person (replanned events)", OURS),
    ("reverts", "", "returns to the original path (reverted events)", OURS),
    ("plans_refused", "", "goals the planner refused", OURS),
    ("battery_used", "", "sum of the battery level's decreases (1 = a full charge)", OURS),
    ("battery_final", "", "battery level at trial_end", OURS),
    ("charge_trips", "", "times the mission sent the robot to charge", OURS),
    ("gems_robot", "", "gems the robot collected", OURS),
    ("gems_human", "", "gems the people collected", OURS),
    ("robot_gem_order", "", "the robot's gems in the order collected", OURS),
    ("path_projection_shown_s", "s", "time the projected path was on show", OURS),
    ("turn_signal_shown_s", "s", "time a turn signal was lit", OURS),
    ("thought_bubble_shown_s", "s", "time the thought bubble was on show", OURS),
    ("battery_indicator_shown_s", "s", "time the battery gauge was on show", OURS),
    ("turns", "", "turns of the robot (|w| rising above 0.3 rad/s)", OURS),
    ("turns_signalled", "", "turns the signal on that side announced", OURS),
    ("turn_signal_lead_s_mean", "s", "mean time the matching signal had been lit when a turn began (0 if not)", OURS),
    ("passes", "", "re-plans around a person on the path (the paper's Figure 3)", OURS),
    ("passes_signalled", "", "passes whose side's turn signal was lit before the robot began to turn that way", OURS),
    ("pass_signal_lead_s_median", "s", "median time that signal had been lit when the curve began (0 if not)", OURS),
    ("condition_segments", "", "metrics.json only: per stretch of one condition, its start, end and cue exposure", OURS),
    ("valid", "", "false when the recording is incomplete (see invalid_reasons); an interrupted trial recorded whole is valid", OURS),
    ("invalid_reasons", "", "why a session is not valid: lost messages, gaps, a missing trial_end, bag or scenario copy, outside publishers", OURS),
    ("outside_publishers", "", "outside publishers the lockstep clock ignored (ones that could change the outcome: invalid_reasons)", OURS),
    ("<h>_time_to_finish_s", "s", "when the person's own task was done (their last gem or room)", OURS),
    ("<h>_path_length_m", "m", "length of the person's track", OURS),
    ("<h>_time_not_moving_s", "s", "time the person stood (speed < 0.05 m/s)", HUNAV),
    ("<h>_hesitations", "", "times the person, walking their task, went slower than half their own walking speed for 0.5 s or more", OURS),
    ("<h>_hesitation_s", "s", "time spent in those hesitations", OURS),
    ("<h>_detour_m", "m", "walked length minus the shortest walk through where each gem or room counted, in order (needs the world)", OURS),
    ("<h>_gems", "", "gems the person collected", OURS),
    ("<h>_min_distance_m", "m", "closest approach of the robot to this person, centre to centre", HUNAV),
    ("<h>_contacts", "", "contact episodes with this person (and _robot_on_person, _person_on_robot)", SEAN),
    ("<h>_<zone>_intrusion_s", "s", "time the robot was within the zone's radius of this person (cumulative zones)", HALL),
    ("<h>_<zone>_intrusions", "", "times the robot entered the zone's radius", HALL),
    ("<h>_<zone>_band_s", "s", "time the robot was in the zone's band only (disjoint: intimate < 0.45 <= personal < 1.2 <= social < 3.6)", HALL),
)


def plugin_rows() -> list[tuple[str, str, str, str]]:
    """The codebook rows of the installed metric plugins that document their columns (`columns`),
    and of the installed cues' exposure."""
    from haven_sim.common import plugins  # (the registry loads the metrics module, which imports this one)

    rows = [tuple(c) for p in plugins.registry("metrics") for c in getattr(p.value, "columns", ())]
    ours = {m[0] for m in METRICS}
    cues = [p for p in plugins.registry("cues") if p.value.exposure not in ours]  # (a lab's cue's exposure column)
    return rows + [(p.value.exposure, "s", f"time the {p.name} cue was on show", p.package) for p in cues]


def markdown(plugins: bool = True) -> str:
    """The codebook: ours, then (`plugins`) the installed plugins' documented columns."""
    lines = ["| metric | unit | definition | source |", "|---|---|---|---|"]
    rows = (*METRICS, *plugin_rows()) if plugins else METRICS
    lines += [f"| `{name}` | {unit} | {definition} | {source} |" for name, unit, definition, source in rows]
    return "\n".join(lines)


def documented(key: str, humans: list[str]) -> bool:
    """Whether a metrics.json key is in the table (per-person keys by their pattern)."""
    names = {m[0] for m in (*METRICS, *plugin_rows())}
    if key in names:
        return True
    for h in humans:
        if key.startswith(h + "_"):
            rest = key[len(h) + 1 :]
            for z in ZONES:
                rest = rest.replace(z + "_", "<zone>_") if rest.startswith(z + "_") else rest
            if "<h>_" + rest in names or "<h>_" + rest.removesuffix("_robot_on_person").removesuffix("_person_on_robot") in names:
                return True
    return False
