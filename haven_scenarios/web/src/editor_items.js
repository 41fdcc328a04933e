// The world editor's items: every place in the world tree (the YAML-equivalent JSON the loader
// reads) that holds points, listed so drawing, picking, moving and highlighting treat them alike.
// The tree is the only state; nothing here checks it (the server runs the real loader).

// [kind, index, points] for each item: `points` are the tree's own [x, y] arrays (moved in place).
export function items(world) {
  const out = [];
  const add = (kind, list, pts) => (list || []).forEach((it, i) => out.push({ kind, index: i, item: it, points: pts(it) }));
  add("walls", world.walls, (w) => w.segment || w.polygon || []);
  add("obstacles", world.obstacles, (w) => w.segment || w.polygon || []);
  add("obstructions", world.obstructions, (w) => w.segment || w.polygon || []);
  add("rooms", world.rooms, (r) => [r.centre]);
  add("hallways", world.hallways, (h) => h.centreline);
  add("gems", world.gems, (g) => [g.position]);
  add("humans", world.humans, (h) => [h.start]);
  if (world.charging_base) out.push({ kind: "charging_base", index: -1, item: world.charging_base, points: [world.charging_base.position] });
  if (world.robot) out.push({ kind: "robot", index: -1, item: world.robot, points: [world.robot.start] });
  return out;
}

// The item a loader key names ("walls[2].segment" -> walls item 2; "robot.start" -> the robot).
export function named(world, key) {
  const m = /^(\w+)(?:\[(\d+)\])?/.exec(key || "");
  if (!m) return null;
  return items(world).find((it) => it.kind === m[1] && (m[2] === undefined || it.index === Number(m[2]))) || null;
}

function segmentDistance(p, a, b) {
  const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
  const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy || 1)));
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

function inside(p, poly) {
  let hit = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const [a, b] = [poly[i], poly[j]];
    if (a[1] > p[1] !== b[1] > p[1] && p[0] < ((b[0] - a[0]) * (p[1] - a[1])) / (b[1] - a[1]) + a[0]) hit = !hit;
  }
  return hit;
}

// How far `p` is from an item (0 inside a polygon).
export function distance(p, it) {
  const pts = it.points;
  if (pts.length === 1) return Math.hypot(p[0] - pts[0][0], p[1] - pts[0][1]);
  if (it.item.polygon && inside(p, pts)) return 0;
  let best = Infinity;
  const closed = it.item.polygon ? pts.length : pts.length - 1;
  for (let i = 0; i < closed; i++) best = Math.min(best, segmentDistance(p, pts[i], pts[(i + 1) % pts.length]));
  return best;
}

// The item nearest `p` within `reach` metres (points first: a room inside a room's walls wins).
export function pick(world, p, reach) {
  let best = null;
  for (const it of items(world)) {
    const d = distance(p, it) - (it.points.length === 1 ? reach / 2 : 0);
    if (d <= reach && (!best || d < best.d)) best = { d, it };
  }
  return best && best.it;
}

export function remove(world, it) {
  if (it.kind === "charging_base") delete world.charging_base;
  else if (it.kind !== "robot") world[it.kind].splice(it.index, 1); // (a world always has its robot start)
}

// The wall, furniture and door corners, to snap a new point onto.
export function corners(world) {
  return items(world)
    .filter((it) => ["walls", "obstacles", "obstructions"].includes(it.kind))
    .flatMap((it) => it.points);
}

// A free name: `prefix` + the smallest number not yet used in `taken`.
export function freeName(prefix, taken) {
  for (let n = 1; ; n++) if (!taken.includes(prefix + n)) return prefix + n;
}
