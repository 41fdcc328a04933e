// A small top-down map: walls and obstacles (from the world markers), gems, the robot, people, and
// the participant (blue, with their heading).
export function drawInset(canvas, cfg, world, state, others) {
  const ctx = canvas.getContext("2d");
  const [x0, y0, x1, y1] = cfg.bounds;
  const pad = 0.5;
  const s = Math.min(canvas.width / (x1 - x0 + 2 * pad), canvas.height / (y1 - y0 + 2 * pad));
  const X = (x) => (x - x0 + pad) * s;
  const Y = (y) => canvas.height - (y - y0 + pad) * s;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = "rgba(255,255,255,0.85)";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  for (const { marker: m } of world.objects.values()) {
    const c = m.color;
    ctx.fillStyle = `rgba(${255 * c.r},${255 * c.g},${255 * c.b},${Math.max(c.a, 0.3)})`;
    if (m.type === 11) {
      for (let i = 0; i + 2 < m.points.length; i += 3) {
        const [a, b, d] = [m.points[i], m.points[i + 1], m.points[i + 2]];
        if (!(a.z > 0.01 && b.z > 0.01 && d.z > 0.01)) continue; // the top faces: the footprint
        ctx.beginPath();
        ctx.moveTo(X(a.x), Y(a.y));
        ctx.lineTo(X(b.x), Y(b.y));
        ctx.lineTo(X(d.x), Y(d.y));
        ctx.fill();
      }
    } else if (m.ns === "gems" || m.ns === "charging_base") {
      ctx.beginPath();
      ctx.arc(X(m.pose.position.x), Y(m.pose.position.y), Math.max(2, (m.scale.x / 2) * s), 0, 2 * Math.PI);
      ctx.fill();
    }
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
