// Reads a gdnav MCAP recording with the official TypeScript reader (@mcap/core: McapIndexedReader through the
// summary and index, and McapStreamReader front to back with CRC checks; zstd chunks through @foxglove/wasm-zstd)
// and decodes every message of every channel with Foxglove's OMG IDL deserializer (@foxglove/omgidl-parser,
// @foxglove/omgidl-serialization) from the schema stored in the file. Compares with the expected values that
// gdnav's own reader wrote (EXPECTED.json, tests/integration/viewing/mcap_node_test.cpp): message counts per topic, and every
// field of the samples at the listed steps, exactly; and, under "h5", the values the run's run.h5 holds of some
// fields at some steps, exactly. Exit 0 when everything matches, 1 with the mismatches.
//
//   node check_mcap.mjs FILE.mcap EXPECTED.json
import { readFile } from "node:fs/promises";
import { McapStreamReader } from "@mcap/core";
import { parseIDL } from "@foxglove/omgidl-parser";
import { MessageReader } from "@foxglove/omgidl-serialization";
import { decompressHandlers as zstdHandlers, indexedReader, problemList } from "./mcap_file.mjs";

const [file, expectedFile] = process.argv.slice(2);
if (!file || !expectedFile) {
  console.error("usage: node check_mcap.mjs FILE.mcap EXPECTED.json");
  process.exit(2);
}
const decompressHandlers = await zstdHandlers();
const expected = JSON.parse(await readFile(expectedFile, "utf8"));
const [problems, problem] = problemList();

// Indexed reader: summary, statistics, chunk indexes, metadata, attachments.
const { reader, closeFile } = await indexedReader(file);
console.log(`header: profile '${reader.header.profile}', library '${reader.header.library}'`);
console.log(`summary: ${reader.channelsById.size} channels, ${reader.schemasById.size} schemas, ` +
  `${reader.chunkIndexes.length} chunks (${[...new Set(reader.chunkIndexes.map((c) => c.compression))].join(",")}), ` +
  `${reader.statistics?.messageCount} messages`);
if (!reader.statistics) problem("no Statistics record in the summary");
if (reader.chunkIndexes.length === 0) problem("no Chunk Index records");
for (const c of reader.chunkIndexes) {
  if (c.compression !== "zstd") problem(`chunk at ${c.chunkStartOffset}: compression '${c.compression}'`);
  if (c.messageIndexOffsets.size === 0) problem(`chunk at ${c.chunkStartOffset}: no message index`);
}

// One deserializer per channel, from the channel's own schema.
const decoders = new Map();
for (const [id, channel] of reader.channelsById) {
  const schema = reader.schemasById.get(channel.schemaId);
  if (!schema) {
    problem(`channel ${channel.topic}: no schema`);
    continue;
  }
  if (channel.messageEncoding !== "cdr") problem(`channel ${channel.topic}: message encoding ${channel.messageEncoding}`);
  if (schema.encoding !== "omgidl") problem(`channel ${channel.topic}: schema encoding ${schema.encoding}`);
  const definitions = parseIDL(new TextDecoder().decode(schema.data));
  decoders.set(id, { topic: channel.topic, type: schema.name, reader: new MessageReader(schema.name, definitions) });
}

// Exact comparison of a decoded value with gdnav's expected value (a string: doubles with 17 significant digits,
// 64-bit integers in decimal, booleans as true/false).
function same(decoded, want, kind) {
  switch (kind) {
    case "f64": return typeof decoded === "number" && decoded === Number(want);
    case "u64": return BigInt(decoded) === BigInt(want);
    case "bool": return decoded === (want === "true");
    case "string": return decoded === want;
    default: return Number(decoded) === Number(want);  // u8, u32, enum (index)
  }
}
function field(obj, dotted) {
  return dotted.split(".").reduce((o, k) => (o === undefined ? undefined : o[k]), obj);
}
function compare(topic, step, msg, want, source = "gdnav's reader") {
  let compared = 0;
  for (const [name, { kind, values }] of Object.entries(want)) {
    const got = field(msg, name);
    const list = values.length === 1 && !(got instanceof Object) ? [got] : Array.from(got ?? []);
    if (list.length !== values.length) {
      problem(`${topic} step ${step} ${name}: ${list.length} values decoded, ${values.length} expected`);
      continue;
    }
    for (let i = 0; i < values.length; ++i) {
      ++compared;
      if (!same(list[i], values[i], kind))
        problem(`${topic} step ${step} ${name}[${i}]: decoded ${list[i]}, ${source} ${values[i]}`);
    }
  }
  return compared;
}

