// visualization_msgs/MarkerArray -> three.js objects, one per (namespace, id), in ROS coordinates
// (x forward, y left, z up). ADD/MODIFY replace a marker, DELETE removes one, DELETEALL all of a
// topic's; nothing is guessed or smoothed: what the viz node emits is what is drawn.
import * as THREE from "three";

const ARROW = 0, CUBE = 1, SPHERE = 2, CYLINDER = 3, LINE_STRIP = 4, TEXT = 9, TRIANGLES = 11;
const DELETE = 2, DELETEALL = 3;

const box = new THREE.BoxGeometry(1, 1, 1);
const ball = new THREE.SphereGeometry(0.5, 24, 16);
const tube = new THREE.CylinderGeometry(0.5, 0.5, 1, 32).rotateX(Math.PI / 2); // ROS cylinders stand on z
const materials = new Map();
const BUBBLE = { r: 1, g: 1, b: 1, a: 0.9 }; // a thought bubble's text sits on a white label facing the viewer

function material(c, lit = true) {
  const key = `${c.r},${c.g},${c.b},${c.a},${lit}`;
  if (!materials.has(key)) {
    const opts = { color: new THREE.Color(c.r, c.g, c.b), transparent: c.a < 1, opacity: c.a, side: THREE.DoubleSide };
    materials.set(key, lit ? new THREE.MeshLambertMaterial(opts) : new THREE.MeshBasicMaterial(opts));
  }
  return materials.get(key);
}

// A text label as a sprite (always faces the camera); `height` in metres.
export function textSprite(text, color, height, background = null) {
  const px = 64, pad = background ? 28 : 12;
  const canvas = document.createElement("canvas");
  const ctx = canvas.getContext("2d");
  ctx.font = `bold ${px}px sans-serif`;
  canvas.width = Math.ceil(ctx.measureText(text).width) + 2 * pad;
  canvas.height = px + 2 * pad;
  ctx.font = `bold ${px}px sans-serif`;
  if (background) {
    const b = background;
    ctx.fillStyle = `rgba(${255 * b.r},${255 * b.g},${255 * b.b},${b.a})`;
    ctx.beginPath();
    ctx.roundRect(0, 0, canvas.width, canvas.height, canvas.height / 2);
    ctx.fill();
  }
  ctx.fillStyle = `rgba(${255 * color.r},${255 * color.g},${255 * color.b},${color.a})`;
  ctx.textBaseline = "middle";
  ctx.fillText(text, pad, canvas.height / 2);
  const tex = new THREE.CanvasTexture(canvas);
  tex.colorSpace = THREE.SRGBColorSpace;
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: tex, transparent: true }));
  const h = height * (canvas.height / px);
  sprite.scale.set((h * canvas.width) / canvas.height, h, 1);
  return sprite;
}

function arrow(m) {
  // ROS: along x, shaft length scale.x, shaft diameter scale.y, head diameter scale.z
  const g = new THREE.Group();
  const len = m.scale.x, shaft = m.scale.y, head = m.scale.z;
  const headLen = Math.min(len * 0.35, head * 1.5);
  const mat = material(m.color);
  const body = new THREE.Mesh(new THREE.CylinderGeometry(shaft / 2, shaft / 2, len - headLen, 12), mat);
  body.rotation.z = -Math.PI / 2;
  body.position.x = (len - headLen) / 2;
  const tip = new THREE.Mesh(new THREE.ConeGeometry(head / 2, headLen, 16), mat);
  tip.rotation.z = -Math.PI / 2;
  tip.position.x = len - headLen / 2;
  g.add(body, tip);
  return g;
}

function build(m, options) {
  switch (m.type) {
    case CUBE:
    case SPHERE:
    case CYLINDER: {
      const mesh = new THREE.Mesh(m.type === CUBE ? box : m.type === SPHERE ? ball : tube, material(m.color));
      mesh.scale.set(m.scale.x, m.scale.y, m.scale.z);
      return mesh;
    }
    case ARROW:
      return arrow(m);
    case TEXT:
      return textSprite(m.text, m.color, m.scale.z, options.bubbles && options.bubbles.has(m.ns) ? BUBBLE : null);
    case TRIANGLES: {
      const stretch = (options.stretchZ && options.stretchZ[m.ns]) || 1;
      const pos = new Float32Array(m.points.length * 3);
      m.points.forEach((p, i) => pos.set([p.x, p.y, p.z * stretch], 3 * i));
      const geo = new THREE.BufferGeometry();
      geo.setAttribute("position", new THREE.BufferAttribute(pos, 3));
      geo.computeVertexNormals();
      const own = options.materials && options.materials[m.ns];
      if (own) {  // texture coordinates in metres: along the wall (x + y: its walls are axis-aligned or near), and up
        const uv = new Float32Array(m.points.length * 2);
        m.points.forEach((p, i) => uv.set([p.x + p.y, p.z * stretch], 2 * i));
        geo.setAttribute("uv", new THREE.BufferAttribute(uv, 2));
      }
      return new THREE.Mesh(geo, own || material(m.color));
    }
    case LINE_STRIP: {
      const geo = new THREE.BufferGeometry().setFromPoints(m.points.map((p) => new THREE.Vector3(p.x, p.y, p.z)));
      return new THREE.Line(geo, new THREE.LineBasicMaterial({ color: new THREE.Color(m.color.r, m.color.g, m.color.b) }));
    }
    default:
      return null;
  }
}

