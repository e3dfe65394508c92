// Reads an MCAP recording made by `autonomy record` with independent readers (npm's @mcap/core
// and @foxglove/omgidl-serialization, not the project's code) and checks it:
//   - the file: magic, summary CRC (indexed reader), every chunk CRC, the data section CRC
//     (recomputed here over the bytes before the Data End record), summary statistics;
//   - every message decodes with its channel's embedded OMG IDL schema (message encoding cdr);
//   - the expectations in EXPECT.json: exact counts per topic, minimum counts, and values of
//     selected messages (see tests/integration/recording_test.cpp, which writes it).
// Usage: node validate_recording.js FILE.mcap EXPECT.json     exit 0 = valid, 1 = a check failed
"use strict";
const fs = require("fs");
const { McapIndexedReader, McapStreamReader } = require("@mcap/core");
const { loadDecompressHandlers } = require("@mcap/support");
const { parseIDL } = require("@foxglove/omgidl-parser");
const { MessageReader } = require("@foxglove/omgidl-serialization");
const { crc32 } = require("@foxglove/crc");

const failures = [];
function check(cond, what) {
  if (!cond) failures.push(what);
}
function field(obj, path) {
  return path.split(".").reduce((o, k) => (o == undefined ? undefined : o[k]), obj);
}
function matches(msg, match) {
  return Object.entries(match || {}).every(([k, v]) => field(msg, k) === v);
}
function near(a, b) {
  return typeof b === "number" ? Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(b)) : a === b;
}

async function main() {
  const [file, expectFile] = process.argv.slice(2);
  if (!file || !expectFile) throw new Error("usage: node validate_recording.js FILE.mcap EXPECT.json");
  const expect = JSON.parse(fs.readFileSync(expectFile, "utf8"));
  const buf = fs.readFileSync(file);
  const decompressHandlers = await loadDecompressHandlers();

  // Indexed reading: footer, summary (its CRC), chunk indexes, statistics; chunk CRCs on read.
  const readable = {
    size: async () => BigInt(buf.length),
    read: async (offset, length) => buf.subarray(Number(offset), Number(offset + length)),
  };
  const indexed = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  check(indexed.footer.summaryCrc !== 0, "the footer carries no summary CRC");

  // Linear reading of every record (chunk CRCs validated), and the data section CRC.
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(buf);
  const recordCounts = {};
  let dataEnd;
  let record;
  while ((record = stream.nextRecord())) {
    recordCounts[record.type] = (recordCounts[record.type] || 0) + 1;
    if (record.type === "DataEnd") dataEnd = record;
  }
  check(stream.done(), "the stream reader did not reach the end of the file");
  check(dataEnd !== undefined, "no Data End record");
  const dataEndOffset = Number(indexed.footer.summaryStart) - (1 + 8 + 4);
  check(buf[dataEndOffset] === 0x0f, `no Data End record at byte ${dataEndOffset}`);
  const dataCrc = crc32(buf.subarray(0, dataEndOffset));
  check(dataEnd && dataEnd.dataSectionCrc === dataCrc,
        `data section CRC: file says ${dataEnd && dataEnd.dataSectionCrc}, computed ${dataCrc}`);

  // Every message, decoded with its embedded schema.
  const readers = new Map();
  const decoded = {};  // topic -> [message]
  let total = 0;
  for (const [id, channel] of indexed.channelsById) {
    const schema = indexed.schemasById.get(channel.schemaId);
    check(schema && schema.encoding === "omgidl", `channel ${channel.topic}: schema encoding is not omgidl`);
    check(channel.messageEncoding === "cdr", `channel ${channel.topic}: message encoding ${channel.messageEncoding}`);
    check(channel.metadata.get("reliability") !== undefined, `channel ${channel.topic}: no QoS in its metadata`);
    const text = new TextDecoder().decode(schema.data);
    check(!/^\s*#\s*include/m.test(text), `schema ${schema.name} is not self-contained (#include)`);
    readers.set(id, new MessageReader(schema.name, parseIDL(text)));
    decoded[channel.topic] = [];
  }
  let lastLogTime = 0n;
  for await (const m of indexed.readMessages()) {
    const channel = indexed.channelsById.get(m.channelId);
    let value;
    try {
      value = readers.get(m.channelId).readMessage(m.data);
    } catch (e) {
      failures.push(`${channel.topic} message ${m.sequence}: does not decode: ${e.message}`);
      continue;
    }
    check(m.logTime >= lastLogTime, `${channel.topic}: log times out of order`);
    lastLogTime = m.logTime;
    check(m.publishTime > 0n, `${channel.topic}: no publish time`);
    decoded[channel.topic].push(value);
    total++;
  }
  check(BigInt(total) === indexed.statistics.messageCount,
        `statistics say ${indexed.statistics.messageCount} messages, read ${total}`);
  check(recordCounts.Message === total, `stream reader saw ${recordCounts.Message} messages, indexed reader ${total}`);

  for (const [topic, n] of Object.entries(expect.counts || {}))
    check((decoded[topic] || []).length === n, `${topic}: ${(decoded[topic] || []).length} messages, expected ${n}`);
  for (const [topic, n] of Object.entries(expect.min_counts || {}))
    check((decoded[topic] || []).length >= n, `${topic}: ${(decoded[topic] || []).length} messages, expected at least ${n}`);
  for (const v of expect.values || []) {
    const found = (decoded[v.topic] || []).filter((m) => matches(m, v.match));
    check(found.length > 0, `${v.topic}: no message with ${JSON.stringify(v.match)}`);
    const pick = v.last ? found[found.length - 1] : found[0];
    for (const [k, want] of Object.entries(v.expect || {}))
      if (pick) check(near(field(pick, k), want), `${v.topic} ${JSON.stringify(v.match)}: ${k} = ${field(pick, k)}, expected ${want}`);
  }
  for (const s of expect.sequences || []) {
    const got = (decoded[s.topic] || []).filter((m) => matches(m, s.match)).map((m) => field(m, s.field));
    check(JSON.stringify(got) === JSON.stringify(s.values),
          `${s.topic} ${JSON.stringify(s.match)}: ${s.field} sequence ${JSON.stringify(got)}, expected ${JSON.stringify(s.values)}`);
  }

  const topics = Object.keys(decoded).length;
  console.log(`validate_recording: ${file}: ${total} messages on ${topics} topics, ${indexed.chunkIndexes.length} chunks; ` +
              `summary, chunk and data CRCs checked; every message decoded with its embedded IDL schema`);
  if (failures.length > 0) {
    for (const f of failures) console.error(`validate_recording: FAIL: ${f}`);
    process.exit(1);
  }
  // Exit now rather than when the event loop drains: once, in CI's sanitizer run, the script had
  // printed this line and was still running 120 s later (not reproduced; 0.5-0.6 s otherwise).
  process.exit(0);
}

main().catch((e) => {
  console.error(`validate_recording: FAIL: ${e.stack || e}`);
  process.exit(1);
});
