// The participant's scene beyond the diagram: a floor and walls with texture and, at the highest
// quality, soft shadows. Textures are drawn here on canvases (nothing downloaded, nothing to
// license). The researcher picks the quality for each device (`&quality=` on the participant's
// address): `low` is the plain scene (the fastest on a machine without a GPU), `standard` adds the
// textures, `high` adds soft shadows from the ceiling light. Without a choice: `standard`, or `low`
// where the browser draws in software (no GPU: SwiftShader, llvmpipe), which textures halve.
import * as THREE from "three";

export const QUALITIES = ["low", "standard", "high"];

function canvasTexture(size, paint) {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = size;
  paint(canvas.getContext("2d"), size);
  const t = new THREE.CanvasTexture(canvas);
  t.wrapS = t.wrapT = THREE.RepeatWrapping;
  t.colorSpace = THREE.SRGBColorSpace;
  return t;
}

// A seeded noise, so every page draws the same floor.
function speckle(ctx, size, count, colours, seed = 1) {
  let s = seed;
  const next = () => ((s = (s * 16807) % 2147483647) / 2147483647);
  for (let i = 0; i < count; i++) {
    ctx.fillStyle = colours[Math.floor(next() * colours.length)];
    ctx.fillRect(next() * size, next() * size, 1 + next() * 2, 1 + next() * 2);
  }
}

// Floor tiles 0.5 m square with grout lines (one texture repeat per tile).
function floorTexture() {
  return canvasTexture(128, (ctx, n) => {
    ctx.fillStyle = "#cfc8bb";
    ctx.fillRect(0, 0, n, n);
    speckle(ctx, n, 900, ["#c4bcae", "#d8d2c6", "#bfb7a8"]);
    ctx.strokeStyle = "#a79f90";
    ctx.lineWidth = 3;
    ctx.strokeRect(0, 0, n, n);
  });
}

// Painted plaster with a darker skirting board along the bottom (one repeat: 1 m wide, the wall's height).
function wallTexture() {
  return canvasTexture(128, (ctx, n) => {
    ctx.fillStyle = "#e9e4da";
    ctx.fillRect(0, 0, n, n);
    speckle(ctx, n, 700, ["#e1dbd0", "#f0ece4", "#ddd6ca"], 7);
    ctx.fillStyle = "#8d8273";
    ctx.fillRect(0, n - 6, n, 6);
  });
}

const SOFTWARE = /swiftshader|llvmpipe|softpipe|software/i;

// The WebGL renderer's name, where the browser tells it (a software one means no GPU).
export function rendererName(renderer) {
  const gl = renderer.getContext();
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  return String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER) || "");
}

export function quality(cfg, renderer) {
  const asked = new URLSearchParams(location.search).get("quality") || cfg.quality;
  if (QUALITIES.includes(asked)) return asked;
  return SOFTWARE.test(rendererName(renderer)) ? "low" : "standard";
}

// Dress the scene for the quality: the floor's and the walls' materials (walls: the world layer's
// `materials` option, with texture coordinates from their metres), shadows at `high`.
export function dressScene({ level, renderer, sun, floor, grid, world, bounds, wallHeight }) {
  if (level === "low") return { shade: () => {} };
  const [x0, y0, x1, y1] = bounds;
  const floorMap = floorTexture();
  floorMap.repeat.set((x1 - x0 + 20) / 0.5, (y1 - y0 + 20) / 0.5);
  floor.material = new THREE.MeshLambertMaterial({ map: floorMap });
  grid.visible = false;
  const wallMap = wallTexture();
  wallMap.repeat.set(1, 1 / wallHeight);
  world.options.materials = { walls: new THREE.MeshLambertMaterial({ map: wallMap, side: THREE.DoubleSide }) };
  if (level !== "high") return { shade: () => {} };
  renderer.shadowMap.enabled = true;
  renderer.shadowMap.type = THREE.PCFSoftShadowMap;
  sun.castShadow = true;
  sun.shadow.mapSize.set(1024, 1024);
  sun.shadow.radius = 4;
  const c = sun.shadow.camera;
  const half = Math.max(x1 - x0, y1 - y0) / 2 + 2;
  [c.left, c.right, c.top, c.bottom, c.near, c.far] = [-half, half, half, -half, 0.5, 60];
  sun.position.set((x0 + x1) / 2 + 3, (y0 + y1) / 2 - 4, 20);
  sun.target.position.set((x0 + x1) / 2, (y0 + y1) / 2, 0);
  sun.target.updateMatrixWorld();
  floor.receiveShadow = true;
  world.options.shadows = true;
  // Bodies made later (the robot, people) cast shadows too.
  return { shade: (object) => object.traverse((o) => o.isMesh && (o.castShadow = true)) };
}
