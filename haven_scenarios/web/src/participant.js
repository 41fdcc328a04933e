// The participant's page: HAVEN's first-person view. The camera sits at eye height on the
// participant's own pose from /humans (the simulator's: collisions and pushes included); the world
// comes from /haven/world_markers, the AR cues from /haven/ar_markers as the viz node emits them,
// the robot from /odom. Keys or a gamepad publish the avatar's velocity on /humans/<id>/cmd_vel.
import * as THREE from "three";
import { Link, config as readConfig, twist, yawOf } from "./link.js";
import { MarkerLayer } from "./markers.js";
import { robotBody, spinParts, withModel, person, walkPerson } from "./bodies.js";
import { dressScene, quality } from "./scenery.js";
import { drawInset } from "./inset.js";
import { Controls } from "./controls.js";
import { taskLine, promptFor, NOT_ASKED } from "./task.js";
import { goOn } from "./next_page.js";
import { QuestionnaireForm } from "./questionnaire.js";

const cfg = readConfig();
const me = cfg.role;
const state = (window.havenState = { frames: 0, pose: null, trial: null, markers: {}, world: 0, latencies: [], wire: [], xr: false, answered: [] });

// -- the scene, in ROS coordinates (z up) -------------------------------------------------------
const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.setSize(window.innerWidth, window.innerHeight);
renderer.xr.enabled = true;
document.getElementById("view").appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xdfe6ee);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8d8d, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.2);
sun.position.set(3, -4, 10);
scene.add(sun);
const [x0, y0, x1, y1] = cfg.bounds;
const floor = new THREE.Mesh(new THREE.PlaneGeometry(x1 - x0 + 20, y1 - y0 + 20), new THREE.MeshLambertMaterial({ color: 0xc9c3b8 }));
floor.position.set((x0 + x1) / 2, (y0 + y1) / 2, -0.001);
scene.add(floor);
const grid = new THREE.GridHelper(Math.ceil(Math.max(x1 - x0, y1 - y0)) + 20, Math.ceil(Math.max(x1 - x0, y1 - y0)) + 20, 0xa8a298, 0xb8b2a8);
grid.rotation.x = Math.PI / 2;
grid.position.set((x0 + x1) / 2, (y0 + y1) / 2, 0);
scene.add(grid);

const stretch = cfg.view_wall_height_m / cfg.marker_wall_height_m;
const world = new MarkerLayer(scene, { stretchZ: { walls: stretch, obstructions: stretch }, lift: { rooms: cfg.view_wall_height_m - 0.3 } });
state.quality = quality(cfg, renderer);
const dressed = dressScene({ level: state.quality, renderer, sun, floor, grid, world, bounds: cfg.bounds, wallHeight: cfg.view_wall_height_m });
const FACING = new Set(["thought_bubble", "battery_indicator"]);
const LEGIBLE = new Set(["thought_bubble"]); // shown far away only when the researcher asks: then readable there
const PULL_M = 1.0; // the bubble and the gauge are drawn this near, so a wall beside the robot never clips them (markers.js)
const cues = new MarkerLayer(scene, { hide: new Set(["robot", "humans", "human_names"]), bubbles: new Set(["thought_bubble"]) }); // bodies come from the poses
let robot = robotBody(cfg.robot);
robot.visible = false;
scene.add(robot);
dressed.shade(robot);
const modelLoaded = (body) => () => {
  dressed.shade(body);
  if (body === robot) state.robotModel = true;
};
withModel(robot, cfg.robot, modelLoaded(robot));
let robotMoved = 0; // metres since the last frame (the wheels turn by it)
// The robot at its /odom pose, its height included (an aerial robot's altitude).
function placeRobot(x, y, z, yaw) {
  if (robot.visible) robotMoved += Math.hypot(x - robot.position.x, y - robot.position.y, z - robot.position.z);
  robot.position.set(x, y, z);
  robot.rotation.z = yaw;
  robot.visible = true;
  state.robot = { x, y, z, meshes: robot.userData.meshes };
}
const others = new Map(); // human id -> avatar

