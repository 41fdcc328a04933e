"""Every metric of metrics.json and the report CSV: name, unit, definition, source and where its
formula is (one table, rendered into the docs and shipped as the study report's codebook). `<h>`
stands for each person's id, `<zone>` for intimate / personal / social. Times are seconds since
`trial_start`. Ours are computed over [trial_start, trial_end] on one 0.02 s grid, robot and people
interpolated onto it from their messages' header stamps; the `hunav_*` columns on HuNavSim's own
samples (record/hunav.py, 20 Hz). A metric credited to another benchmark carries that benchmark's
name and follows its code exactly; ours say "HAVEN for ROS 2" and, where a benchmark has a similar
measure, "cf." it without claiming to follow it."""

from __future__ import annotations

from haven_scenarios.record.hesitation import MIN_S, SLOW_FRACTION

# Hall (1966), The Hidden Dimension: intimate to 18 in, personal to 4 ft, social to 12 ft; the same
# radii as hunav_metrics.indicator_function (which applies them to surface distances).
ZONES = {"intimate": 0.45, "personal": 1.2, "social": 3.6}

HUNAV = "HuNavSim evaluator (Pérez-Higueras et al. 2023)"
HUNAV_CODE = "robotics-upo/hunav_sim@afa9743 hunav_evaluator/hunav_evaluator/hunav_metrics.py"
SEAN = "SEAN 2.0 (Tsoi et al. 2022)"
SOCNAV = "SocNavBench (Biswas et al. 2022)"
HALL = "Hall (1966) zone radii"
OURS = "HAVEN for ROS 2"
CODE = "haven_scenarios/record/metrics.py"


def cf(other: str) -> str:
    """Ours, with a similar measure elsewhere named (not followed)."""
    return f"{OURS}; cf. {other}"


Row = tuple[str, str, str, str, str]  # name, unit, definition, source, where the formula is

