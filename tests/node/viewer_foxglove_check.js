#!/usr/bin/env node
// Test-only: connects to a running viewer as a Foxglove client would (npm's @foxglove/ws-protocol
// FoxgloveClient over the `ws` package, subprotocol foxglove.websocket.v1), and decodes what it
// receives with the advertised schemas only (@foxglove/omgidl-parser and
// @foxglove/omgidl-serialization: no project code).
//
//   node viewer_foxglove_check.js --url ws://127.0.0.1:PORT/ --robot r1 --width W --height H
//        [--map NAME] [--timeout-s 60]
//
// Checks, printing one line each and a JSON summary last; exit code 0 when all hold, 1 otherwise:
//   - serverInfo comes first, then an advertise listing autonomy/robot/state with encoding cdr,
//     schemaEncoding omgidl, schemaName autonomy::RobotState and a schema that parses;
//   - subscribed, autonomy/robot/state messages decode with that schema: the robot's id, x and y
//     numbers inside the map (0..W, 0..H), a receive timestamp in nanoseconds near now, and the
//     robot at two different positions (it is driving);
//   - with --map NAME: a subscription to autonomy/map made after the first one gets the map at
//     once (transient-local state) and it decodes with the name NAME;
//   - after unsubscribing from the robot states, a new subscription to them gets messages again.
"use strict";
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const { WebSocket } = require("ws");
const { parseIDL } = require("@foxglove/omgidl-parser");
const { MessageReader } = require("@foxglove/omgidl-serialization");

function parseArgs(argv) {
  const out = { url: "", robot: "", width: NaN, height: NaN, map: "", timeoutS: 60 };
  for (let i = 2; i < argv.length; i++) {
    const a = argv[i], v = argv[i + 1];
    if (a === "--url") out.url = v;
    else if (a === "--robot") out.robot = v;
    else if (a === "--width") out.width = Number(v);
    else if (a === "--height") out.height = Number(v);
    else if (a === "--map") out.map = v;
    else if (a === "--timeout-s") out.timeoutS = Number(v);
    else { console.error(`viewer_foxglove_check: unknown argument ${a}`); process.exit(2); }
    i++;
  }
  if (!out.url || !out.robot || !(out.width > 0) || !(out.height > 0)) {
    console.error("viewer_foxglove_check: --url, --robot, --width and --height are required");
    process.exit(2);
  }
  return out;
}

const args = parseArgs(process.argv);
const failures = [];
const summary = { checks: 0, robot_messages: 0, positions: [] };
function check(cond, what) {
  summary.checks++;
  console.log(`${cond ? "ok" : "FAILED"}: ${what}`);
  if (!cond) failures.push(what);
  return cond;
}

function finish(code) {
  summary.failures = failures;
  console.log(JSON.stringify(summary));
  process.exit(code);
}

// The next event of the client that satisfies pred, in order.
function makeWaiter(client) {
  const queue = [];
  let wake = null;
  for (const name of ["serverInfo", "advertise", "message", "status", "error", "close"]) {
    client.on(name, (event) => {
      queue.push({ name, event });
      if (wake) wake();
    });
  }
  return async function next(pred) {
    for (;;) {
      const i = queue.findIndex(pred);
      if (i >= 0) return queue.splice(i, 1)[0];
      const closed = queue.find((e) => e.name === "close" || e.name === "error");
      if (closed) throw new Error(`connection ${closed.name}: ${closed.event && (closed.event.message || closed.event.code)}`);
      await new Promise((resolve) => (wake = resolve));
      wake = null;
    }
  };
}