// The participant's head: the rig stands on their pose and turns with their heading; inside it a
// y-up frame (WebXR's) looking along -z, so a headset's pose adds to the avatar's.
const rig = new THREE.Group();
const head = new THREE.Group();
head.matrixAutoUpdate = false;
head.matrix.makeBasis(new THREE.Vector3(0, -1, 0), new THREE.Vector3(0, 0, 1), new THREE.Vector3(-1, 0, 0));
rig.add(head);
scene.add(rig);
const camera = new THREE.PerspectiveCamera(70, window.innerWidth / window.innerHeight, 0.05, 200);
camera.position.set(0, cfg.eye_height_m, 0);
head.add(camera);

// -- what arrives --------------------------------------------------------------------------------
let pending = null; // key press waiting to be seen: {t, x, y, yaw}
const link = new Link(
  cfg,
  {
    "/haven/world_markers": (m) => {
      world.apply(m);
      state.world = world.count();
    },
    "/haven/ar_markers": (m) => {
      cues.apply(m);
      state.markers = cues.namespaces();
    },
    "/odom": (m) => {
      const p = m.pose.pose;
      placeRobot(p.position.x, p.position.y, p.position.z, yawOf(p.orientation));
    },
    "/humans": (m, at) => {
      m.poses.forEach((p, i) => {
        const id = cfg.humans[i];
        const pose = { x: p.position.x, y: p.position.y, yaw: yawOf(p.orientation) };
        if (id === me) {
          state.pose = pose;
          if (pending && Math.hypot(pose.x - pending.x, pose.y - pending.y) + Math.abs(pose.yaw - pending.yaw) > 1e-3) {
            pending.seen = at;
          }
          return;
        }
        if (!others.has(id)) {
          others.set(id, person(id, cfg.human_body.radius_m, cfg.human_body.height_m));
          dressed.shade(others.get(id));
          scene.add(others.get(id));
        }
        const a = others.get(id);
        a.userData.moved = (a.userData.moved || 0) + Math.hypot(pose.x - a.position.x, pose.y - a.position.y);
        a.position.set(pose.x, pose.y, 0);
        a.rotation.z = pose.yaw;
        state.others = others.size;
      });
    },
    "/haven/trial_status": (m) => {
      state.trial = JSON.parse(m.data);
      showTrial();
    },
    "/haven/participants": (m) => {
      const p = JSON.parse(m.data);
      state.paused = p.paused ? Object.keys(p.participants).filter((id) => p.participants[id].state === "away") : null;
      showTrial();
    },
    "/haven/events": (m) => {  // the web node confirms each questionnaire this participant answered; the researcher may skip them
      const e = JSON.parse(m.data);
      if (e.type === "questionnaire_answered" && e.by === me && !state.answered.includes(e.questionnaire)) {
        state.answered.push(e.questionnaire);
        showTrial();
      } else if (e.type === "intervention" && e.action === "skip_questionnaires") {
        state.skipped = true;
        showTrial();
      }
    },
  },
  state,
);

// -- the participant's controls -------------------------------------------------------------------
let inputAt = null; // the last key or stick input (for the researcher's check that the participant is there)
const controls = new Controls(cfg.speed_mps, (cmd, pressedAt) => {
  if (cmd.vx || cmd.vy || cmd.wz) inputAt = performance.now();
  if (pressedAt !== undefined && state.pose && !pending) pending = { t: pressedAt, ...state.pose };
  return link.publish(`/humans/${me}/cmd_vel`, twist(cmd.vx, cmd.vy, cmd.wz));
});