# HuNavSim's evaluator, as its code computes it (record/hunav.py; "samples": 20 Hz ticks holding the
# newest /odom and /humans; "surface": centre distance minus both radii, 0.177 m and 0.25 m).
HUNAV_METRICS: tuple[Row, ...] = (
    (
        "hunav_time_to_reach_goal_s",
        "s",
        "last sample's stamp - first's (trial_start to the last 0.05 s tick before trial_end)",
        HUNAV,
        f"{HUNAV_CODE}:total_time",
    ),
    (
        "hunav_path_length_m",
        "m",
        "sum of the robot's displacements between samples",
        HUNAV,
        f"{HUNAV_CODE}:robot_path_length",
    ),
    (
        "hunav_cumulative_heading_changes_rad",
        "rad",
        "sum over samples of |normalize_angle(yaw_i - yaw_i+1)|",
        HUNAV,
        f"{HUNAV_CODE}:cumulative_heading_changes",
    ),
    (
        "hunav_avg_distance_to_closest_person_m",
        "m",
        "sum over samples of the closest person's surface distance clamped at 0, / all samples",
        HUNAV,
        f"{HUNAV_CODE}:avg_closest_person",
    ),
    (
        "hunav_minimum_distance_to_people_m",
        "m",
        "smallest surface distance to any person over the samples, clamped at 0",
        HUNAV,
        f"{HUNAV_CODE}:minimum_distance_to_people",
    ),
    (
        "hunav_maximum_distance_to_people_m",
        "m",
        "largest centre distance minus the robot's radius only, to any person over the samples",
        HUNAV,
        f"{HUNAV_CODE}:maximum_distance_to_people",
    ),
    (
        "hunav_intimate_space_intrusions_pct",
        "%",
        "% of samples whose closest clamped surface distance is < 0.45 m",
        HUNAV + "; " + HALL,
        f"{HUNAV_CODE}:intimate_space_intrusions",
    ),
    (
        "hunav_personal_space_intrusions_pct",
        "%",
        "% of samples whose closest clamped surface distance is in [0.45, 1.2) m",
        HUNAV + "; " + HALL,
        f"{HUNAV_CODE}:personal_space_intrusions",
    ),
    (
        "hunav_social_space_intrusions_pct",
        "%",
        "% of samples whose closest clamped surface distance is in [1.2, 3.6) m",
        HUNAV + "; " + HALL,
        f"{HUNAV_CODE}:social_space_intrusions",
    ),
    (
        "hunav_robot_on_person_collisions",
        "samples",
        "samples x people with surface distance < 0.02 m attributed to the "
        "robot by HuNavSim's angle/velocity rule (scales with the 20 Hz rate)",
        HUNAV,
        f"{HUNAV_CODE}:robot_on_person_collision",
    ),
    (
        "hunav_person_on_robot_collisions",
        "samples",
        "the same, attributed to the person",
        HUNAV,
        f"{HUNAV_CODE}:person_on_robot_collision",
    ),
    (
        "hunav_time_not_moving_s",
        "s",
        "time_to_reach_goal / samples x samples with v < 0.01 m/s and w < 0.02 rad/s, "
        "SIGNED as its code compares them (abs() wraps the comparison)",
        HUNAV,
        f"{HUNAV_CODE}:time_not_moving",
    ),
    (
        "hunav_avg_robot_linear_speed_mps",
        "m/s",
        "mean over samples of the robot's signed forward speed",
        HUNAV + "; " + SOCNAV,
        f"{HUNAV_CODE}:avg_robot_linear_speed",
    ),
    (
        "hunav_avg_robot_angular_speed_rps",
        "rad/s",
        "mean over samples of |angular speed|",
        HUNAV + "; " + SOCNAV,
        f"{HUNAV_CODE}:avg_robot_angular_speed",
    ),
    (
        "hunav_avg_acceleration_mps2",
        "m/s^2",
        "sum of |dv/dt| between samples, / all samples",
        HUNAV + "; " + SOCNAV,
        f"{HUNAV_CODE}:avg_acceleration",
    ),
    (
        "hunav_avg_overacceleration",
        "m/s^3",
        "sum of |dv/dt| / dt between samples, / all samples (not a jerk; depends on the 20 Hz rate)",
        HUNAV + "; " + SOCNAV,
        f"{HUNAV_CODE}:avg_overacceleration",
    ),
    (
        "hunav_avg_pedestrian_velocity_mps",
        "m/s",
        "sum of every person's speed over the samples / (samples x people in the first sample)",
        HUNAV,
        f"{HUNAV_CODE}:avg_pedestrian_velocity",
    ),
)

