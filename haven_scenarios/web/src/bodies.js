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

// A person built from primitives (nothing to license), in the proportions of the segment lengths
// Drillis, Contini and Bluestein gave as fractions of stature H (as drawn in D. A. Winter,
// Biomechanics and Motor Control of Human Movement, 4th ed., 2009, Fig. 4.1): hip height 0.530 H,
// shoulder height 0.818 H, shoulder width 0.259 H, hip width 0.191 H, upper arm 0.186 H, forearm
// and hand 0.254 H, head 0.130 H. Legs and arms swing with the distance walked (`walkPerson`); each
// person's shirt has its own colour (from their id), so two people are told apart.
const SHIRTS = [0xcc3333, 0x2f6db5, 0x3a8f4a, 0xc77d1e, 0x7a4fa3, 0x1f8f8f];
const STRIDE_M = 0.75; // one step (a comfortable walking step: about 0.43 H at 1.75 m)
const SWING_RAD = 0.45;

function limb(length, radius, material) {
  const pivot = new THREE.Group(); // at the hip or shoulder: the limb hangs down from it
  const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius * 0.8, length, 10).rotateX(Math.PI / 2), material);
  mesh.position.z = -length / 2;
  pivot.add(mesh);
  return pivot;
}

export function person(id, radius, height) {
  const g = new THREE.Group();
  const H = height;
  const hash = [...id].reduce((h, c) => (h * 31 + c.charCodeAt(0)) >>> 0, 7);
  const skin = lambert(0xe0b090), shirt = lambert(SHIRTS[hash % SHIRTS.length]), trousers = lambert(0x34384a);
  const hip = 0.53 * H, shoulder = 0.818 * H, head = 0.13 * H;
  const legs = [1, -1].map((side) => {
    const leg = limb(hip - 0.04, 0.065, trousers);
    leg.position.set(0, (side * 0.191 * H) / 2 - side * 0.045, hip);
    const shoe = new THREE.Mesh(new THREE.BoxGeometry(0.26, 0.1, 0.08), lambert(0x2a2a2a));
    shoe.position.set(0.05, 0, -(hip - 0.04));
    leg.add(shoe);
    return leg;
  });
  const torso = new THREE.Mesh(new THREE.CylinderGeometry(0.259 * H * 0.42, 0.191 * H * 0.5, shoulder - hip + 0.04, 16).rotateX(Math.PI / 2), shirt);
  torso.position.z = (hip + shoulder) / 2;
  torso.scale.x = 0.6; // flatter front to back than side to side
  const arms = [1, -1].map((side) => {
    const arm = limb(0.44 * H - 0.02, 0.045, shirt);
    arm.position.set(0, (side * 0.259 * H) / 2, shoulder - 0.02);
    const hand = new THREE.Mesh(new THREE.SphereGeometry(0.045, 10, 8), skin);
    hand.position.z = -(0.44 * H - 0.02);
    arm.add(hand);
    return arm;
  });
  const neck = new THREE.Mesh(new THREE.CylinderGeometry(0.05, 0.05, 0.08, 10).rotateX(Math.PI / 2), skin);
  neck.position.z = shoulder + 0.03;
  const face = new THREE.Mesh(new THREE.SphereGeometry(head / 2, 20, 14), skin);
  face.scale.set(0.9, 0.8, 1);
  face.position.z = H - head / 2;
  const nose = new THREE.Mesh(new THREE.ConeGeometry(0.025, 0.06, 8), lambert(0xd09a7a));
  nose.rotation.z = -Math.PI / 2;
  nose.position.set(head * 0.45, 0, H - head / 2);
  const label = textSprite(id, { r: 0.1, g: 0.1, b: 0.1, a: 1 }, 0.18);
  label.position.z = H + 0.25;
  g.add(...legs, torso, ...arms, neck, face, nose, label);
  g.userData.gait = { legs, arms, phase: 0 };
  return g;
}

// The gait: legs and the opposite arms swing with the distance walked since the last frame; a
// person standing still eases back to standing.
export function walkPerson(g, movedM, dt) {
  const gait = g.userData.gait;
  let swing;
  if (movedM > 1e-3) {
    gait.phase += (movedM / STRIDE_M) * Math.PI;
    swing = Math.sin(gait.phase) * SWING_RAD;
  } else {
    swing = gait.legs[0].rotation.y * Math.max(0, 1 - 8 * dt);
  }
  gait.legs[0].rotation.y = swing;
  gait.legs[1].rotation.y = -swing;
  gait.arms[0].rotation.y = -0.7 * swing;
  gait.arms[1].rotation.y = 0.7 * swing;
}
