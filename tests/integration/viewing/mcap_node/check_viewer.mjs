// The viewer channels of a gdnav recording (components/viewer/viewer_channels.hpp) read with the
// official TypeScript reader (@mcap/core, indexed, CRCs checked) and decoded by Foxglove's OMG IDL deserializer
// (@foxglove/omgidl-parser + @foxglove/omgidl-serialization) from the schema text in the file, then compared with
// values computed here, independently of gdnav's C++ code, from the raw topics of the same file (gdnav/Truth,
// gdnav/PositionEstimate, gdnav/AttitudeEstimate, decoded the same way) and with the run's run.h5 /error rows
// (EXPECTED.json, written by tests/integration/viewing/mcap_node_test.cpp):
//   LocationFix     latitude/longitude = lat_rad/lon_rad * 180/pi, altitude = h_m, timestamp = log time
//   FrameTransform  rotation: the body's forward and up axes equal Truth's/the estimate's q_nb axes in ENU;
//                   the first true translation is 0; |est - true| horizontally ~ the horizontal error
//   PoseInFrame     frame_id enu, position and orientation = the FrameTransform's of the same step (same body)
//   NavErrors       = run.h5 /error at the same step (rot_rad in degrees, hor_m, h_m, vn/ve, ...), gs_err from the
//                   velocities, gnss_denied = PositionEstimate.gnss_denied (and the run crosses the GNSS loss)
// Exit 0 when everything matches, 1 with the mismatches.
//
//   node check_viewer.mjs FILE.mcap EXPECTED.json
import { readFile } from "node:fs/promises";
import { parseIDL } from "@foxglove/omgidl-parser";
import { MessageReader } from "@foxglove/omgidl-serialization";
import { indexedReader, problemList } from "./mcap_file.mjs";

const [file, expectedFile] = process.argv.slice(2);
if (!file || !expectedFile) {
  console.error("usage: node check_viewer.mjs FILE.mcap EXPECTED.json");
  process.exit(2);
}
const expected = JSON.parse(await readFile(expectedFile, "utf8"));
const stepNs = BigInt(expected.step_ns);
const decimation = BigInt(expected.decimation);
const [problems, problem] = problemList();
const close = (a, b, tol) => typeof a === "number" && Math.abs(a - b) <= tol * Math.max(1, Math.abs(b));

const { reader, closeFile } = await indexedReader(file);

const viewerSchemas = {
  "/viewer/true/fix": "foxglove::LocationFix",
  "/viewer/est/fix": "foxglove::LocationFix",
  "/viewer/true/tf": "foxglove::FrameTransform",
  "/viewer/est/tf": "foxglove::FrameTransform",
  "/viewer/nav_errors": "gdnav::viewer::NavErrors",
  "/viewer/true/pose": "foxglove::PoseInFrame",
  "/viewer/est/pose": "foxglove::PoseInFrame",
};
const rawTopics = ["gdnav/Truth", "gdnav/PositionEstimate", "gdnav/AttitudeEstimate"];
const decoders = new Map();
for (const [id, channel] of reader.channelsById) {
  const schema = reader.schemasById.get(channel.schemaId);
  const want = viewerSchemas[channel.topic];
  if (!want && !rawTopics.includes(channel.topic)) continue;
  if (!schema) {
    problem(`${channel.topic}: no schema`);
    continue;
  }
  if (want && schema.name !== want) problem(`${channel.topic}: schema ${schema.name}, expected ${want}`);
  if (schema.encoding !== "omgidl" || channel.messageEncoding !== "cdr")
    problem(`${channel.topic}: ${schema.encoding}/${channel.messageEncoding}, expected omgidl/cdr`);
  const reader_ = new MessageReader(schema.name, parseIDL(new TextDecoder().decode(schema.data)));
  decoders.set(id, { topic: channel.topic, reader: reader_ });
}
for (const t of [...Object.keys(viewerSchemas), ...rawTopics])
  if (![...decoders.values()].some((d) => d.topic === t)) problem(`no channel ${t}`);

// Every message of these channels, decoded, by step.
const byTopic = new Map();
for await (const m of reader.readMessages({ validateCrcs: true })) {
  const d = decoders.get(m.channelId);
  if (!d) continue;
  let msg;
  try {
    msg = d.reader.readMessage(m.data);
  } catch (e) {
    problem(`${d.topic} at log time ${m.logTime}: cannot decode: ${e.message}`);
    continue;
  }
  if (m.logTime % stepNs !== 0n) problem(`${d.topic}: log time ${m.logTime} is not a step`);
  const step = m.logTime / stepNs;
  if (!byTopic.has(d.topic)) byTopic.set(d.topic, new Map());
  byTopic.get(d.topic).set(step, { msg, logTime: m.logTime });
}
await closeFile();
const at = (topic, step) => byTopic.get(topic)?.get(step)?.msg;

