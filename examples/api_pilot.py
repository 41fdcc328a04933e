"""A pilot from a Python script (haven_scenarios.api): one recorded trial with the whole node
suite, then a three-participant pilot study of the hallway with and without turn signals
(simulated participants, batch trials), its report, and a look at the numbers.

usage: python examples/api_pilot.py [FOLDER]   (default: ./pilot; ROS_DOMAIN_ID as for haven run)
"""

import sys
from pathlib import Path

import yaml

from haven_scenarios import api

folder = Path(sys.argv[1] if len(sys.argv) > 1 else "pilot")
folder.mkdir(parents=True, exist_ok=True)

# One recorded trial: blocks until the session folder is complete.
trial = api.recorded_trial(
    "hallway", participant="pilot", condition=["turn_signals"], seed=1, sessions=folder / "sessions"
)
print(
    f"recorded: {trial.folder.name}: {trial.outcome}, valid {trial.valid}, "
    f"closest approach {trial.metrics['min_human_centre_distance_m']} m"
)

# A pilot study: three participants, two conditions, counterbalanced.
study = folder / "pilot_study.yaml"
study.write_text(
    yaml.safe_dump(
        {
            "name": "pilot",
            "scenarios": ["hallway"],
            "conditions": {"none": ["none"], "signals": ["turn_signals"]},
            "participants": ["p01", "p02", "p03"],
            "counterbalancing": "latin",
            "seeds": {"policy": "per_participant", "base": 0},
        }
    )
)
print(f"plan: {len(api.study_plan(str(study)))} trials")
for participant in ("p01", "p02", "p03"):
    code = api.run_participant(str(study), participant, batch=True, dir=folder / "study")
    assert code == 0, f"{participant}: exit code {code}"
done = [t for t in api.study_status(str(study), dir=folder / "study") if t.status == "done"]
report = api.study_report(str(study), dir=folder / "study")
print(f"study: {len(done)} trials done; {report.counts}; tables in {report.folder}")
