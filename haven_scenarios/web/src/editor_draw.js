// The world editor's plan: a metre grid, the map image under it, and the world's items drawn from
// above in the colours `haven world show` uses (walls dark, furniture brown, hallway lines purple,
// the robot blue, people red); the selected item outlined blue, the one the loader names red.
const COLOURS = { walls: "#333", obstacles: "#8d6e63", obstructions: "#ff9800", rooms: "#2e7d32", hallways: "#8e44ad", robot: "#1f77b4", humans: "#d62728", charging_base: "#f9a825" };
const GEM = { robot: "#1f77b4", human: "#d62728" };

function grid(ctx, { view, toPixels, toMetres }) {
  const [w, h] = [ctx.canvas.width, ctx.canvas.height];
  const [x0, y0] = toMetres(0, h);
  const [x1, y1] = toMetres(w, 0);
  const step = view.scale >= 30 ? 1 : view.scale >= 8 ? 5 : 10; // metres between lines: labels stay readable
  ctx.lineWidth = 1;
  ctx.font = "11px system-ui";
  ctx.fillStyle = "#777";
  for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
    const [px] = toPixels(x, 0);
    ctx.strokeStyle = x === 0 ? "#999" : "#e3e3e3";
    ctx.beginPath(), ctx.moveTo(px, 0), ctx.lineTo(px, h), ctx.stroke();
    ctx.fillText(`${x} m`, px + 2, h - 4);
  }
  for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
    const [, py] = toPixels(0, y);
    ctx.strokeStyle = y === 0 ? "#999" : "#e3e3e3";
    ctx.beginPath(), ctx.moveTo(0, py), ctx.lineTo(w, py), ctx.stroke();
    ctx.fillText(`${y} m`, 2, py - 2);
  }
}

function path(ctx, pts, toPixels, closed) {
  ctx.beginPath();
  pts.forEach((p, i) => (i ? ctx.lineTo : ctx.moveTo).call(ctx, ...toPixels(p[0], p[1])));
  if (closed) ctx.closePath();
}

function shape(ctx, it, scene, colour) {
  const { toPixels, view } = scene;
  if (it.segment) {
    path(ctx, it.segment, toPixels, false);
    ctx.strokeStyle = colour;
    ctx.lineWidth = Math.max(2, (it.thickness || 0.1) * view.scale);
    ctx.lineCap = "butt";
    return ctx.stroke();
  }
  if (!it.polygon || it.polygon.length < 2) return;
  path(ctx, it.polygon, toPixels, true);
  ctx.fillStyle = colour;
  ctx.fill();
}

function pose(ctx, start, scene, colour, label) {
  const [px, py] = scene.toPixels(start[0], start[1]);
  const yaw = start[2] || 0;
  const r = Math.max(6, 0.2 * scene.view.scale);
  ctx.fillStyle = colour;
  ctx.beginPath(), ctx.arc(px, py, r, 0, 2 * Math.PI), ctx.fill();
  ctx.strokeStyle = "#fff";
  ctx.lineWidth = 2;
  ctx.beginPath(), ctx.moveTo(px, py), ctx.lineTo(px + r * Math.cos(yaw), py - r * Math.sin(yaw)), ctx.stroke();
  ctx.fillStyle = colour;
  ctx.fillText(label, px + r + 3, py - r);
}

function spot(ctx, p, scene, colour, radius, label) {
  const [px, py] = scene.toPixels(p[0], p[1]);
  const r = Math.max(4, radius * scene.view.scale);
  ctx.fillStyle = colour;
  ctx.globalAlpha = radius > 0.2 ? 0.6 : 1; // (a gem's or the base's area: the plan shows through)
  ctx.beginPath(), ctx.arc(px, py, r, 0, 2 * Math.PI), ctx.fill();
  ctx.globalAlpha = 1;
  if (label) ctx.fillText(label, px + r + 3, py - 4);
}