// -- prompts and the task line -------------------------------------------------------------------
const taskEl = document.getElementById("task");
const promptEl = document.getElementById("prompt");
const startButton = document.getElementById("start");
startButton.addEventListener("click", () => {
  if (link.publish("/haven/ready", { data: me })) {
    state.pressedStart = true;
    showTrial();
  }
});
const form = new QuestionnaireForm(document.getElementById("questionnaire"), (q, answers) =>
  link.publish("/haven/questionnaire", { data: JSON.stringify({ human: me, questionnaire: q.name, answers }) }),
);
window.havenForm = form;
// After a trial that was not called off: the questionnaires this participant has not answered, in order.
function pendingQuestionnaire(t) {
  if (!t || t.state !== "ended" || NOT_ASKED.includes(t.end_reason) || state.skipped) return null;
  return cfg.questionnaires.find((q) => !state.answered.includes(q.name)) || null;
}
function showTrial() {
  const t = state.trial;
  const q = pendingQuestionnaire(t);
  state.questionnaire = q ? q.name : null;
  if (q) form.show(q, cfg.questionnaires.indexOf(q) + 1, cfg.questionnaires.length);
  else form.hide();
  taskEl.textContent = state.paused ? `Paused: waiting for ${state.paused.join(", ")} to come back` : taskLine(t, me);
  const dwell = t && t.humans[me] && t.humans[me].dwell;
  document.getElementById("dwell").style.width = dwell ? `${Math.round(100 * dwell)}%` : "0";
  const prompt = promptFor(t, cfg, state.pressedStart, state.skipped);
  promptEl.hidden = !prompt || !!q;
  state.prompt = prompt && !q ? prompt.title : null;
  if (prompt) {
    promptEl.querySelector("h1").textContent = prompt.title;
    promptEl.querySelector("p").textContent = prompt.text;
    promptEl.querySelector("small").textContent = prompt.small;
    startButton.hidden = !prompt.start;
  }
  const over = !!t && t.state === "ended";
  controls.enabled = !!t && t.state === "running" && state.connected;
  link.reconnect = !over || !!q; // the study is over: its server goes away, and that is no loss
  if (over && !q) goOn(cfg.next_url); // (haven serve: on to the participant's next page)
  document.getElementById("lost").hidden = state.connected || !state.everConnected || (over && !q);
}
setInterval(() => {  // the connection: a notice when it is lost, and no walking blind
  state.everConnected ||= state.connected;
  if (state.shownConnected !== state.connected) {
    state.shownConnected = state.connected;
    showTrial();
  }
}, 250);
showTrial();

// -- every 2 s, what the researcher checks this machine by: frame rate, key-to-view latency, last input
// ... and, with `&stats` on the page's address, the same in a corner for the researcher's own look.
const statsEl = new URLSearchParams(location.search).has("stats") ? document.body.appendChild(document.createElement("div")) : null;
if (statsEl) statsEl.id = "stats";
let reportedFrames = 0;
let reportedAt = performance.now();
setInterval(() => {
  const now = performance.now();
  const fps = ((state.frames - reportedFrames) * 1000) / (now - reportedAt);
  [reportedFrames, reportedAt] = [state.frames, now];
  const latency = state.latencies.length ? state.latencies[state.latencies.length - 1] : null;
  const report = { fps: Math.round(fps * 10) / 10, latency_ms: latency === null ? null : Math.round(latency), input_age_s: inputAt === null ? null : (now - inputAt) / 1000 };
  state.reported = (state.reported || 0) + (link.publish("/haven/page_report", { data: JSON.stringify(report) }) ? 1 : 0);
  if (statsEl) statsEl.textContent = `${report.fps} fps · key→view ${report.latency_ms === null ? "–" : report.latency_ms + " ms"}`;
}, 2000);

// -- the map inset (optional per study) ----------------------------------------------------------
const inset = document.getElementById("inset");
inset.hidden = !cfg.map_inset;
let insetAt = 0;

