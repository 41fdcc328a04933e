// What the participant is told: the task line (their progress) and the prompts before and after
// the trial, from the latched /haven/trial_status (the questionnaires after it: questionnaire.js).
export function taskLine(t, me) {
  if (!t || !t.humans[me] || t.state === "ended") return "";
  const h = t.humans[me];
  if (h.done) return "Your task is done: wait for the trial to end";
  if (t.kind === "hallway") {
    return h.next_room ? `Go to room ${h.next_room}  (${h.rooms_done + 1} of ${h.rooms.length})` : "";
  }
  const line = `Gems: ${h.gems_done} of ${h.gems_total}`;
  return h.dwell !== null ? `${line}  ·  standing in a gem: stay there` : line;
}

// Trials that end so run again (or not at all): nothing is asked about them.
export const NOT_ASKED = ["aborted", "interrupted"];

const ENDINGS = {
  completed: "Everyone finished the task.",
  timeout: "The time for this trial is up.",
  contact: "The trial ended because you touched the robot.",
  battery_empty: "The robot's battery ran out.",
  stopped: "The researcher ended the trial.",
  aborted: "The researcher called the trial off.",
  interrupted: "The trial was stopped.",
};

export function promptFor(t, cfg, pressedStart, skipped) {
  if (!t || t.state === "waiting" || t.state === "held") {
    const held = t && t.state === "held";
    return {
      title: "Welcome",
      text: cfg.instructions,
      small: `${cfg.controls}.` + (pressedStart ? " Waiting for the trial to start…" : held ? "" : " Connecting to the trial…"),
      start: held && !pressedStart,
    };
  }
  if (t.state === "ended") {
    const answered = cfg.questionnaires.length && !NOT_ASKED.includes(t.end_reason) && !skipped ? " Thank you for your answers!" : " Thank you!";
    const small = cfg.next_url ? "Taking you on…" : "You can close this page.";
    return { title: "Trial over", text: `${ENDINGS[t.end_reason] || ""}${answered}`, small, start: false };
  }
  return null;
}
