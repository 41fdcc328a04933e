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
    window.addEventListener("keydown", (e) => {
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
    setInterval(() => this.tick(), SEND_MS);
  }

  command() {
    const c = { vx: this.pad.vx, vy: this.pad.vy, wz: this.pad.wz };
    for (const code of this.held) {
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

  // Gamepads (the Gamepad API) and, in VR, the controllers' thumbsticks.
  poll(xrSession) {
    const pads = [];
    if (xrSession) for (const src of xrSession.inputSources) if (src.gamepad) pads.push(src.gamepad);
    if (navigator.getGamepads) for (const p of navigator.getGamepads()) if (p) pads.push(p);
    const next = { vx: 0, vy: 0, wz: 0 };
    for (const p of pads) {
      const a = p.axes;
      if (p.mapping === "xr-standard") {
        next.vx -= axis(a[3] || 0);
        next.wz -= axis(a[2] || 0);
      } else {
        next.vx -= axis(a[1] || 0);
        next.vy -= axis(a[0] || 0);
        next.wz -= axis(a[2] || 0);
      }
    }
    this.pad = next;
  }
}
