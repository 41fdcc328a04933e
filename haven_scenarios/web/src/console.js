// The researcher console: the live top-down scene with everyone's tracks, the trial's status and
// controls, the condition's cue toggles (the viz node's parameters, one per installed cue), the event stream,
// Wizard-of-Oz control of the robot (teleop velocity, thought text), and after the trial each
// participant's questionnaire progress with Skip questionnaires. Every intervention is an event.
import { Link, config as readConfig, twist, yawOf } from "./link.js";
import { fit, footprint, disc, rgba } from "./topdown.js";
import { NOT_ASKED } from "./task.js";

const cfg = readConfig();
const state = (window.havenState = { frames: 0, trial: null, toggles: null, events: [], tracks: { robot: [] }, cue: null });
const world = new Map(); // "ns/id" -> marker
const seen = new Set(); // events shown, by source and seq
const cueMarkers = new Map();
let plan = [];

const link = new Link(
  cfg,
  {
    "/haven/world_markers": (m) => applyMarkers(world, m),
    "/haven/ar_markers": (m) => applyMarkers(cueMarkers, m),
    "/odom": (m) => track("robot", m.pose.pose),
    "/humans": (m) => m.poses.forEach((p, i) => track(cfg.humans[i], p)),
    "/plan": (m) => (plan = m.poses.map((p) => p.pose.position)),
    "/haven/trial_status": (m) => {
      state.trial = JSON.parse(m.data);
      showStatus();
    },
    "/haven/participants": (m) => {
      state.participants = JSON.parse(m.data);
      showParticipants();
      showStatus();
    },
    "/haven/cue_state": (m) => {
      state.cue = JSON.parse(m.data);
      state.toggles = state.cue.toggles;
      showToggles();
      showThought();
    },
    "/haven/thought": (m) => {
      state.thought = m.data;
      showThought();
    },
    "/haven/events": (m) => {
      const e = JSON.parse(m.data);
      const key = `${e.source}/${e.seq}`; // the log is sent again to each console that opens: once each
      if (seen.has(key)) return;
      seen.add(key);
      state.events.push(e);
      if (e.type === "questionnaire_answered") (answeredBy[e.by] ||= []).push(e.questionnaire);
      if (e.type === "intervention" && e.action === "skip_questionnaires") state.skipped = true;
      showQuestionnaires();
      const line = document.createElement("div");
      const { stamp, source, type, seq, ...rest } = e;
      line.textContent = `${stamp.toFixed(1)}  ${source}  ${type}  ${Object.entries(rest).map(([k, v]) => `${k}=${JSON.stringify(v)}`).join(" ")}`;
      const list = document.getElementById("events");
      list.prepend(line);
      while (list.childElementCount > 300) list.lastChild.remove();
    },
  },
  state,
);

function applyMarkers(store, array) {
  for (const m of array.markers) {
    if (m.action === 3) store.clear();
    else if (m.action === 2) store.delete(`${m.ns}/${m.id}`);
    else store.set(`${m.ns}/${m.id}`, m);
  }
}

const lastPose = {};
function track(id, p) {
  const pose = { x: p.position.x, y: p.position.y, yaw: yawOf(p.orientation) };
  lastPose[id] = pose;
  const t = state.tracks[id] || (state.tracks[id] = []);
  const prev = t[t.length - 1];
  if (!prev || Math.hypot(prev.x - pose.x, prev.y - pose.y) > 0.05) t.push(pose);
}

// -- status, task progress, who -----------------------------------------------------------------------
document.getElementById("who").textContent = `participant ${cfg.participant} · scenario ${cfg.scenario}${cfg.session ? " · " + cfg.session : ""}`;
function showStatus() {
  const t = state.trial;
  const away = awayWhilePaused();
  document.getElementById("status-line").textContent = !t
    ? "connecting…"
    : away && t.state === "running"
      ? `trial paused: waiting for ${away.join(", ")}`
      : `trial ${t.state}${t.end_reason ? ": " + t.end_reason : ""}`;
  document.getElementById("tasks").textContent = !t
    ? ""
    : Object.entries(t.humans)
        .map(([id, h]) => `${id}: ${h.done ? "done" : t.kind === "hallway" ? `room ${h.rooms_done} of ${h.rooms.length}` : `gems ${h.gems_done} of ${h.gems_total}${h.dwell !== null ? " (in a gem)" : ""}`}`)
        .join(" · ");
  document.getElementById("start").disabled = !t || t.state !== "held";
  const over = !t || t.state === "ended";
  for (const el of document.querySelectorAll("#stop, #abort, #toggles input, #drive-pad button, #thought-form *")) el.disabled = over;
  showQuestionnaires();
}

