// The page's connection to the suite: a Foxglove WebSocket client (through the study's front door)
// that decodes ros2msg/CDR channels itself and publishes through the client-publish capability.
import { FoxgloveClient } from "@foxglove/ws-protocol";
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";

export const SUBPROTOCOL = "foxglove.sdk.v1"; // what foxglove-sdk's server accepts

export class Link {
  // config: the page's embedded settings; topics: {topic: handler(message, receiveTimeMs)}
  constructor(config, topics, state) {
    this.config = config;
    this.topics = topics;
    this.state = state; // window.havenState: counters the tests and the status line read
    this.readers = new Map(); // subscription id -> {topic, reader}
    this.writers = new Map(); // topic -> {channel, writer}
    this.parameterHandlers = [];
    this.reconnect = true; // the page turns it off once the trial is over
    this.state.decoded = {};
    this.state.connected = false;
    this.connect();
  }

  socketUrl() {
    const token = new URLSearchParams(location.search).get("token") || "";
    const scheme = location.protocol === "https:" ? "wss" : "ws";
    const path = this.config.console ? "ws/console" : `ws/participant/${encodeURIComponent(this.config.role)}`;
    return `${scheme}://${location.host}/${path}?token=${encodeURIComponent(token)}`;
  }

  connect() {
    const ws = new WebSocket(this.socketUrl(), [SUBPROTOCOL]);
    const client = new FoxgloveClient({ ws });
    this.client = client;
    client.on("open", () => {
      this.state.connected = true;
      this.writers.clear();
    });
    client.on("close", () => {
      this.state.connected = false;
      this.readers.clear();
      if (this.reconnect) setTimeout(() => this.connect(), 1000); // the suite may still be starting, or restarting
    });
    client.on("error", () => {});
    client.on("advertise", (channels) => {
      for (const ch of channels) {
        if (!(ch.topic in this.topics) || ch.encoding !== "cdr") continue;
        const reader = new MessageReader(parse(ch.schema, { ros2: true }));
        const id = client.subscribe(ch.id);
        this.readers.set(id, { topic: ch.topic, reader });
      }
    });
    client.on("message", ({ subscriptionId, data }) => {
      const sub = this.readers.get(subscriptionId);
      if (!sub) return;
      const msg = sub.reader.readMessage(data);
      this.state.decoded[sub.topic] = (this.state.decoded[sub.topic] || 0) + 1;
      this.topics[sub.topic](msg, performance.now());
    });
    client.on("status", (s) => console.warn("server:", s.message));
    client.on("parameterValues", ({ parameters }) => this.parameterHandlers.forEach((h) => h(parameters)));
  }

  // Publish a message on a topic this page's role may publish on (types from the config).
  publish(topic, message) {
    if (!this.state.connected) return false;
    let w = this.writers.get(topic);
    if (!w) {
      const type = this.config.publish[topic];
      if (!type) throw new Error(`this page may not publish on ${topic}`);
      const schema = this.config.schemas[type];
      const channel = this.client.advertise({ topic, encoding: "cdr", schemaName: type, schema, schemaEncoding: "ros2msg" });
      w = { channel, writer: new MessageWriter(parse(schema, { ros2: true })) };
      this.writers.set(topic, w);
    }
    this.client.sendMessage(w.channel, w.writer.writeMessage(message));
    return true;
  }

  onParameters(handler) {
    this.parameterHandlers.push(handler);
  }

  getParameters(names) {
    if (this.state.connected) this.client.getParameters(names, "get");
  }

  setParameters(parameters) {
    if (this.state.connected) this.client.setParameters(parameters, "set");
  }
}

export function twist(vx, vy, wz) {
  return { linear: { x: vx, y: vy, z: 0 }, angular: { x: 0, y: 0, z: wz } };
}

export function yawOf(q) {
  return Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

export function config() {
  return JSON.parse(document.getElementById("config").textContent);
}