async function main() {
  setTimeout(() => {
    check(false, `finished within ${args.timeoutS} s`);
    finish(1);
  }, args.timeoutS * 1000).unref();

  const ws = new WebSocket(args.url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const client = new FoxgloveClient({ ws });
  const next = makeWaiter(client);
  client.on("status", (s) => console.log(`status from the server: level ${s.level}: ${s.message}`));

  const first = await next((e) => e.name === "serverInfo" || e.name === "advertise");
  check(ws.protocol === FoxgloveClient.SUPPORTED_SUBPROTOCOL, `the server chose the subprotocol (${ws.protocol})`);
  check(first.name === "serverInfo", `serverInfo first (name "${first.event.name}")`);
  const { event: channels } = await next((e) => e.name === "advertise");
  summary.channels = channels.length;
  const byTopic = new Map(channels.map((c) => [c.topic, c]));
  const stateChannel = byTopic.get("autonomy/robot/state");
  if (!check(stateChannel !== undefined, `advertise lists autonomy/robot/state (${channels.length} channels)`)) finish(1);
  check(stateChannel.encoding === "cdr", `its encoding is cdr (${stateChannel.encoding})`);
  check(stateChannel.schemaEncoding === "omgidl", `its schema encoding is omgidl (${stateChannel.schemaEncoding})`);
  check(stateChannel.schemaName === "autonomy::RobotState", `its schema name (${stateChannel.schemaName})`);
  const readerOf = (channel) => new MessageReader(channel.schemaName, parseIDL(channel.schema));
  let stateReader;
  try {
    stateReader = readerOf(stateChannel);
    check(true, "the advertised IDL parses");
  } catch (e) {
    check(false, `the advertised IDL parses: ${e.message}`);
    finish(1);
  }

  // Robot states: decoded with the advertised schema only.
  const nowNs = () => BigInt(Date.now()) * 1000000n;
  const awaitRobot = async (subscription, wanted) => {
    const seen = [];
    while (seen.length < wanted) {
      const { event: m } = await next((e) => e.name === "message" && e.event.subscriptionId === subscription);
      const bytes = new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength);
      const state = stateReader.readMessage(bytes);
      summary.robot_messages++;
      if (state.robot_id !== args.robot) continue;
      if (seen.length === 0) {
        check(typeof state.x === "number" && typeof state.y === "number", `x and y are numbers (${state.x}, ${state.y})`);
        check(state.x >= 0 && state.x <= args.width && state.y >= 0 && state.y <= args.height,
              `${args.robot} is inside the ${args.width} x ${args.height} m map`);
        const skew = Number(nowNs() - m.timestamp) / 1e9;
        check(Math.abs(skew) < 60, `the receive timestamp is ns since the epoch (${skew.toFixed(3)} s ago)`);
      }
      seen.push([state.x, state.y]);
    }
    return seen;
  };
  const sub1 = client.subscribe(stateChannel.id);
  const firstSeen = (await awaitRobot(sub1, 1))[0];
  summary.positions.push(firstSeen);
  check(true, `${args.robot} decoded at (${firstSeen[0].toFixed(3)}, ${firstSeen[1].toFixed(3)})`);
  // It drives: a later state at another position.
  for (;;) {
    const [p] = await awaitRobot(sub1, 1);
    if (Math.hypot(p[0] - firstSeen[0], p[1] - firstSeen[1]) > 0.05) {
      summary.positions.push(p);
      check(true, `${args.robot} decoded again at another position (${p[0].toFixed(3)}, ${p[1].toFixed(3)})`);
      break;
    }
  }

  if (args.map) {
    const mapChannel = byTopic.get("autonomy/map");
    if (check(mapChannel !== undefined, "advertise lists autonomy/map")) {
      const subMap = client.subscribe(mapChannel.id);
      const { event: m } = await next((e) => e.name === "message" && e.event.subscriptionId === subMap);
      const map = readerOf(mapChannel).readMessage(new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength));
      check(map.name === args.map, `the map's transient-local state arrives on subscribing: "${map.name}"`);
    }
  }

  client.unsubscribe(sub1);
  const sub2 = client.subscribe(stateChannel.id);
  check(sub2 !== sub1, `subscribed again as ${sub2} after unsubscribing ${sub1}`);
  const [again] = await awaitRobot(sub2, 1);
  check(true, `robot states arrive on the new subscription (${again[0].toFixed(3)}, ${again[1].toFixed(3)})`);

  client.close();
  finish(failures.length === 0 ? 0 : 1);
}

main().catch((e) => {
  check(false, `no error: ${e.stack || e}`);
  finish(1);
});