const deg = (rad) => (rad * 180) / Math.PI;
// Axes of a Hamilton quaternion's rotation matrix: columns 1 and 3 (body x and z) in the parent frame.
const xAxis = (w, x, y, z) => [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)];
const zAxis = (w, x, y, z) => [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)];
const nedToEnu = ([n, e, d]) => [e, n, -d];

function checkTimestamp(topic, step, entry) {
  const t = entry.msg.timestamp;
  if (BigInt(t.sec) * 1000000000n + BigInt(t.nsec) !== entry.logTime)
    problem(`${topic} step ${step}: timestamp ${t.sec}.${t.nsec}, log time ${entry.logTime}`);
  if (step % decimation !== 0n) problem(`${topic}: message at step ${step}, not a multiple of ${decimation}`);
}
function checkFix(topic, src, frame) {
  let n = 0;
  for (const [step, entry] of byTopic.get(topic) ?? []) {
    const f = entry.msg, s = at(src, step);
    checkTimestamp(topic, step, entry);
    if (!s) {
      problem(`${topic} step ${step}: no ${src} sample`);
      continue;
    }
    if (!close(f.latitude, deg(s.lat_rad), 1e-13) || !close(f.longitude, deg(s.lon_rad), 1e-13) || f.altitude !== s.h_m)
      problem(`${topic} step ${step}: (${f.latitude}, ${f.longitude}, ${f.altitude}) vs ${src} (${deg(s.lat_rad)}, ${deg(s.lon_rad)}, ${s.h_m})`);
    if (f.frame_id !== frame) problem(`${topic}: frame_id '${f.frame_id}'`);
    ++n;
  }
  return n;
}
function checkTf(topic, src, child) {
  let n = 0;
  for (const [step, entry] of byTopic.get(topic) ?? []) {
    const tf = entry.msg, s = at(src, step);
    checkTimestamp(topic, step, entry);
    if (!s) {
      problem(`${topic} step ${step}: no ${src} sample`);
      continue;
    }
    if (tf.parent_frame_id !== "enu" || tf.child_frame_id !== child)
      problem(`${topic}: frames ${tf.parent_frame_id} -> ${tf.child_frame_id}`);
    const r = tf.rotation, [w, x, y, z] = s.q_nb;
    const fwd = xAxis(r.w, r.x, r.y, r.z), up = zAxis(r.w, r.x, r.y, r.z);
    const fwdWant = nedToEnu(xAxis(w, x, y, z)), upWant = nedToEnu(zAxis(w, x, y, z)).map((v) => -v);
    for (let i = 0; i < 3; ++i)
      if (!close(fwd[i], fwdWant[i], 1e-12) || !close(up[i], upWant[i], 1e-12)) {
        problem(`${topic} step ${step}: axes fwd ${fwd} up ${up}, expected ${fwdWant} ${upWant}`);
        break;
      }
    ++n;
  }
  return n;
}

function checkPose(topic, tfTopic) {
  let n = 0;
  for (const [step, entry] of byTopic.get(topic) ?? []) {
    const p = entry.msg, tf = at(tfTopic, step);
    checkTimestamp(topic, step, entry);
    if (!tf) {
      problem(`${topic} step ${step}: no ${tfTopic} message`);
      continue;
    }
    if (p.frame_id !== "enu") problem(`${topic}: frame_id '${p.frame_id}'`);
    for (const k of ["x", "y", "z"])
      if (p.pose.position[k] !== tf.translation[k]) problem(`${topic} step ${step}: position.${k} ${p.pose.position[k]}, tf ${tf.translation[k]}`);
    for (const k of ["x", "y", "z", "w"])
      if (p.pose.orientation[k] !== tf.rotation[k]) problem(`${topic} step ${step}: orientation.${k} ${p.pose.orientation[k]}, tf ${tf.rotation[k]}`);
    ++n;
  }
  return n;
}

const counts = {};
counts.true_fix = checkFix("/viewer/true/fix", "gdnav/Truth", "body_true");
counts.est_fix = checkFix("/viewer/est/fix", "gdnav/PositionEstimate", "body_est");
counts.true_tf = checkTf("/viewer/true/tf", "gdnav/Truth", "body_true");
counts.est_tf = checkTf("/viewer/est/tf", "gdnav/AttitudeEstimate", "body_est");
counts.true_pose = checkPose("/viewer/true/pose", "/viewer/true/tf");
counts.est_pose = checkPose("/viewer/est/pose", "/viewer/est/tf");

