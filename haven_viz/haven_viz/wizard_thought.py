"""The researcher's thought text (Wizard of Oz) on /haven/wizard_thought: shown in the thought
bubble instead of the robot's own until `until` (simulated time; the robot's own thoughts meanwhile
do not overwrite it), and with `everywhere` whoever is near (not only within `thought_radius_m`).
Published by the web node from the console (latched: a viz that starts late still gets it, and a
hold that is over is simply past)."""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass

MAX_HOLD_S = 3600.0  # a thought held an hour at most


@dataclass(frozen=True)
class WizardThought:
    text: str
    until: float  # simulated time the text is held to
    everywhere: bool = False

    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @staticmethod
    def from_json(text: str) -> WizardThought:
        """ValueError in one line for anything else than {"text": str, "until": number, "everywhere": bool}."""
        try:
            data = json.loads(text)
        except (json.JSONDecodeError, RecursionError):
            raise ValueError("not JSON") from None
        if not isinstance(data, dict) or not isinstance(data.get("text"), str):
            raise ValueError('must be {"text": ..., "until": sim time, "everywhere": true|false}')
        until, everywhere = data.get("until"), data.get("everywhere", False)
        if isinstance(until, bool) or not isinstance(until, (int, float)) or not math.isfinite(until):
            raise ValueError(f"until: must be a number (simulated time), got {str(until)[:40]}")
        if not isinstance(everywhere, bool):
            raise ValueError(f"everywhere: must be true or false, got {str(everywhere)[:40]}")
        return WizardThought(data["text"], float(until), everywhere)