// -- who is connected: each participant's page, what it reports (study/presence.py) -------------------------
function showParticipants() {
  const p = state.participants;
  const table = document.getElementById("participants");
  table.replaceChildren();
  const row = (cells, head = false) => {
    const tr = table.insertRow();
    for (const c of cells) {
      const cell = document.createElement(head ? "th" : "td");
      cell.textContent = c;
      tr.appendChild(cell);
    }
    return tr;
  };
  row(["", "connection", "fps", "key→view", "last input"], true);
  const num = (v, unit) => (v === null || v === undefined ? "–" : `${v}${unit}`);
  for (const [id, r] of Object.entries(p.participants)) {
    const connection = r.state === "away" ? `away ${r.away_s} s` : r.state;
    const stale = r.report_age_s !== null && r.report_age_s > 5; // its page stopped reporting
    const tr = row([id, connection, num(r.fps, ""), num(r.latency_ms, " ms"), num(r.input_age_s, " s ago")]);
    tr.className = r.state === "away" ? "away" : stale ? "stale" : "";
  }
  if (p.paused) row([`paused: waiting for ${awayWhilePaused().join(", ")}`]).cells[0].colSpan = 5;
}
function awayWhilePaused() {
  const p = state.participants;
  return p && p.paused ? Object.keys(p.participants).filter((id) => p.participants[id].state === "away") : null;
}

// -- the questionnaires after the trial: each participant's progress, and Skip (haven run then stops) --
const answeredBy = {}; // human -> the questionnaires they answered
function showQuestionnaires() {
  const names = cfg.questionnaires.map((q) => q.name);
  const t = state.trial;
  const asked = names.length > 0 && !!t && t.state === "ended" && !NOT_ASKED.includes(t.end_reason);
  const progress = Object.fromEntries(cfg.teleoperated.map((h) => [h, (answeredBy[h] || []).length]));
  const lines = cfg.teleoperated.map((h) => (progress[h] >= names.length ? `${h}: questionnaires done` : `${h}: questionnaire ${progress[h] + 1} of ${names.length}`));
  state.questionnaires = asked ? lines : [];
  const el = document.getElementById("questionnaires");
  if (!names.length) el.textContent = "";
  else if (!asked) el.textContent = `after the trial: ${names.join(", ")}`;
  else el.textContent = state.skipped ? "questionnaires skipped" : lines.join(" · ");
  document.getElementById("skip-questionnaires").hidden = !asked || !!state.skipped || Object.values(progress).every((k) => k >= names.length);
}
document.getElementById("skip-questionnaires").addEventListener("click", () => link.publish("/haven/skip_questionnaires", { data: "skip" }));

// What the participants' bubble says now (the researcher's text while it is held), and whether a
// participant sees it (the bubble shows within 3 m, or at any distance when the researcher chose).
function showThought() {
  const shown = state.cue && state.cue.thought;
  document.getElementById("thought-now").textContent = shown
    ? `bubble shows: "${shown}"`
    : state.thought
      ? `robot thinks: "${state.thought}" (not shown: ${state.toggles && state.toggles.thought_bubble === false ? "the thought bubble is off in this condition: switch it on to show text" : "nobody near"})`
      : "robot thinks: nothing yet";
}
showStatus();
showThought();

// -- the condition: one toggle per cue /haven/cue_state names (any installed cue), set as the viz node's parameters --
const togglesEl = document.getElementById("toggles");
function showToggles() {
  for (const [cue, on] of Object.entries(state.toggles || {})) {
    let input = document.getElementById(`cue-${cue}`);
    if (!input) {
      const label = document.createElement("label");
      label.innerHTML = `<input type="checkbox" id="cue-${cue}"> ${cue.replaceAll("_", " ")}`;
      togglesEl.append(label);
      input = label.querySelector("input");
      input.disabled = !state.trial || state.trial.state === "ended";
      input.addEventListener("change", (e) => {
        link.setParameters([{ name: `/viz.${cue}`, value: e.target.checked, type: undefined }]);
      });
    }
    input.checked = !!on;
  }
}

// -- trial control ----------------------------------------------------------------------------------
for (const command of ["start", "stop", "abort"]) {
  document.getElementById(command).addEventListener("click", () => link.publish("/haven/trial_control", { data: command }));
}

