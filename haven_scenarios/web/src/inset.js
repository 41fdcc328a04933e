// A small top-down map: walls and obstacles (from the world markers), gems, the robot, people, and
// the participant (blue, with their heading).
import { fit, footprint, disc } from "./topdown.js";

export function drawInset(canvas, cfg, world, state, others) {
  const ctx = canvas.getContext("2d");
  const t = fit(canvas, cfg.bounds, 0.5);
  const { X, Y } = t;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = "rgba(255,255,255,0.85)";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  for (const { marker: m } of world.objects.values()) {
    if (m.type === 11) footprint(ctx, m, t);
    else if (m.ns === "gems" || m.ns === "charging_base") disc(ctx, m, t);
  }
  const dot = (x, y, r, color) => {
    ctx.fillStyle = color;
    ctx.beginPath();
    ctx.arc(X(x), Y(y), r, 0, 2 * Math.PI);
    ctx.fill();
  };
  if (state.robot) dot(state.robot.x, state.robot.y, 4, "#222");
  for (const a of others.values()) dot(a.position.x, a.position.y, 4, "#c33");
  if (state.pose) {
    const p = state.pose;
    dot(p.x, p.y, 5, "#1660e8");
    ctx.strokeStyle = "#1660e8";
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(X(p.x), Y(p.y));
    ctx.lineTo(X(p.x + 0.8 * Math.cos(p.yaw)), Y(p.y + 0.8 * Math.sin(p.yaw)));
    ctx.stroke();
  }
}