// -- Enter VR where the browser offers immersive WebXR -------------------------------------------
const vrButton = document.getElementById("enter-vr");
if (navigator.xr) {
  navigator.xr.isSessionSupported("immersive-vr").then((ok) => {
    vrButton.hidden = !ok;
    state.xrOffered = ok;
  });
}
vrButton.addEventListener("click", async () => {
  const session = await navigator.xr.requestSession("immersive-vr", { optionalFeatures: ["local-floor"] });
  renderer.xr.setReferenceSpaceType("local-floor");
  await renderer.xr.setSession(session);
  state.xr = true;
  session.addEventListener("end", () => (state.xr = false));
});

window.addEventListener("resize", () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
});

// Where a point of the world is on the screen (CSS pixels; z > 1: behind the camera), for tests.
window.havenProject = (x, y, z) => {
  const v = new THREE.Vector3(x, y, z).project(camera);
  return { x: ((v.x + 1) / 2) * window.innerWidth, y: ((1 - v.y) / 2) * window.innerHeight, z: v.z };
};
// For the pictures of each robot (tests, docs): draw another robot's description, stand the
// participant at a pose, look down by `pitch` rad.
window.havenShowRobot = (desc, at, eye, pitch = 0) => {
  scene.remove(robot);
  robot = robotBody(desc);
  scene.add(robot);
  dressed.shade(robot);
  state.robotModel = false;
  withModel(robot, desc, modelLoaded(robot));
  placeRobot(at.x, at.y, at.z, at.yaw);
  state.pose = eye;
  state.posed = true;
  camera.rotation.x = -pitch;
  return robot.userData.meshes;
};
window.havenOthers = () => Object.fromEntries([...others].map(([id, a]) => [id, { x: a.position.x, y: a.position.y }]));
window.havenMarker = (ns, id) => {
  const e = cues.objects.get(`${ns}/${id}`);
  return e ? { x: e.object.position.x, y: e.object.position.y, z: e.object.position.z, pull: e.object.userData.pull } : null;
};

// -- every frame -----------------------------------------------------------------------------------
let frameAt = null;
renderer.setAnimationLoop((time) => {
  if (state.questionnaire) return; // the last view stays under the questionnaire; software rendering would only slow it
  const dt = frameAt === null ? 0 : Math.min(0.1, (time - frameAt) / 1000);
  frameAt = time;
  spinParts(robot, robotMoved, robot.userData.aerial && robot.position.z > 0.05, dt);
  robotMoved = 0;
  for (const a of others.values()) {
    walkPerson(a, a.userData.moved || 0, dt);
    a.userData.moved = 0;
  }
  controls.poll(renderer.xr.isPresenting ? renderer.xr.getSession() : null);
  controls.look(dt);
  if (!renderer.xr.isPresenting && !state.posed) camera.rotation.x = controls.pitch; // (a headset looks with the head)
  state.pitch = controls.pitch;
  if (state.pose) {
    rig.position.set(state.pose.x, state.pose.y, 0);
    rig.rotation.z = state.pose.yaw;
  }
  scene.updateMatrixWorld();
  const xr = renderer.xr.isPresenting;
  cues.face(xr ? renderer.xr.getCamera() : camera, FACING, LEGIBLE, xr ? 0 : PULL_M);
  renderer.render(scene, camera);
  state.frames++;
  // (from the matrix the frame was drawn with: getWorldDirection would recompute an XR camera's
  // matrix without the avatar's rig)
  const seen = new THREE.Vector3(0, 0, -1).transformDirection((renderer.xr.isPresenting ? renderer.xr.getCamera() : camera).matrixWorld);
  state.view = { x: seen.x, y: seen.y, z: seen.z }; // where the participant looks (map frame)
  if (pending && pending.seen !== undefined) {
    state.latencies.push(performance.now() - pending.t); // key press -> own pose moved -> this frame drawn
    state.wire.push(pending.seen - pending.t); // ... of which until the moved pose arrived
    pending = null;
  }
  if (cfg.map_inset && time - insetAt > 200) {
    insetAt = time;
    drawInset(inset, cfg, world, state, others);
  }
});
