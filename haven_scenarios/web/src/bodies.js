// The moving bodies drawn from the simulation's poses: the trial's robot (from its description's
// look) and people (body, head, name).
import * as THREE from "three";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
import { textSprite } from "./markers.js";

const lambert = (hex) => new THREE.MeshLambertMaterial({ color: hex });

// A robot from its description's look (page_config.robot_view): each primitive in the base frame
// (x forward, z up), a cylinder's and a cone's axis up, turned by roll-pitch-yaw (ROS: about fixed
// x, y, z). Parts with `spin` turn about their own axis (spinParts).
function geometry(shape, [a, b, c]) {
  switch (shape) {
    case "box":
      return new THREE.BoxGeometry(a, b, c);
    case "cylinder":
      return new THREE.CylinderGeometry(a, b, c, 40).rotateX(Math.PI / 2);
    case "cone":
      return new THREE.ConeGeometry(a, c, 32).rotateX(Math.PI / 2);
    case "sphere":
      return new THREE.SphereGeometry(a, 20, 14);
    case "torus":
      return new THREE.TorusGeometry(a, b, 12, 40); // in the x-y plane: its axis up
    default:
      throw new Error(`robot look: unknown shape ${shape}`);
  }
}

export function robotBody(desc) {
  const g = new THREE.Group();
  g.userData.spinning = [];
  for (const p of desc.primitives) {
    const part = new THREE.Group();
    part.position.set(...p.at);
    part.rotation.set(p.rpy[0], p.rpy[1], p.rpy[2], "ZYX");
    const mesh = new THREE.Mesh(geometry(p.shape, p.size), lambert(new THREE.Color(p.colour)));
    part.add(mesh);
    g.add(part);
    if (p.spin) g.userData.spinning.push({ mesh, radius: Math.max(p.size[0], 1e-3) });
  }
  if (!desc.primitives.length) {  // no look given: its footprint's cylinder at its height
    const r = desc.radius_m;
    const body = new THREE.Mesh(geometry("cylinder", [r, r, desc.height_m]), lambert(0x555555));
    body.position.z = desc.height_m / 2;
    g.add(body);
  }
  g.userData.meshes = g.children.length;
  g.userData.aerial = desc.flight_height_m !== null && desc.flight_height_m !== undefined;
  return g;
}

// A robot file's glTF model (look.model, served by the front door at desc.model_url) in place of
// its primitives once it loads: turned from glTF's axes (y up, +z forward) to the base frame's,
// scaled to the footprint's length and width, centred over it, standing on the floor. If it does not
// load, the primitives stay.
export function withModel(body, desc, loaded) {
  if (!desc.model_url) return;
  new GLTFLoader().load(desc.model_url, (gltf) => {
    const holder = new THREE.Group();
    gltf.scene.rotation.set(Math.PI / 2, 0, 0);
    holder.rotation.z = Math.PI / 2;
    holder.add(gltf.scene);
    holder.updateMatrixWorld(true);
    const box = new THREE.Box3().setFromObject(holder);
    const size = box.getSize(new THREE.Vector3());
    const fp = footprintBox(desc.footprint);
    const k = Math.max(fp.max.x - fp.min.x, fp.max.y - fp.min.y) / Math.max(size.x, size.y, 1e-6);
    const centre = box.getCenter(new THREE.Vector3());
    holder.scale.setScalar(k);
    holder.position.set((fp.min.x + fp.max.x) / 2 - k * centre.x, (fp.min.y + fp.max.y) / 2 - k * centre.y, -k * box.min.z);
    for (const part of body.children) part.visible = false;
    body.add(holder);
    body.userData.model = true;
    loaded();
  });
}

function footprintBox(fp) {
  const points = fp.polygon.length ? fp.polygon : [[-fp.radius_m, -fp.radius_m], [fp.radius_m, fp.radius_m]];
  return new THREE.Box2().setFromPoints(points.map(([x, y]) => new THREE.Vector2(x, y)));
}

export const ROTOR_RPS = 40; // drawn rotor speed, rad/s (a blur at any real rotor speed)

// Turn the spinning parts: wheels by the distance travelled over their radius, rotors while airborne.
export function spinParts(body, travelledM, airborne, dt) {
  for (const s of body.userData.spinning) {
    s.mesh.rotation.z += airborne ? ROTOR_RPS * dt : travelledM / s.radius;
  }
}

export function person(id, radius, height) {
  const g = new THREE.Group();
  const head = 0.23;
  const body = new THREE.Mesh(new THREE.CylinderGeometry(radius * 0.8, radius * 0.6, height - head, 20).rotateX(Math.PI / 2), lambert(0xcc3333));
  body.position.z = (height - head) / 2;
  const face = new THREE.Mesh(new THREE.SphereGeometry(head / 2, 20, 14), lambert(0xe0b090));
  face.position.z = height - head / 2;
  const nose = new THREE.Mesh(new THREE.ConeGeometry(0.03, 0.07, 8), lambert(0xd09a7a));
  nose.rotation.z = -Math.PI / 2;
  nose.position.set(head / 2, 0, height - head / 2);
  const label = textSprite(id, { r: 0.1, g: 0.1, b: 0.1, a: 1 }, 0.18);
  label.position.z = height + 0.25;
  g.add(body, face, nose, label);
  return g;
}
