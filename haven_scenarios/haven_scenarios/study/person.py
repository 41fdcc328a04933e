"""A simulated participant's perception and walking parameters, with the literature they come from,
and the person and trial drawn from them.

`PersonParams` is what a scenario file sets per person (`humans: - {id: h1, params: {reaction_s: 1.0}}`)
and what a sweep varies (`dataclasses.replace(task.params, reaction_s=0.8)`): every field is a number.
The plain fields are the population's typical values; each `*_person_sd` spreads them between people
(a random effect: the same person keeps their draw over all their trials) and each `*_trial_sd`
within a person from trial to trial (`individual` draws both). A person is named by `person_seed`
(a study gives each participant their own; -1: a new person per trial seed, as a plain sweep has),
and `session_trial` (1 = their first trial) is how far into their session the trial comes: people
learn, so their reaction time and their rate of misreading a cue shrink as the power law of
practice has it (Newell & Rosenbloom 1981: performance improves as a power of the number of trials).

Typical values and their sources (ASSUMPTION marks a value of ours, not a measured figure):
  * `fov_deg` 110: the horizontal field in which a walker notices things without turning the head.
    The binocular field is about 120 deg of the ~200 deg total (Strasburger, Rentschler & Juttner
    2011, J. Vision 11(5):13), and HAVEN's participants saw the cues through a VR headset, whose field
    is about 100-110 deg.
  * `view_m` 8: cues and the robot are noticed within Hall's (1966) public distance (3.6-7.6 m); a
    0.2 m path marker subtends under 1.5 deg beyond it.
  * `reaction_s` 1.0: the perception-response time to a moving hazard (Green 2000, "How long does it
    take to stop?": about 0.7 s when expected, 1.25-1.5 s when not). Between people a log-normal
    spread, `reaction_person_sd` 0.25 (ASSUMPTION: +-2 sd spans about 0.6-1.65 s, Green's range);
    within a person `reaction_trial_sd` 0.1 (ASSUMPTION).
  * walking speed: the scenario's `speed_mps` (comfortable gait 1.3-1.4 m/s outdoors, Bohannon 1997;
    about 1.4 m/s over ground, Mohler et al. 2007; slower indoors with a task). Between people
    `speed_person_sd` 0.11 of it: the coefficient of variation of comfortable gait speed among
    adults of one age band (Bohannon 1997, Age and Ageing 26:15-19: sd about 0.15 m/s at a mean
    of about 1.4 m/s); within a person `speed_trial_sd` 0.04 (ASSUMPTION).
  * `pass_gap_m` 0.5: the gap a person keeps between their body and the robot's shown path when
    passing; Pacchierotti, Christensen & Jensfelt (2006) found 0.4 m lateral distance the least
    subjects accepted in a corridor, more preferred. Log-normal spreads `pass_gap_person_sd` 0.25
    and `pass_gap_trial_sd` 0.1 (ASSUMPTION: personal space differs between people).
  * `anticipate_m` 6: how far ahead along their way a shown path makes a person move aside (an
    oncoming pedestrian is avoided from about 4-8 m, the social-to-public distance of Hall 1966);
    log-normal spreads `anticipate_person_sd` 0.2, `anticipate_trial_sd` 0.1 (ASSUMPTION).
  * `hesitate_m` 3.6 and `hesitate_factor` 0.5: a robot closing in within Hall's social distance whose
    intent the person cannot read makes them slow down (walkers facing a crossing robot adapt by
    slowing and prefer to give way to it, Vassallo et al. 2017, Gait & Posture 51; illegible robot
    motion lowers perceived safety, Lichtenthaler, Lorenz & Kirsch 2012). The centre, half speed,
    is an ASSUMPTION (we found no measured figure for how far people slow), and it is a random
    effect: `hesitate_person_sd` 0.12 between people and `hesitate_trial_sd` 0.05 within a person
    (absolute, on the factor; ASSUMPTION). The hesitation metric's threshold
    (`record/hesitation.SLOW_FRACTION`) is fixed apart from all of these.
  * `cue_error` 0.15: the probability that a person ignores the cues shown during one encounter with
    the robot (from when they first see a cue until they have seen none for a while), at their first
    trial: AR intent cues are not always understood or noticed. ASSUMPTION: a round figure, no
    measured comprehension-error rate for these cues was found; `cue_error_person_sd` 0.5 spreads it
    between people on the logit scale (ASSUMPTION).
  * `learning` 0.15: the power-law exponent applied to `reaction_s` and `cue_error` over the session's
    trials: by the ninth trial a reaction time of 1.0 s is down to about 0.72 s, Green's expected-
    hazard figure (ASSUMPTION: the exponent chosen so).

The cue effects a simulated pilot shows follow from these assumptions: they are what the model
assumes people do, not findings about people.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, fields, replace

HALL_SOCIAL_M = 3.6  # Hall (1966): social distance ends here (the metrics' social zone, too)
NEW_PERSON = -1  # `person_seed`: a new person for every trial seed
# a drawn slowdown factor is kept within these (a person neither stops dead nor ignores the robot)
HESITATE_LIMITS = (0.2, 0.9)
SPEED_FACTOR_LIMITS = (0.6, 1.4)  # a drawn walking-speed factor is kept within these (3.6 sd of Bohannon's spread)
INT_FIELDS = ("person_seed", "session_trial")


@dataclass(frozen=True)
class PersonParams:
    fov_deg: float = 110.0
    view_m: float = 8.0
    reaction_s: float = 1.0
    reaction_person_sd: float = 0.25
    reaction_trial_sd: float = 0.1
    speed_person_sd: float = 0.11
    speed_trial_sd: float = 0.04
    pass_gap_m: float = 0.5
    pass_gap_person_sd: float = 0.25
    pass_gap_trial_sd: float = 0.1
    anticipate_m: float = 6.0
    anticipate_person_sd: float = 0.2
    anticipate_trial_sd: float = 0.1
    hesitate_m: float = HALL_SOCIAL_M
    hesitate_factor: float = 0.5
    hesitate_person_sd: float = 0.12
    hesitate_trial_sd: float = 0.05
    cue_error: float = 0.15
    cue_error_person_sd: float = 0.5
    learning: float = 0.15
    person_seed: float = NEW_PERSON  # whole numbers (stored as int): every field is a number, as a sweep gives it
    session_trial: float = 1

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ValueError(f"{f.name} must be a finite number, got {value!r}")
        for name in INT_FIELDS:  # (a sweep's --grid gives floats: 3.0 is person 3)
            value = getattr(self, name)
            if value != int(value):
                raise ValueError(f"{name} must be a whole number, got {value:g}")
            object.__setattr__(self, name, int(value))
        if self.person_seed < NEW_PERSON:
            raise ValueError(
                f"person_seed must be -1 (a new person per trial seed) or a seed >= 0, got {self.person_seed}"
            )
        if self.session_trial < 1:
            raise ValueError(
                f"session_trial must be 1 or more (the trial's position in the session), got {self.session_trial}"
            )
        if not 0 < self.fov_deg <= 360:
            raise ValueError(f"fov_deg must be within (0, 360], got {self.fov_deg:g}")
        for name in ("view_m", "anticipate_m", "hesitate_m"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be positive, got {getattr(self, name):g}")
        for name in ("reaction_s", "pass_gap_m", "learning", *(f.name for f in fields(self) if f.name.endswith("_sd"))):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must not be negative, got {getattr(self, name):g}")
        for name in ("speed_person_sd", "speed_trial_sd"):
            if not getattr(self, name) < 1:
                raise ValueError(f"{name} must be within [0, 1), got {getattr(self, name):g}")
        if not 0 < self.hesitate_factor <= 1:
            raise ValueError(f"hesitate_factor must be within (0, 1], got {self.hesitate_factor:g}")
        if not 0 <= self.cue_error < 1:
            raise ValueError(f"cue_error must be within [0, 1), got {self.cue_error:g}")


@dataclass(frozen=True)
class Individual:
    """One simulated person as they are in one trial: their parameters with every spread drawn
    (`params`, spreads zeroed), their walking-speed factor, and their own random stream for what
    varies within the trial (misreading a cue)."""

    params: PersonParams
    speed_factor: float
    rng: random.Random


def _z(rng: random.Random) -> float:
    return rng.gauss(0.0, 1.0)


def _logit(p: float) -> float:
    return math.log(p / (1.0 - p))


def individual(params: PersonParams, human_id: str, trial_seed: int) -> Individual:
    """The person `params` describe, as they are in this trial. The person draw comes from
    `person_seed` (or, with -1, from the trial seed) and the human's id, so it is the same over all
    of a participant's trials; the trial draw from the trial seed, the person and `session_trial`,
    so it differs between their trials even when a study gives them all one seed. String seeds:
    `random.Random` hashes them the same in every process."""
    p = params
    who = f"seed{trial_seed}" if p.person_seed == NEW_PERSON else f"person{p.person_seed}"
    person = random.Random(f"haven.person:{who}:{human_id}")
    trial = random.Random(f"haven.trial:{trial_seed}:{who}:{p.session_trial}:{human_id}")

    def spread(person_sd: float, trial_sd: float) -> float:  # person and trial normal deviates, scaled
        return person_sd * _z(person) + trial_sd * _z(trial)

    practice = p.session_trial ** (-p.learning)
    lo, hi = SPEED_FACTOR_LIMITS
    speed = min(hi, max(lo, 1.0 + spread(p.speed_person_sd, p.speed_trial_sd)))
    reaction = p.reaction_s * math.exp(spread(p.reaction_person_sd, p.reaction_trial_sd)) * practice
    gap = p.pass_gap_m * math.exp(spread(p.pass_gap_person_sd, p.pass_gap_trial_sd))
    anticipate = p.anticipate_m * math.exp(spread(p.anticipate_person_sd, p.anticipate_trial_sd))
    # (a centre of 1: no slowing)
    lo, hi = min(HESITATE_LIMITS[0], p.hesitate_factor), max(HESITATE_LIMITS[1], p.hesitate_factor)
    hesitate = min(hi, max(lo, p.hesitate_factor + spread(p.hesitate_person_sd, p.hesitate_trial_sd)))
    error = 0.0
    if p.cue_error > 0.0:
        error = 1.0 / (1.0 + math.exp(-(_logit(p.cue_error) + p.cue_error_person_sd * _z(person)))) * practice
    drawn = replace(
        p,
        reaction_s=reaction,
        pass_gap_m=gap,
        anticipate_m=anticipate,
        hesitate_factor=hesitate,
        cue_error=error,
        **{f.name: 0.0 for f in fields(p) if f.name.endswith("_sd")},
    )
    return Individual(drawn, speed, random.Random(f"haven.misread:{trial_seed}:{who}:{p.session_trial}:{human_id}"))