function hallway(ctx, h, scene) {
  path(ctx, h.centreline, scene.toPixels, false);
  ctx.strokeStyle = "rgba(142, 68, 173, 0.15)";
  ctx.lineWidth = h.width * scene.view.scale;
  ctx.lineCap = "round";
  ctx.stroke();
  ctx.strokeStyle = COLOURS.hallways;
  ctx.lineWidth = 2;
  ctx.setLineDash([8, 6]);
  ctx.stroke();
  ctx.setLineDash([]);
  const [px, py] = scene.toPixels(...h.centreline[0]);
  ctx.fillStyle = COLOURS.hallways;
  ctx.fillText(`hallway ${h.name}`, px + 4, py + 14);
}

function items(ctx, scene) {
  const w = scene.world;
  ctx.font = "13px system-ui";
  (w.hallways || []).forEach((h) => hallway(ctx, h, scene));
  (w.walls || []).forEach((it) => shape(ctx, it, scene, COLOURS.walls));
  (w.obstacles || []).forEach((it) => shape(ctx, it, scene, COLOURS.obstacles));
  (w.obstructions || []).forEach((it) => shape(ctx, it, scene, COLOURS.obstructions));
  (w.rooms || []).forEach((r) => spot(ctx, r.centre, scene, COLOURS.rooms, 0.12, `room ${r.name}`));
  (w.gems || []).forEach((g) => spot(ctx, g.position, scene, GEM[g.owner] || "#555", g.radius || 0.3, `gem ${g.id}`));
  if (w.charging_base) spot(ctx, w.charging_base.position, scene, COLOURS.charging_base, w.charging_base.radius || 0.5, "charging base");
  (w.humans || []).forEach((h) => pose(ctx, h.start, scene, COLOURS.humans, `person ${h.id}`));
  if (w.robot && w.robot.start) pose(ctx, w.robot.start, scene, COLOURS.robot, "robot");
}

function outline(ctx, it, scene, colour) {
  if (!it) return;
  ctx.strokeStyle = colour;
  ctx.lineWidth = 3;
  if (it.points.length === 1) {
    const [px, py] = scene.toPixels(...it.points[0]);
    ctx.beginPath(), ctx.arc(px, py, 14, 0, 2 * Math.PI), ctx.stroke();
    return;
  }
  path(ctx, it.points, scene.toPixels, !!it.item.polygon);
  ctx.stroke();
}

function drafts(ctx, scene) {
  ctx.strokeStyle = "#1660e8";
  ctx.fillStyle = "#1660e8";
  ctx.lineWidth = 2;
  if (scene.pending.length) {
    path(ctx, scene.pending, scene.toPixels, false);
    ctx.stroke();
    for (const p of scene.pending) spot(ctx, p, scene, "#1660e8", 0, "");
    if (scene.hover) {
      ctx.setLineDash([6, 4]);
      path(ctx, [scene.pending[scene.pending.length - 1], scene.hover], scene.toPixels, false);
      ctx.stroke();
      ctx.setLineDash([]);
      const length = Math.hypot(scene.hover[0] - scene.pending[scene.pending.length - 1][0], scene.hover[1] - scene.pending[scene.pending.length - 1][1]);
      ctx.fillText(`${length.toFixed(2)} m`, ...scene.toPixels(...scene.hover).map((v) => v + 10));
    }
  }
  const d = scene.drag;
  if (d && d.from) {
    const [ax, ay] = scene.toPixels(...d.from);
    const [bx, by] = scene.toPixels(...d.to);
    ctx.strokeRect(Math.min(ax, bx), Math.min(ay, by), Math.abs(bx - ax), Math.abs(by - ay));
  }
}

// Everything, back to front.
export function drawPlan(ctx, scene) {
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, ctx.canvas.width, ctx.canvas.height);
  const bg = scene.background;
  if (bg) {
    const [px, py] = scene.toPixels(bg.x, bg.y + bg.bitmap.height * bg.resolution);
    const s = bg.resolution * scene.view.scale;
    ctx.globalAlpha = 0.5;
    ctx.drawImage(bg.bitmap, px, py, bg.bitmap.width * s, bg.bitmap.height * s);
    ctx.globalAlpha = 1;
  }
  grid(ctx, scene);
  items(ctx, scene);
  outline(ctx, scene.selected, scene, "#1660e8");
  outline(ctx, scene.bad, scene, "#e53935");
  drafts(ctx, scene);
}