// Every message of every channel, through the index (log-time order), decoded.
const counts = new Map();
let decodedFields = 0, checkedSamples = 0, h5Fields = 0, h5Samples = 0;
for await (const m of reader.readMessages({ validateCrcs: true })) {
  const d = decoders.get(m.channelId);
  if (!d) continue;
  let msg;
  try {
    msg = d.reader.readMessage(m.data);
  } catch (e) {
    problem(`${d.topic} sequence ${m.sequence}: cannot decode: ${e.message}`);
    continue;
  }
  counts.set(d.topic, (counts.get(d.topic) ?? 0) + 1);
  const step = BigInt(msg.stamp.step);
  if (step !== BigInt(m.sequence)) problem(`${d.topic}: stamp.step ${step} in the message of sequence ${m.sequence}`);
  const want = expected.topics[d.topic]?.samples?.[String(step)];
  if (want) {
    decodedFields += compare(d.topic, step, msg, want);
    ++checkedSamples;
  }
  const h5 = expected.h5?.[d.topic]?.[String(step)];
  if (h5) {
    h5Fields += compare(d.topic, step, msg, h5, "run.h5");
    ++h5Samples;
  }
}
for (const [topic, e] of Object.entries(expected.topics)) {
  const got = counts.get(topic) ?? 0;
  if (got !== e.count) problem(`${topic}: ${got} messages decoded, gdnav's reader has ${e.count}`);
  if (decoders.get([...reader.channelsById].find(([, c]) => c.topic === topic)?.[0])?.type !== e.type)
    problem(`${topic}: schema name is not ${e.type}`);
}
const wantSamples = Object.values(expected.topics).reduce((n, e) => n + Object.keys(e.samples).length, 0);
if (checkedSamples !== wantSamples) problem(`${checkedSamples} samples compared, ${wantSamples} expected`);
const wantH5 = Object.values(expected.h5 ?? {}).reduce((n, e) => n + Object.keys(e).length, 0);
if (h5Samples !== wantH5) problem(`${h5Samples} samples compared with run.h5, ${wantH5} expected`);

// Metadata and attachment.
const metadata = new Map();
for await (const m of reader.readMetadata()) metadata.set(m.name, m.metadata);
for (const [key, value] of Object.entries(expected.metadata ?? {}))
  if (metadata.get("gdnav.run")?.get(key) !== value)
    problem(`metadata gdnav.run.${key}: '${metadata.get("gdnav.run")?.get(key)}', expected '${value}'`);
let runYaml = "";
for await (const a of reader.readAttachments({ name: "run.yaml", validateCrcs: true })) runYaml = new TextDecoder().decode(a.data);
if (expected.run_yaml_bytes !== undefined && runYaml.length !== expected.run_yaml_bytes)
  problem(`attachment run.yaml: ${runYaml.length} bytes, expected ${expected.run_yaml_bytes}`);

// Front to back with the streaming reader (CRCs of chunks and of the data section checked).
const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
stream.append(await readFile(file));
let streamed = 0, record, sawFooter = false;
while ((record = stream.nextRecord())) {
  if (record.type === "Message") ++streamed;
  if (record.type === "Footer") sawFooter = true;
}
if (!sawFooter || !stream.done()) problem("stream reader: did not reach the footer");
if (BigInt(streamed) !== reader.statistics?.messageCount) problem(`stream reader: ${streamed} messages, statistics ${reader.statistics?.messageCount}`);
await closeFile();

for (const [topic, n] of counts) console.log(`  ${topic}: ${n} messages decoded (${decoders.get([...reader.channelsById].find(([, c]) => c.topic === topic)[0]).type})`);
console.log(`compared ${decodedFields} field values of ${checkedSamples} samples with gdnav's reader, ` +
  `${h5Fields} of ${h5Samples} samples with run.h5; stream reader: ${streamed} messages; metadata: ${[...metadata.keys()].join(", ")}; run.yaml ${runYaml.length} bytes`);
if (problems.length) {
  console.log(`FAIL: ${problems.length} problem(s)`);
  for (const p of problems) console.log(`  ${p}`);
  process.exit(1);
}
console.log("PASS");
