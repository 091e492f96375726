// A Foxglove WebSocket client (@foxglove/ws-protocol over `ws`) watching a gdnav run live (CTest LiveNode,
// tests/integration/viewing/live_node_test.cpp). Connects to URL (retrying until the server listens), subscribes to every
// advertised channel and decodes every message with Foxglove's OMG IDL deserializer (@foxglove/omgidl-parser,
// @foxglove/omgidl-serialization) from the advertised schema.
//
//   node live_client.mjs URL OUT.json read  SECONDS   keep reading until the server closes; write OUT.json
//   node live_client.mjs URL OUT.json stall SECONDS   stop reading (pause the socket) after the first message;
//                                                     write OUT.json at once, then idle until killed or SECONDS
//
// OUT.json: {channels: [advertised channels], topics: {TOPIC: {count, steps: [...], timestamps: [...],
//   samples: {STEP: {fields: {dotted.name: [values as strings]}, hex: payload}}}}, errors: [...], stalled: bool}
// `steps` is stamp.step for stamped messages, else null; samples are kept at steps that are multiples of 100
// (stamped topics) or of 100 log-time steps (the others, step = timestamp / 1e7).
import { writeFileSync } from "node:fs";
import WebSocket from "ws";
import wsProtocol from "@foxglove/ws-protocol";  // CommonJS
import { parseIDL } from "@foxglove/omgidl-parser";
import { MessageReader } from "@foxglove/omgidl-serialization";

const { FoxgloveClient } = wsProtocol;

const [url, outFile, mode, secondsArg] = process.argv.slice(2);
if (!url || !outFile || !["read", "stall"].includes(mode)) {
  console.error("usage: node live_client.mjs URL OUT.json read|stall SECONDS");
  process.exit(2);
}
const deadline = Date.now() + 1000 * Number(secondsArg ?? 120);
const out = { channels: [], topics: {}, errors: [], stalled: false, messages: 0 };
const channels = new Map();  // id -> {topic, reader}
const bySubscription = new Map();  // subscription id -> channel id
const error = (s) => { if (out.errors.length < 50) out.errors.push(s); };

function write() { writeFileSync(outFile, JSON.stringify(out, (k, v) => (typeof v === "bigint" ? v.toString() : v))); }

function value(v) {
  if (typeof v === "bigint") return v.toString();
  if (typeof v === "boolean") return v ? "true" : "false";
  return String(v);
}
// Nested objects -> dotted names; arrays and typed arrays -> their elements; other values -> one element.
function flatten(obj, prefix, into) {
  for (const [k, v] of Object.entries(obj)) {
    const name = prefix ? `${prefix}.${k}` : k;
    if (ArrayBuffer.isView(v) || Array.isArray(v)) into[name] = Array.from(v, value);
    else if (v !== null && typeof v === "object") flatten(v, name, into);
    else into[name] = [value(v)];
  }
  return into;
}
const hex = (u8) => Buffer.from(u8.buffer, u8.byteOffset, u8.byteLength).toString("hex");

function connect() {
  const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const client = new FoxgloveClient({ ws });
  let opened = false;
  client.on("open", () => { opened = true; });
  client.on("error", (e) => {
    if (!opened && Date.now() < deadline) return;  // not listening yet: the close handler retries
    error(`websocket error: ${e?.message ?? e}`);
  });
  client.on("close", () => {
    if (!opened) {
      if (Date.now() < deadline) setTimeout(connect, 100);
      else { error("could not connect before the deadline"); write(); process.exit(1); }
      return;
    }
    write();
    console.log(`closed: ${out.messages} messages on ${Object.keys(out.topics).length} topics, ${out.errors.length} errors`);
    process.exit(out.errors.length ? 1 : 0);
  });
  client.on("status", (s) => error(`server status ${s.level}: ${s.message}`));
  client.on("advertise", (list) => {
    for (const c of list) {
      out.channels.push({ id: c.id, topic: c.topic, encoding: c.encoding, schemaName: c.schemaName,
                          schemaEncoding: c.schemaEncoding, schema: c.schema });
      try {
        const reader = new MessageReader(c.schemaName, parseIDL(c.schema));
        channels.set(c.id, { topic: c.topic, reader });
        bySubscription.set(client.subscribe(c.id), c.id);
      } catch (e) {
        error(`channel ${c.topic}: cannot parse its schema: ${e.message}`);
      }
    }
    console.log(`subscribed to ${bySubscription.size} channels`);
  });
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    const ch = channels.get(bySubscription.get(subscriptionId));
    if (!ch) { error(`message of unknown subscription ${subscriptionId}`); return; }
    const bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
    let msg;
    try {
      msg = ch.reader.readMessage(bytes);
    } catch (e) {
      error(`${ch.topic}: cannot decode: ${e.message}`);
      return;
    }
    ++out.messages;
    const t = (out.topics[ch.topic] ??= { count: 0, steps: [], timestamps: [], samples: {} });
    ++t.count;
    const step = msg.stamp?.step !== undefined ? BigInt(msg.stamp.step) : null;
    t.steps.push(step === null ? null : Number(step));
    t.timestamps.push(Number(timestamp));
    const sampleStep = step ?? timestamp / 10000000n;
    if (sampleStep % 100n === 0n) t.samples[sampleStep.toString()] = { fields: flatten(msg, "", {}), hex: hex(bytes) };
    if (mode === "stall" && !out.stalled) {
      out.stalled = true;
      ws._socket.pause();  // stop reading: the server's sends pile up in the socket buffers, then at the server
      write();
      console.log("STALLED");
    }
  });
}

setTimeout(() => { write(); console.log(`deadline: ${out.messages} messages`); process.exit(mode === "stall" ? 0 : 1); },
           Math.max(0, deadline - Date.now()));
connect();
