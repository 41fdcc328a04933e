// The world editor (`haven edit`): a plan from above in metres, tools to draw walls and furniture
// and to place rooms, hallway lines, gems, the charging base and the starts. The world tree (what
// the YAML file will hold) is the only state; after every change it goes to the server, which runs
// the real loader and answers OK or the loader's one line (web/editor_server.py): no second
// validator here. window.havenEditor is for the tests (the tree, the verdict, metres <-> pixels).
import { drawPlan } from "./editor_draw.js";
import { corners, freeName, items, named, pick, remove } from "./editor_items.js";

const cfg = JSON.parse(document.getElementById("config").textContent);
const SNAP_M = 0.05; // new points land on a 5 cm grid ...
const SNAP_PX = 10; // ... or on a wall's corner within 10 pixels
const CHECK_DELAY_MS = 250; // the loader is asked once the drawing pauses
const canvas = document.getElementById("plan");
const ctx = canvas.getContext("2d");
const $ = (id) => document.getElementById(id);

let world = structuredClone(cfg.world);
const undoStack = [];
const view = { scale: 40, x0: -1, y0: -1 }; // pixels per metre; the metres at the lower-left corner
const state = { tool: "wall", pending: [], selected: null, drag: null, verdict: null, checks: 0, saved: [], overwrite: false, background: null };

const toMetres = (px, py) => [view.x0 + px / view.scale, view.y0 + (canvas.height - py) / view.scale];
const toPixels = (x, y) => [(x - view.x0) * view.scale, canvas.height - (y - view.y0) * view.scale];
const round = (v) => Math.round(v / SNAP_M) * SNAP_M;
const num = (id) => Number($(id).value);

function snapped(px, py) {
  for (const c of corners(world)) {
    const [cx, cy] = toPixels(c[0], c[1]);
    if (Math.hypot(cx - px, cy - py) <= SNAP_PX) return [c[0], c[1]];
  }
  const [x, y] = toMetres(px, py);
  return [+round(x).toFixed(2), +round(y).toFixed(2)];
}

function change(edit) {
  undoStack.push(JSON.stringify(world));
  edit();
  state.overwrite = false;
  changed();
}

let checkTimer = null;
function changed() {
  draw();
  clearTimeout(checkTimer);
  checkTimer = setTimeout(check, CHECK_DELAY_MS);
}

async function post(path, body, type = "application/json") {
  const r = await fetch(path, { method: "POST", headers: { "Content-Type": type }, body });
  return [r.status, await r.json().catch(() => ({ ok: false, error: `the editor answered ${r.status}` }))];
}

async function check() {
  const sent = JSON.stringify(world);
  const [, answer] = await post("/edit/check", sent);
  if (sent !== JSON.stringify(world)) return; // changed meanwhile: a newer check follows
  state.verdict = answer;
  state.checkedWorld = sent;
  state.checks += 1;
  say(answer.ok ? `OK: ${answer.summary}` : `Not valid yet: ${answer.error}`, answer.ok);
  draw();
}

function say(text, ok) {
  $("status").textContent = text;
  $("status").className = ok ? "ok" : "bad";
}

const place = {
  room: (p) => world.rooms.push({ name: $("label").value.trim() || freeName("room", world.rooms.map((r) => r.name)), centre: p }),
  gem: (p) => world.gems.push({ id: freeName("g", world.gems.map((g) => g.id)), owner: $("owner").value, position: p }),
  base: (p) => (world.charging_base = { position: p, radius: 0.5 }),
  robot: (p) => (world.robot = { start: [...p, +((num("heading") * Math.PI) / 180).toFixed(4)] }),
  person: (p) => world.humans.push({ id: $("person").value.trim() || freeName("h", world.humans.map((h) => h.id)), start: [...p, +((num("heading") * Math.PI) / 180).toFixed(4)] }),
};
const LISTS = ["walls", "obstacles", "rooms", "hallways", "gems", "humans", "obstructions"];