// -- Wizard of Oz ------------------------------------------------------------------------------------
let drive = [0, 0];
const DRIVE = { v: 0.3, w: 0.8 };
setInterval(() => {
  if (drive[0] || drive[1] || state.driving) {
    link.publish("/cmd_vel_teleop", twist(drive[0] * DRIVE.v, 0, drive[1] * DRIVE.w));
    state.driving = !!(drive[0] || drive[1]);
  }
}, 50);
for (const b of document.querySelectorAll("[data-drive]")) {
  const d = b.dataset.drive.split(",").map(Number);
  b.addEventListener("pointerdown", () => (drive = d));
  for (const ev of ["pointerup", "pointerleave"]) b.addEventListener(ev, () => (drive = [0, 0]));
}
const KEYS = { KeyI: [1, 0], KeyK: [-1, 0], KeyJ: [0, 1], KeyL: [0, -1] };
window.addEventListener("keydown", (e) => {
  if (e.target.tagName !== "INPUT" && KEYS[e.code]) drive = KEYS[e.code];
});
window.addEventListener("keyup", (e) => {
  if (KEYS[e.code]) drive = [0, 0];
});
document.getElementById("thought-text").maxLength = cfg.thought_max_chars; // the study log's limit
document.getElementById("thought-form").addEventListener("submit", (e) => {
  e.preventDefault();
  const sent = { text: document.getElementById("thought-text").value, hold_s: Number(document.getElementById("thought-hold").value), everywhere: document.getElementById("thought-everywhere").checked };
  link.publish("/haven/wizard_thought", { data: JSON.stringify(sent) });
});

// The robot's footprint at real size, turned with its heading: its circle or its polygon.
function robotOutline(ctx, p, { s, X, Y }) {
  const fp = cfg.robot.footprint;
  if (!fp.polygon.length) return ctx.arc(X(p.x), Y(p.y), fp.radius_m * s, 0, 2 * Math.PI);
  const c = Math.cos(p.yaw), n = Math.sin(p.yaw);
  fp.polygon.forEach(([x, y], i) => {
    const wx = p.x + c * x - n * y, wy = p.y + n * x + c * y;
    if (i) ctx.lineTo(X(wx), Y(wy));
    else ctx.moveTo(X(wx), Y(wy));
  });
  ctx.closePath();
}

// -- the top-down scene --------------------------------------------------------------------------------
const canvas = document.getElementById("scene");
const COLORS = { robot: "#222", me: "#1660e8" };
function draw() {
  canvas.width = canvas.clientWidth;
  canvas.height = canvas.clientHeight;
  const ctx = canvas.getContext("2d");
  const t = fit(canvas, cfg.bounds, 0.8);
  const { s, X, Y } = t;
  for (const m of [...world.values(), ...cueMarkers.values()]) {
    const p = m.pose.position;
    if (m.type === 11) footprint(ctx, m, t);
    else if (m.type === 9) {
      if (m.ns === "human_names") continue;
      ctx.font = m.ns === "rooms" ? "bold 16px sans-serif" : "13px sans-serif";
      ctx.fillStyle = rgba(m.color, 1);
      ctx.fillText(m.text, X(p.x) + (m.ns === "rooms" ? -6 : 10), Y(p.y) - (m.ns === "rooms" ? 0 : 12));
    } else if (m.ns !== "robot" && m.ns !== "humans") disc(ctx, m, t);
  }
  if (plan.length) {
    ctx.strokeStyle = "rgba(230,180,0,0.9)";
    ctx.lineWidth = 2;
    ctx.beginPath();
    plan.forEach((p, i) => (i ? ctx.lineTo(X(p.x), Y(p.y)) : ctx.moveTo(X(p.x), Y(p.y))));
    ctx.stroke();
  }
  for (const [id, track] of Object.entries(state.tracks)) {
    const color = id === "robot" ? COLORS.robot : cfg.humans.indexOf(id) === 0 ? COLORS.me : "#c33";
    ctx.strokeStyle = color;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    track.forEach((p, i) => (i ? ctx.lineTo(X(p.x), Y(p.y)) : ctx.moveTo(X(p.x), Y(p.y))));
    ctx.stroke();
    const p = lastPose[id];
    if (!p) continue;
    ctx.fillStyle = color;
    ctx.beginPath();
    if (id === "robot") robotOutline(ctx, p, t);
    else ctx.arc(X(p.x), Y(p.y), cfg.human_body.radius_m * s, 0, 2 * Math.PI);
    ctx.fill();
    ctx.strokeStyle = "#fff";
    ctx.beginPath();
    ctx.moveTo(X(p.x), Y(p.y));
    ctx.lineTo(X(p.x + 0.35 * Math.cos(p.yaw)), Y(p.y + 0.35 * Math.sin(p.yaw)));
    ctx.stroke();
    ctx.fillStyle = "#000";
    ctx.font = "12px sans-serif";
    ctx.fillText(id, X(p.x) + 8, Y(p.y) + 16);
  }
  state.frames++;
  requestAnimationFrame(draw);
}
requestAnimationFrame(draw);
