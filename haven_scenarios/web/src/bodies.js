// The moving bodies drawn from the simulation's poses: a TurtleBot2 (Kobuki base, three plates on
// standoffs, a Kinect-style sensor bar) and people (body, head, name).
import * as THREE from "three";
import { textSprite } from "./markers.js";

const lambert = (hex) => new THREE.MeshLambertMaterial({ color: hex });

export function turtlebot(radius, height) {
  const g = new THREE.Group();
  const baseH = 0.09;
  const base = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, baseH, 40).rotateX(Math.PI / 2), lambert(0x2b2b2e));
  base.position.z = 0.01 + baseH / 2;
  const bumper = new THREE.Mesh(
    new THREE.CylinderGeometry(radius + 0.004, radius + 0.004, 0.03, 40, 1, true, -Math.PI / 2.2, Math.PI / 1.1).rotateX(Math.PI / 2),
    lambert(0x8a8d93),
  );
  bumper.position.z = 0.05;
  bumper.rotation.z = Math.PI / 2; // the bumper wraps the front (+x)
  g.add(base, bumper);
  const plateR = radius * 0.92;
  const levels = [0.14, 0.14 + (height - 0.14) / 2, height - 0.008];
  for (const z of levels) {
    const plate = new THREE.Mesh(new THREE.CylinderGeometry(plateR, plateR, 0.012, 40).rotateX(Math.PI / 2), lambert(0x3a3a3f));
    plate.position.z = z;
    g.add(plate);
  }
  for (let k = 0; k < 4; k++) {
    const a = Math.PI / 4 + (k * Math.PI) / 2;
    const post = new THREE.Mesh(new THREE.CylinderGeometry(0.006, 0.006, height - 0.1, 8).rotateX(Math.PI / 2), lambert(0xb8bcc4));
    post.position.set(0.8 * plateR * Math.cos(a), 0.8 * plateR * Math.sin(a), 0.1 + (height - 0.1) / 2);
    g.add(post);
  }
  const kinect = new THREE.Mesh(new THREE.BoxGeometry(0.06, 0.28, 0.04), lambert(0x111111));
  kinect.position.set(0.02, 0, levels[1] + 0.03);
  g.add(kinect);
  const led = new THREE.Mesh(new THREE.SphereGeometry(0.012, 8, 8), new THREE.MeshBasicMaterial({ color: 0x33ff66 }));
  led.position.set(radius * 0.7, 0, 0.1);
  g.add(led);
  return g;
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