function click(p) {
  for (const key of LISTS) world[key] = world[key] || [];
  if (place[state.tool]) return change(() => place[state.tool](p));
  if (state.tool === "hallway") return state.pending.push(p), draw();
  if (state.tool !== "wall" && state.tool !== "door") return;
  if (!state.pending.length) return state.pending.push(p), draw();
  const [a] = state.pending;
  state.pending = [];
  if (a[0] === p[0] && a[1] === p[1]) return draw();
  if (state.tool === "wall") return change(() => world.walls.push({ segment: [a, p], thickness: num("thickness") }));
  const door = { id: freeName("door", world.obstructions.map((o) => o.id)), segment: [a, p], thickness: num("thickness") };
  if ($("opens").value.trim()) door.removed_when_human_reaches = $("opens").value.trim();
  change(() => world.obstructions.push(door));
}

function finishHallway() {
  const line = state.pending;
  state.pending = [];
  if (line.length < 2) return draw();
  const name = $("label").value.trim() || freeName("hall", (world.hallways || []).map((h) => h.name));
  change(() => (world.hallways = [...(world.hallways || []), { name, centreline: line, width: num("width") }]));
}

function obstacle(a, b) {
  const [x0, x1, y0, y1] = [Math.min(a[0], b[0]), Math.max(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[1], b[1])];
  if (x1 - x0 < SNAP_M || y1 - y0 < SNAP_M) return;
  const it = { polygon: [[x0, y0], [x1, y0], [x1, y1], [x0, y1]] };
  if ($("height").value) it.height = num("height");
  change(() => (world.obstacles = [...(world.obstacles || []), it]));
}

canvas.addEventListener("mousedown", (e) => {
  const p = snapped(e.offsetX, e.offsetY);
  if (state.tool === "pan" || e.button === 1) state.drag = { pan: [e.offsetX, e.offsetY, view.x0, view.y0] };
  else if (state.tool === "obstacle") state.drag = { from: p, to: p };
  else if (state.tool === "select") {
    const it = pick(world, toMetres(e.offsetX, e.offsetY), SNAP_PX / view.scale);
    state.selected = it && { kind: it.kind, index: it.index };
    if (it) undoStack.push(JSON.stringify(world));
    state.drag = it && { move: p, moved: false };
    draw();
  } else click(p);
});
canvas.addEventListener("mousemove", (e) => {
  const d = state.drag;
  if (!d) {
    state.hover = state.pending.length ? snapped(e.offsetX, e.offsetY) : null; // where the next click lands
    return state.hover && draw();
  }
  if (d.pan) {
    view.x0 = d.pan[2] - (e.offsetX - d.pan[0]) / view.scale;
    view.y0 = d.pan[3] + (e.offsetY - d.pan[1]) / view.scale;
  } else if (d.from) d.to = snapped(e.offsetX, e.offsetY);
  else if (d.move) {
    const p = snapped(e.offsetX, e.offsetY);
    const [dx, dy] = [p[0] - d.move[0], p[1] - d.move[1]];
    for (const q of selectedItem().points) [q[0], q[1]] = [+(q[0] + dx).toFixed(3), +(q[1] + dy).toFixed(3)];
    d.move = p;
    d.moved = d.moved || dx !== 0 || dy !== 0;
  }
  draw();
});
window.addEventListener("mouseup", () => {
  const d = state.drag;
  state.drag = null;
  if (d && d.from) obstacle(d.from, d.to);
  else if (d && d.move && d.moved) changed();
  else if (d && d.move) undoStack.pop();
});
canvas.addEventListener("wheel", (e) => {
  e.preventDefault();
  const [x, y] = toMetres(e.offsetX, e.offsetY);
  view.scale = Math.min(400, Math.max(4, view.scale * (e.deltaY < 0 ? 1.2 : 1 / 1.2)));
  view.x0 = x - e.offsetX / view.scale;
  view.y0 = y - (canvas.height - e.offsetY) / view.scale;
  draw();
});

const selectedItem = () => state.selected && items(world).find((it) => it.kind === state.selected.kind && it.index === state.selected.index);

function deleteSelected() {
  const it = selectedItem();
  if (!it) return;
  state.selected = null;
  change(() => remove(world, it));
}

function undo() {
  if (!undoStack.length) return;
  world = JSON.parse(undoStack.pop());
  state.selected = null;
  $("name").value = world.name;
  changed();
}

window.addEventListener("keydown", (e) => {
  if (e.target instanceof HTMLInputElement) return;
  if (e.key === "Enter") finishHallway();
  else if (e.key === "Escape") (state.pending = []), draw();
  else if (e.key === "Delete" || e.key === "Backspace") deleteSelected();
  else if (e.key === "z" && (e.ctrlKey || e.metaKey)) undo();
});