METRICS: tuple[Row, ...] = (
    ("scenario", "", "scenario name", OURS, ""),
    (
        "end_reason",
        "",
        "completed, timeout, contact, battery_empty, "
        "stopped / aborted (researcher), interrupted (Ctrl-C, no trial_end)",
        OURS,
        "",
    ),
    ("duration_s", "s", "trial_end - trial_start", OURS, "haven_scenarios/record/metric_kind.py:compute"),
    ("robot_time_to_finish_s", "s", "when the robot's task was done (task_done by robot)", OURS, f"{CODE}:_robot"),
    (
        "robot_path_length_m",
        "m",
        "length of the robot's track on the 0.02 s grid",
        cf("HuNavSim path_length"),
        f"{CODE}:_robot",
    ),
    (
        "robot_time_not_moving_s",
        "s",
        "time with |v| < 0.01 m/s and |w| < 0.01 rad/s",
        cf("HuNavSim time_not_moving (signed v < 0.01, w < 0.02)"),
        f"{CODE}:_robot",
    ),
    ("robot_speed_mean_mps", "m/s", "mean |v| over the grid", cf(SOCNAV + " average speed"), f"{CODE}:_robot"),
    ("robot_speed_max_mps", "m/s", "largest |v|", OURS, f"{CODE}:_robot"),
    (
        "robot_accel_mean_mps2",
        "m/s^2",
        "mean |dv/dt| over the grid",
        cf(SOCNAV + " average acceleration"),
        f"{CODE}:_robot",
    ),
    ("robot_accel_max_mps2", "m/s^2", "largest |dv/dt|", OURS, f"{CODE}:_robot"),
    (
        "robot_jerk_mean_mps3",
        "m/s^3",
        "mean |d2v/dt2| over the grid: a true jerk (not HuNavSim's avg_overacceleration)",
        cf(SOCNAV + " average jerk"),
        f"{CODE}:_robot",
    ),
    (
        "cumulative_heading_change_rad",
        "rad",
        "sum of |heading changes| of the robot on the grid, each wrapped to [-pi, pi)",
        cf("HuNavSim cumulative_heading_changes"),
        f"{CODE}:_robot",
    ),
    (
        "path_efficiency",
        "ratio",
        "planned length / driven length, summed over the goals the robot was given (1 = as planned)",
        cf(SEAN + " path efficiency (geodesic from the start)"),
        f"{CODE}:_navigation",
    ),
    (
        "path_irregularity_rad",
        "rad",
        "the robot's turning beyond the turning of its first plan for each goal",
        cf(SEAN + " path irregularity"),
        f"{CODE}:_navigation",
    ),
    (
        "min_human_centre_distance_m",
        "m",
        "closest approach of the robot to any person, centre to centre",
        OURS,
        f"{CODE}:_proximity",
    ),
    (
        "min_human_surface_distance_m",
        "m",
        "the same minus both radii, not clamped (0 = touching; < 0 = pressed together)",
        cf("hunav_minimum_distance_to_people_m (clamped)"),
        f"{CODE}:_proximity",
    ),
    (
        "avg_closest_human_centre_distance_m",
        "m",
        "mean over the grid of the distance to the closest person, centre to centre",
        cf("hunav_avg_distance_to_closest_person_m (surfaces)"),
        f"{CODE}:_proximity",
    ),
    (
        "closest_intimate_centre_pct",
        "%",
        "time the closest person's centre is within 0.45 m of the robot's",
        cf(HALL + "; HuNavSim measures between surfaces"),
        f"{CODE}:_proximity",
    ),
    (
        "closest_personal_centre_pct",
        "%",
        "time it is 0.45-1.2 m away, centre to centre",
        cf(HALL),
        f"{CODE}:_proximity",
    ),
    ("closest_social_centre_pct", "%", "time it is 1.2-3.6 m away, centre to centre", cf(HALL), f"{CODE}:_proximity"),
    (
        "closest_public_centre_pct",
        "%",
        "time it is farther than 3.6 m, centre to centre",
        cf(HALL),
        f"{CODE}:_proximity",
    ),
    (
        "human_contacts",
        "episodes",
        "robot-person contact EPISODES (touches less than 0.5 s apart are one episode)",
        cf(SEAN + " collisions; HuNavSim counts samples"),
        f"{CODE}:_contacts",
    ),
    (
        "human_contacts_robot_on_person",
        "episodes",
        "episodes where the robot closed in faster at the first touch",
        cf(SEAN + " / HuNavSim robot-on-person collisions (another rule)"),
        "haven_scenarios/record/contacts.py:attribute",
    ),
    (
        "human_contacts_person_on_robot",
        "episodes",
        "episodes where the person closed in faster at the first touch",
        cf(SEAN + " / HuNavSim person-on-robot collisions (another rule)"),
        "haven_scenarios/record/contacts.py:attribute",
    ),
    ("wall_contacts", "episodes", "robot-wall contact episodes", OURS, f"{CODE}:_contacts"),
    ("waits", "count", "times the robot waited for a person (waiting events)", OURS, f"{CODE}:_navigation"),
    (
        "wait_time_s",
        "s",
        "time spent waiting (waiting until resumed, a new plan or a detour)",
        OURS,
        f"{CODE}:_navigation",
    ),
    ("replans", "count", "detours around a person (replanned events)", OURS, f"{CODE}:_navigation"),
    ("reverts", "count", "returns to the original path (reverted events)", OURS, f"{CODE}:_navigation"),
    ("plans_refused", "count", "goals the planner refused", OURS, f"{CODE}:_navigation"),
    ("battery_used", "charge", "sum of the battery level's decreases (1 = a full charge)", OURS, f"{CODE}:_mission"),
    ("battery_final", "charge", "battery level at trial_end (1 = full)", OURS, f"{CODE}:_mission"),
    ("charge_trips", "count", "times the mission sent the robot to charge", OURS, f"{CODE}:_mission"),
    ("gems_robot", "count", "gems the robot collected", OURS, f"{CODE}:_mission"),
    ("gems_human", "count", "gems the people collected", OURS, f"{CODE}:_mission"),
    ("robot_gem_order", "", "the robot's gems in the order collected", OURS, f"{CODE}:_mission"),
    ("path_projection_shown_s", "s", "time the projected path was on show", OURS, f"{CODE}:_exposure"),
    ("turn_signal_shown_s", "s", "time a turn signal was lit", OURS, f"{CODE}:_exposure"),
    ("thought_bubble_shown_s", "s", "time the thought bubble was on show", OURS, f"{CODE}:_exposure"),
    ("battery_indicator_shown_s", "s", "time the battery gauge was on show", OURS, f"{CODE}:_exposure"),
    (
        "nav_points_shown_s",
        "s",
        "aerial robots only: time NavPoints were on show (Walker et al. 2018)",
        OURS,
        f"{CODE}:_exposure",
    ),
    (
        "arrow_shown_s",
        "s",
        "aerial robots only: time the Arrow was on show (Walker et al. 2018)",
        OURS,
        f"{CODE}:_exposure",
    ),
    (
        "gaze_shown_s",
        "s",
        "aerial robots only: time the Gaze eye was on show (Walker et al. 2018)",
        OURS,
        f"{CODE}:_exposure",
    ),
    ("turns", "count", "turns of the robot (|w| rising above 0.3 rad/s)", OURS, f"{CODE}:signal_lead_times"),
    ("turns_signalled", "count", "turns the signal on that side announced", OURS, f"{CODE}:signal_lead_times"),
    (
        "turn_signal_lead_s_mean",
        "s",
        "mean time the matching signal had been lit when a turn began (0 if not)",
        OURS,
        f"{CODE}:signal_lead_times",
    ),
    ("passes", "count", "re-plans around a person on the path (the paper's Figure 3)", OURS, f"{CODE}:_passes"),
    (
        "passes_signalled",
        "count",
        "passes whose side's turn signal was lit before the robot began to turn that way",
        OURS,
        f"{CODE}:pass_signal_leads",
    ),
    (
        "pass_signal_lead_s_median",
        "s",
        "median time that signal had been lit when the curve began (0 if not)",
        OURS,
        f"{CODE}:pass_signal_leads",
    ),
    (
        "condition_segments",
        "",
        "metrics.json only: per stretch of one condition, its start, end and cue exposure",
        OURS,
        f"{CODE}:_cues",
    ),
    (
        "valid",
        "",
        "false when the recording is incomplete (see invalid_reasons); an interrupted trial recorded whole is valid",
        OURS,
        "haven_scenarios/record/validity.py:check",
    ),
    (
        "invalid_reasons",
        "",
        "why a session is not valid: lost messages, gaps, "
        "a missing trial_end, bag or scenario copy, outside publishers",
        OURS,
        "haven_scenarios/record/validity.py:check",
    ),
    (
        "outside_publishers",
        "",
        "outside publishers the lockstep clock ignored (ones that could change the outcome: invalid_reasons)",
        OURS,
        "haven_scenarios/record/validity.py:check",
    ),
    *HUNAV_METRICS,
    (
        "<h>_time_to_finish_s",
        "s",
        "when the person's own task was done (their last gem or room)",
        OURS,
        f"{CODE}:_person",
    ),
    ("<h>_path_length_m", "m", "length of the person's track", OURS, f"{CODE}:_person"),
    (
        "<h>_time_not_moving_s",
        "s",
        "time the person stood (speed < 0.05 m/s) until their own task was done (their task_done; trial_end if none)",
        cf("HuNavSim time_not_moving (of the robot)"),
        f"{CODE}:_person",
    ),
    (
        "<h>_hesitations",
        "count",
        "times the person, walking their task, went slower than "
        f"{SLOW_FRACTION:g} of their own walking speed for {MIN_S:g} s or more",
        OURS,
        "haven_scenarios/record/hesitation.py:hesitations",
    ),
    (
        "<h>_hesitation_s",
        "s",
        "time spent in those hesitations",
        OURS,
        "haven_scenarios/record/hesitation.py:hesitations",
    ),
    (
        "<h>_detour_m",
        "m",
        "walked length minus the shortest walk through where each gem or room counted, in order (needs the world)",
        OURS,
        f"{CODE}:_detour",
    ),
    ("<h>_gems", "count", "gems the person collected", OURS, f"{CODE}:_person"),
    (
        "<h>_min_centre_distance_m",
        "m",
        "closest approach of the robot to this person, centre to centre",
        OURS,
        f"{CODE}:_person",
    ),
    (
        "<h>_contacts",
        "episodes",
        "contact episodes with this person (and _robot_on_person, _person_on_robot)",
        cf(SEAN + " collisions"),
        f"{CODE}:_contacts",
    ),
    (
        "<h>_<zone>_centre_intrusion_s",
        "s",
        "time the robot's centre was within the zone's radius of this person's centre (cumulative zones)",
        cf(HALL),
        f"{CODE}:_person",
    ),
    (
        "<h>_<zone>_centre_intrusions",
        "count",
        "times the robot's centre entered the zone's radius of this person's centre",
        cf(HALL),
        f"{CODE}:_person",
    ),
    (
        "<h>_<zone>_centre_band_s",
        "s",
        "time the robot was in the zone's band only, centre to centre (disjoint: "
        "intimate < 0.45 <= personal < 1.2 <= social < 3.6)",
        cf(HALL),
        f"{CODE}:_person",
    ),
)