// One message per decimated step of the run on every channel.
const wantCount = Number((BigInt(expected.steps) + decimation - 1n) / decimation);
for (const topic of Object.keys(viewerSchemas)) {
  const got = byTopic.get(topic)?.size ?? 0;
  if (got !== wantCount) problem(`${topic}: ${got} messages, expected ${wantCount}`);
}
const first = byTopic.get("/viewer/true/tf")?.get(0n)?.msg;
if (!first || first.translation.x !== 0 || first.translation.y !== 0 || first.translation.z !== 0)
  problem(`/viewer/true/tf step 0: translation ${JSON.stringify(first?.translation)}, expected the origin`);

// Navigation errors against run.h5 /error and the raw topics.
const fields = { att_err_deg: "rot_deg", yaw_err_deg: "yaw_deg", pitch_err_deg: "pitch_deg", bank_err_deg: "bank_deg",
  hor_err_m: "hor_m", cross_err_m: "cross_m", along_err_m: "along_m", alt_err_m: "h_m", vn_err_mps: "vn_mps",
  ve_err_mps: "ve_mps", tas_err_mps: "tas_mps" };
let compared = 0, denied = 0, maxHor = 0;
const rows = expected.errors;
for (const [step, entry] of byTopic.get("/viewer/nav_errors") ?? []) {
  const e = entry.msg, row = rows[String(step)];
  if (!row) {
    problem(`/viewer/nav_errors step ${step}: no run.h5 /error row`);
    continue;
  }
  for (const [name, key] of Object.entries(fields)) {
    const want = key.endsWith("_deg") ? deg(row[key.replace("_deg", "_rad")]) : row[key];
    if (!close(e[name], want, 1e-12)) problem(`/viewer/nav_errors step ${step} ${name}: ${e[name]}, run.h5 ${want}`);
    ++compared;
  }
  const p = at("gdnav/PositionEstimate", step), t = at("gdnav/Truth", step);
  const gs = Math.hypot(p.v_n_mps[0], p.v_n_mps[1]) - Math.hypot(t.v_n_mps[0], t.v_n_mps[1]);
  if (!close(e.gs_err_mps, gs, 1e-12)) problem(`/viewer/nav_errors step ${step} gs_err_mps: ${e.gs_err_mps}, expected ${gs}`);
  if (e.gnss_denied !== p.gnss_denied) problem(`/viewer/nav_errors step ${step}: gnss_denied ${e.gnss_denied}, estimate ${p.gnss_denied}`);
  if (!close(e.t_s, Number(expected.t0_s) + Number(step) * Number(expected.dt_s), 1e-12))
    problem(`/viewer/nav_errors step ${step}: t_s ${e.t_s}`);
  denied += e.gnss_denied ? 1 : 0;
  // The 3D offsets of the two frames agree with the horizontal error (exact ENU vs the metrics' radii at the
  // initial latitude: equal to 0.1 % + 5 cm over a few km).
  const a = at("/viewer/true/tf", step).translation, b = at("/viewer/est/tf", step).translation;
  const d = Math.hypot(b.x - a.x, b.y - a.y);
  if (Math.abs(d - e.hor_err_m) > 1e-3 * e.hor_err_m + 0.05)
    problem(`step ${step}: frames ${d} m apart horizontally, horizontal error ${e.hor_err_m} m`);
  maxHor = Math.max(maxHor, e.hor_err_m);
  compared += 3;
}
if (Object.keys(rows).length !== (byTopic.get("/viewer/nav_errors")?.size ?? 0))
  problem(`${byTopic.get("/viewer/nav_errors")?.size ?? 0} error messages, run.h5 has ${Object.keys(rows).length} rows`);
if (denied === 0 || denied === wantCount) problem(`gnss_denied is ${denied ? "always" : "never"} true: the run must cross the GNSS loss`);

console.log(`viewer channels: ${wantCount} messages each; fixes ${counts.true_fix}/${counts.est_fix}, transforms ` +
  `${counts.true_tf}/${counts.est_tf} checked against the raw topics, poses ${counts.true_pose}/${counts.est_pose} ` +
  `against the transforms; ${compared} error values against run.h5 and ` +
  `the raw topics; GNSS denied in ${denied} of ${wantCount}; largest horizontal error ${maxHor.toFixed(1)} m`);
if (problems.length) {
  console.log(`FAIL: ${problems.length} problem(s)`);
  for (const p of problems) console.log(`  ${p}`);
  process.exit(1);
}
console.log("PASS");