function useTool(tool) {
  if (state.tool === "hallway" && tool !== "hallway") finishHallway();
  state.tool = tool;
  state.pending = [];
  for (const b of document.querySelectorAll("#toolbox button")) b.classList.toggle("active", b.dataset.tool === tool);
  draw();
}
for (const b of document.querySelectorAll("#toolbox button")) b.addEventListener("click", () => useTool(b.dataset.tool));
$("undo").addEventListener("click", undo);
$("delete").addEventListener("click", deleteSelected);
$("name").value = world.name;
$("name").addEventListener("change", () => change(() => (world.name = $("name").value.trim())));

async function save() {
  const [status, answer] = await post("/edit/save", JSON.stringify({ world, task: $("task").value, overwrite: state.overwrite }));
  state.overwrite = status === 409; // the page said so: the next Save replaces them
  if (answer.ok) state.saved = answer.saved;
  say(answer.ok ? `Saved ${answer.saved.join(" and ")}` : status === 409 ? `Already saved as ${answer.exists.join(", ")}: press Save again to replace` : `Not saved: ${answer.error}`, answer.ok);
}
$("save").addEventListener("click", save);

function imageFile() {
  const file = $("image").files[0];
  if (!file) say("Choose a map image first (PNG, JPEG or a ROS map's PGM)", false);
  return file;
}
$("as-background").addEventListener("click", async () => {
  const file = imageFile();
  if (!file) return;
  // The browser draws a PNG or JPEG itself; a PGM (a ROS map's image) comes back from the editor as a PNG.
  const bitmap = await createImageBitmap(file).catch(async () => {
    const r = await fetch("/edit/image", { method: "POST", headers: { "Content-Type": "application/octet-stream" }, body: file });
    return r.ok ? createImageBitmap(await r.blob()) : null;
  });
  if (!bitmap) return say("The image cannot be read: a PNG, JPEG or a ROS map's PGM", false);
  state.background = { bitmap, resolution: num("resolution"), x: num("ox"), y: num("oy") };
  draw();
});
$("as-walls").addEventListener("click", async () => {
  const file = imageFile();
  if (!file) return;
  const query = new URLSearchParams({ resolution: $("resolution").value, x: $("ox").value, y: $("oy").value });
  const [, answer] = await post(`/edit/walls?${query}`, file, file.type);
  if (!answer.walls) return say(`The image gave no walls: ${answer.error}`, false);
  change(() => (world.walls = [...(world.walls || []), ...answer.walls.map((polygon) => ({ polygon }))]));
});

function draw() {
  canvas.width = canvas.clientWidth;
  canvas.height = canvas.clientHeight;
  const bad = state.verdict && !state.verdict.ok ? named(world, state.verdict.key) : null;
  drawPlan(ctx, { world, view, toPixels, toMetres, background: state.background, selected: selectedItem(), bad, pending: state.pending, hover: state.hover, drag: state.drag });
}
window.addEventListener("resize", draw);

window.havenEditor = {
  world: () => structuredClone(world),
  get verdict() { return state.verdict; },
  get checks() { return state.checks; },
  get checkedWorld() { return state.checkedWorld; }, // the world the verdict is about (JSON)
  get saved() { return state.saved; },
  get background() { const b = state.background; return b && { width: b.bitmap.width, height: b.bitmap.height, resolution: b.resolution, x: b.x, y: b.y }; },
  // where a point in metres is on the page (for the tests' mouse)
  toPage: (x, y) => { const r = canvas.getBoundingClientRect(); const [px, py] = toPixels(x, y); return [r.left + px, r.top + py]; },
  fit: (x0, y0, x1, y1) => { view.scale = Math.min(canvas.clientWidth / (x1 - x0), canvas.clientHeight / (y1 - y0)); view.x0 = x0; view.y0 = y0; draw(); },
};
useTool("wall");
const all = items(world).flatMap((it) => it.points);
if (all.length) {
  const xs = all.map((p) => p[0]), ys = all.map((p) => p[1]);
  window.havenEditor.fit(Math.min(...xs) - 1, Math.min(...ys) - 1, Math.max(...xs) + 1, Math.max(...ys) + 1);
}
check();
