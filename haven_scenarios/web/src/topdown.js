// Top-down drawing shared by the participant's map inset and the researcher console: the map frame
// fitted to a canvas, and markers drawn from above (a prism's top faces as its footprint).
export function fit(canvas, bounds, pad) {
  const [x0, y0, x1, y1] = bounds;
  const s = Math.min(canvas.width / (x1 - x0 + 2 * pad), canvas.height / (y1 - y0 + 2 * pad));
  return { s, X: (x) => (x - x0 + pad) * s, Y: (y) => canvas.height - (y - y0 + pad) * s };
}

export function rgba(c, minA = 0) {
  return `rgba(${Math.round(255 * c.r)},${Math.round(255 * c.g)},${Math.round(255 * c.b)},${Math.max(c.a, minA)})`;
}

// A TRIANGLE_LIST marker's top faces (every corner above the floor), filled.
export function footprint(ctx, m, { X, Y }) {
  ctx.fillStyle = rgba(m.color, 0.3);
  for (let i = 0; i + 2 < m.points.length; i += 3) {
    const [a, b, c] = [m.points[i], m.points[i + 1], m.points[i + 2]];
    if (!(a.z > 0.01 && b.z > 0.01 && c.z > 0.01)) continue;
    ctx.beginPath();
    ctx.moveTo(X(a.x), Y(a.y));
    ctx.lineTo(X(b.x), Y(b.y));
    ctx.lineTo(X(c.x), Y(c.y));
    ctx.fill();
  }
}

// A round marker (gem, base, cue sphere) as a disc of its size.
export function disc(ctx, m, { s, X, Y }) {
  ctx.fillStyle = rgba(m.color, 0.3);
  ctx.beginPath();
  ctx.arc(X(m.pose.position.x), Y(m.pose.position.y), Math.max(2, (Math.max(m.scale.x, m.scale.y) / 2) * s), 0, 2 * Math.PI);
  ctx.fill();
}