const LEGIBLE_M = 4; // text as big as it is at this distance, however far away (a thought bubble's: readable at 3-4 m)

export class MarkerLayer {
  // options: {hide: Set of namespaces drawn otherwise, stretchZ: {ns: factor}, lift: {ns: z},
  // bubbles: Set of namespaces whose text is drawn on its own white label, facing the viewer, in
  // place of the namespace's other markers (the viz node's backdrop, which suits a top-down view),
  // materials: {ns: material} in place of the markers' colours (textures: scenery.js),
  // shadows: the markers cast and receive shadows}
  constructor(parent, options = {}) {
    this.group = new THREE.Group();
    parent.add(this.group);
    this.options = options;
    this.objects = new Map(); // "ns/id" -> {object, marker}
  }

  apply(array) {
    for (const m of array.markers) {
      if (m.action === DELETEALL) {
        for (const key of [...this.objects.keys()]) this.remove(key);
        continue;
      }
      const key = `${m.ns}/${m.id}`;
      this.remove(key);
      if (m.action === DELETE || (this.options.hide && this.options.hide.has(m.ns))) continue;
      if (m.type !== TEXT && this.options.bubbles && this.options.bubbles.has(m.ns)) continue;
      const object = build(m, this.options);
      if (!object) continue;
      const p = m.pose.position, q = m.pose.orientation;
      const lift = this.options.lift && this.options.lift[m.ns];
      object.position.set(p.x, p.y, lift !== undefined ? lift : p.z);
      if (m.type !== TEXT) object.quaternion.set(q.x, q.y, q.z, q.w);
      object.userData = { ns: m.ns, id: m.id, type: m.type, anchor: object.position.clone(), scale: m.scale };
      if (this.options.shadows) object.traverse((o) => o.isMesh && (o.castShadow = o.receiveShadow = true));
      this.group.add(object);
      this.objects.set(key, { object, marker: m });
    }
  }

  remove(key) {
    const entry = this.objects.get(key);
    if (!entry) return;
    this.group.remove(entry.object);
    entry.object.traverse((o) => {
      if (o.isSprite) o.material.map.dispose(), o.material.dispose();
      else if (o.geometry && ![box, ball, tube].includes(o.geometry)) o.geometry.dispose();
    });
    this.objects.delete(key);
  }

  count(ns) {
    let n = 0;
    for (const { marker } of this.objects.values()) if (!ns || marker.ns === ns) n++;
    return n;
  }

  namespaces() {
    const out = {};
    for (const { marker } of this.objects.values()) out[marker.ns] = (out[marker.ns] || 0) + 1;
    return out;
  }

  // The namespaces that face the viewer (the battery gauge and the thought bubble, as in HAVEN):
  // each is turned about its first marker so that its x axis runs left to right across the view.
  // `legible`: namespaces whose text grows with distance beyond LEGIBLE_M, so it reads the same from
  // afar (a thought the researcher shows at any distance). `pullTo` (metres, 0: not): each group
  // farther than that is drawn that far from the eye instead, shrunk by as much, so it looks the
  // same (same place and size on screen) but comes before every wall beyond it: a wall beside the
  // robot never clips its bubble or gauge. (Not in a headset, where both eyes would see the change.)
  face(camera, namespaces, legible = new Set(), pullTo = 0) {
    const eye = new THREE.Vector3();
    camera.getWorldPosition(eye);
    const groups = new Map();
    for (const { object } of this.objects.values()) {
      const ns = object.userData.ns;
      if (!namespaces.has(ns)) continue;
      if (!groups.has(ns)) groups.set(ns, []);
      groups.get(ns).push(object);
    }
    for (const objects of groups.values()) {
      objects.sort((a, b) => a.userData.id - b.userData.id);
      const centre = objects[0].userData.anchor;
      const yaw = Math.atan2(eye.y - centre.y, eye.x - centre.x) + Math.PI / 2; // the viewer's right
      const c = Math.cos(yaw), s = Math.sin(yaw);
      const far = eye.distanceTo(centre);
      const pull = pullTo > 0 && far > pullTo ? pullTo / far : 1;
      for (const o of objects) {
        const d = o.userData.anchor.clone().sub(centre);
        o.position.set(centre.x + c * d.x - s * d.y, centre.y + s * d.x + c * d.y, o.userData.anchor.z);
        if (o.userData.type !== TEXT && o.userData.type !== SPHERE) o.rotation.set(0, 0, yaw);
        o.userData.size ||= o.scale.clone();
        const grow = o.isSprite && legible.has(o.userData.ns) ? Math.max(1, eye.distanceTo(o.position) / LEGIBLE_M) : 1;
        o.scale.copy(o.userData.size).multiplyScalar(grow * pull);
        if (pull < 1) o.position.sub(eye).multiplyScalar(pull).add(eye);
        o.userData.pull = pull;
      }
    }
  }
}