def plugin_rows() -> list[Row]:
    """The codebook rows of the installed metric plugins that document their columns (`columns`,
    (name, unit, definition, source) rows: the formula is the plugin's), and of the installed cues' exposure."""
    from haven_sim.common import plugins  # (the registry loads the metrics module, which imports this one)

    rows = [(*c, f"{p.package}:{p.name}") for p in plugins.registry("metrics") for c in p.value.columns]
    ours = {m[0] for m in METRICS}
    cues = [p for p in plugins.registry("cues") if p.value.exposure not in ours]  # (a lab's cue's exposure column)
    return [r for r in rows if r[0] not in ours] + [
        (p.value.exposure, "s", f"time the {p.name} cue was on show", p.package, f"{p.package}:{p.name}") for p in cues
    ]


def rows(plugins: bool = True) -> tuple[Row, ...]:
    """The codebook's rows: ours, then (`plugins`) the installed plugins' documented columns."""
    return (*METRICS, *plugin_rows()) if plugins else METRICS


def markdown(plugins: bool = True) -> str:
    """The codebook as a Markdown table (the docs' metric table)."""
    lines = ["| metric | unit | definition | source | formula |", "|---|---|---|---|---|"]
    lines += [
        f"| `{name}` | {unit} | {definition} | {source} | {f'`{formula}`' if formula else ''} |"
        for name, unit, definition, source, formula in rows(plugins)
    ]
    return "\n".join(lines)


def pattern(key: str, humans: list[str]) -> str:
    """A metrics.json key's row name: `<h>_...` and `<zone>` put back for a person's own keys."""
    for h in sorted(humans, key=len, reverse=True):
        if key.startswith(h + "_"):
            rest = key[len(h) + 1 :]
            for z in ZONES:
                rest = "<zone>_" + rest[len(z) + 1 :] if rest.startswith(z + "_") else rest
            return "<h>_" + rest.removesuffix("_robot_on_person").removesuffix("_person_on_robot")
    return key


def documented(key: str, humans: list[str]) -> bool:
    """Whether a metrics.json key is in the table (per-person keys by their pattern)."""
    names = {m[0] for m in rows()}
    return key in names or pattern(key, humans) in names
