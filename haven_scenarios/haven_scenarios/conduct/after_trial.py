"""`haven run --web --questionnaire SPEC ...`: questionnaires in the participants' pages after the trial.

Each SPEC is a built-in (`nasa_tlx`, `godspeed`) or a YAML file holding one Likert questionnaire
(study/questionnaires.py says what it holds). The web node shows them in order once the trial is
over and writes the answers (record/answers.py). `haven run` then stops the trial's nodes but the
recorder and the web node, and waits until every teleoperated participant has answered every
questionnaire, the researcher presses the console's **Skip questionnaires**, or Ctrl-C; then it
stops as after any trial. session.json says which questionnaires each participant answered and how
the wait ended; unanswered ones do not make the session invalid.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Protocol

from haven_scenarios.conduct.outcomes import exit_text
from haven_scenarios.record.answers import answered, over, wanted
from haven_scenarios.run.supervisor import Supervisor
from haven_scenarios.study.questionnaires import from_mapping, registered, resolve
from haven_scenarios.study.scenario import Scenario
from haven_sim.common import nodes, plugins
from haven_sim.common.yaml_file import file_label, read_yaml

KEPT = (nodes.RECORDER.key, nodes.WEB.key)  # what runs on while the participants answer
Asked = tuple[list[str], list[str]]  # the teleoperated humans, the questionnaires' names


class HasQuestionnaires(Protocol):  # (the run's WebOptions)
    @property
    def questionnaires(self) -> tuple[str | dict[str, Any], ...]: ...


def asked(scenario: Scenario, web: HasQuestionnaires | None) -> Asked | None:
    """Who answers which questionnaires after this run's trial (None: nobody is asked any)."""
    if web is None or not web.questionnaires:
        return None
    return [h.id for h in scenario.humans if h.teleoperated], names(web.questionnaires)


def spec(text: str) -> str | dict[str, Any]:
    """A built-in's name, or the Likert mapping in a YAML file (checked); ValueError in one line naming the file."""
    if text in registered():
        return text
    path = Path(text)
    if not path.exists():
        reg = plugins.registry("questionnaires")
        if text in reg.left_out:
            raise ValueError(f"--questionnaire {text[:80]}: {reg.unknown(text)}")
        raise ValueError(
            f"--questionnaire {text[:80]}: neither a registered questionnaire ({', '.join(registered())}) nor a file"
        )
    data = read_yaml(path, "questionnaire file")
    if not isinstance(data, dict):
        raise ValueError(
            f"{file_label(path)}: must be a mapping of one Likert questionnaire (name, points, anchors, items)"
        )
    from_mapping(data, file_label(path) + ":")
    return data


def specs(texts: Sequence[str] | None, web: bool, teleoperated: Sequence[str]) -> tuple[str | dict[str, Any], ...]:
    """The run's questionnaire specs (() for none); ValueError (one line) if they cannot be asked:
    no web pages, nobody teleoperated, a bad name or file, a name twice."""
    if not texts:
        return ()
    if not web or not teleoperated:
        raise ValueError(
            "--questionnaire: participants answer in their pages: needs --web and teleoperated humans (--teleop)"
        )
    out = tuple(spec(text) for text in texts)
    resolve(list(out), "--questionnaire")
    return out


def as_parameter(questionnaires: Sequence[str | dict[str, Any]]) -> str:
    """The specs as the web node's `questionnaires` parameter: JSON, quoted so that ROS reads a string."""
    return "'" + json.dumps(list(questionnaires), separators=(",", ":")).replace("'", "''") + "'"


def names(questionnaires: Sequence[str | dict[str, Any]]) -> list[str]:
    return [q.name for q in resolve(list(questionnaires), "questionnaires")]


def wait_for_answers(sup: Supervisor, folder: Path, humans: Sequence[str], asked: Sequence[str]) -> str:
    """After a trial that ended: how the questionnaires ended ("answered", "skipped", "interrupted",
    or the node that stopped them); the recorder and the web node run on meanwhile."""
    if not wanted(folder):
        return "not asked: the trial did not start or was aborted"
    sup.stop_some([n for n in sup.procs if n not in KEPT])
    print(
        f"haven: trial over: waiting for {', '.join(humans)} to answer {', '.join(asked)} "
        "(Ctrl-C or the console's Skip questionnaires ends the wait)",
        flush=True,
    )
    ended: list[str] = []

    def done() -> bool:
        ended[:] = [s for s in [over(folder, humans, asked)] if s]
        return bool(ended)

    exited = sup.wait(until=done)
    if ended:
        return ended[0]
    return f"stopped: {exit_text(exited.name, exited.code)}" if exited is not None else "interrupted"


def summary(folder: Path, humans: Sequence[str], asked: Sequence[str], how: str | None) -> dict[str, Any]:
    """For session.json: what each participant answered, and how the questionnaires ended."""
    return {
        "questionnaires_answered": answered(folder, humans, asked),
        "questionnaires_end": how or "not asked: the trial did not end normally",
    }
