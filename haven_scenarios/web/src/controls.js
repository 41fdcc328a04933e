// Keys, a gamepad, or a headset's thumbsticks -> the avatar's velocity (a person walks
// holonomically: forward/back, sideways, and turns). Sent at 20 Hz while held (the simulator stops
// an avatar whose commands stop) and at once on a key press, so a step starts without delay.
const TURN_RPS = 1.6;
const SEND_MS = 50;
const KEYS = {
  KeyW: ["vx", 1], ArrowUp: ["vx", 1], KeyS: ["vx", -1], ArrowDown: ["vx", -1],
  KeyA: ["wz", 1], ArrowLeft: ["wz", 1], KeyD: ["wz", -1], ArrowRight: ["wz", -1],
  KeyQ: ["vy", 1], KeyE: ["vy", -1],
};
// Looking up and down (the view only: a person's pitch is not part of their pose): R / F or Page Up /
// Page Down, a vertical mouse drag on the view, or a gamepad's right stick.
const LOOK_KEYS = { KeyR: 1, PageUp: 1, KeyF: -1, PageDown: -1 };
const LOOK_RPS = 1.0;
const MAX_PITCH = 1.2; // rad, about 70 degrees up or down
const DRAG_RAD_PER_PX = 0.005;
const DEAD = 0.15;
const axis = (v) => (Math.abs(v) < DEAD ? 0 : v);

export class Controls {
  constructor(speed, send) {
    this.speed = speed;
    this.send = send; // (cmd, pressedAt?) -> bool
    this.held = new Set();
    this.pad = { vx: 0, vy: 0, wz: 0 };
    this.enabled = true;
    this.zeros = 0;
    this.pitch = 0; // rad, + looks up
    this.lookPad = 0;
    this.dragY = null;
    window.addEventListener("keydown", (e) => {
      if (e.code in LOOK_KEYS && e.target.tagName !== "INPUT") {
        e.preventDefault();
        this.held.add(e.code);
        return;
      }
      if (!(e.code in KEYS) || e.target.tagName === "INPUT") return;
      e.preventDefault();
      if (this.held.has(e.code)) return;
      this.held.add(e.code);
      this.tick(e.timeStamp);
    });
    window.addEventListener("keyup", (e) => {
      this.held.delete(e.code);
      this.tick();
    });
    window.addEventListener("blur", () => this.held.clear());
    window.addEventListener("pointerdown", (e) => e.target.tagName === "CANVAS" && (this.dragY = e.clientY));
    window.addEventListener("pointerup", () => (this.dragY = null));
    window.addEventListener("pointermove", (e) => {
      if (this.dragY === null) return;
      this.setPitch(this.pitch + (this.dragY - e.clientY) * DRAG_RAD_PER_PX);
      this.dragY = e.clientY;
    });
    setInterval(() => this.tick(), SEND_MS);
  }

  command() {
    const c = { vx: this.pad.vx, vy: this.pad.vy, wz: this.pad.wz };
    for (const code of this.held) {
      if (!(code in KEYS)) continue;
      const [k, sign] = KEYS[code];
      c[k] = sign;
    }
    if (!this.enabled) return { vx: 0, vy: 0, wz: 0 };
    return { vx: c.vx * this.speed, vy: c.vy * this.speed * 0.6, wz: c.wz * TURN_RPS };
  }

  tick(pressedAt) {
    const c = this.command();
    const moving = c.vx !== 0 || c.vy !== 0 || c.wz !== 0;
    if (moving) this.zeros = 3;
    else if (this.zeros > 0) this.zeros--;
    else return;
    this.send(c, moving ? pressedAt : undefined);
  }

  setPitch(p) {
    this.pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, p));
  }

  // Each frame: the look keys and the right stick turn the view up or down.
  look(dt) {
    let rate = -this.lookPad;
    for (const code of this.held) if (code in LOOK_KEYS) rate += LOOK_KEYS[code];
    if (rate) this.setPitch(this.pitch + rate * LOOK_RPS * dt);
  }

  // Gamepads (the Gamepad API) and, in VR, the controllers' thumbsticks.
  poll(xrSession) {
    const pads = [];
    if (xrSession) for (const src of xrSession.inputSources) if (src.gamepad) pads.push(src.gamepad);
    if (navigator.getGamepads) for (const p of navigator.getGamepads()) if (p) pads.push(p);
    const next = { vx: 0, vy: 0, wz: 0 };
    let look = 0;
    for (const p of pads) {
      const a = p.axes;
      if (p.mapping === "xr-standard") {
        next.vx -= axis(a[3] || 0);
        next.wz -= axis(a[2] || 0);
      } else {
        next.vx -= axis(a[1] || 0);
        next.vy -= axis(a[0] || 0);
        next.wz -= axis(a[2] || 0);
        look += axis(a[3] || 0);
      }
    }
    this.pad = next;
    this.lookPad = look;
  }
}
