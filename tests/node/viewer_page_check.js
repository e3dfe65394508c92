#!/usr/bin/env node
// Test-only: loads the viewer's page in headless Chromium (Debian's chromium package) and checks
// what a person would see. Speaks the Chrome DevTools Protocol over --remote-debugging-pipe (fd 3
// in, fd 4 out, messages ended by NUL), so it needs no npm package and no WebSocket in node.
//
//   node viewer_page_check.js --url http://127.0.0.1:PORT/ [--chromium /usr/bin/chromium]
//        [--door ID] [--job ID] [--plan REQUESTER:TOKENS] [--executed EXECUTIVE:TOKENS]
//        [--screenshot FILE.png] [--timeout-s 60]
//
// Checks, printing one line each and a JSON summary last; exit code 0 when all hold, 1 otherwise:
//   - the page loads and receives frames without console errors or uncaught exceptions;
//   - a robot's drawn position changes between two reads of the page's state;
//   - with --door ID: the door is drawn closed (the page's state says closed and the canvas pixel
//     at the middle of its leaf has the closed leaf's colour);
//   - with --job ID: the courier job's state shown in the jobs table changes (the check prints
//     "job ID seen: STATE" when it first shows, so a test can then change the state);
//   - with --plan REQUESTER:TOKENS: the requester's latest plan is drawn as a timeline with that
//     many token bars, and the canvas pixel in the middle of each bar is painted (not the
//     white background);
//   - with --executed EXECUTIVE:TOKENS: the executive's planned-against-executed chart draws its
//     current plan's bars and that many executed-token bars, the middle pixel of each painted
//     (not the row's grey or white background), and the mouse over the first one names it; the
//     JSON lists each bar (running or not) and that tooltip.
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

function parseArgs(argv) {
  const out = { chromium: "/usr/bin/chromium", door: "", job: "", plan: "", executed: "", screenshot: "", timeoutS: 60, url: "" };
  for (let i = 2; i < argv.length; i++) {
    const a = argv[i], v = argv[i + 1];
    if (a === "--url") out.url = v;
    else if (a === "--chromium") out.chromium = v;
    else if (a === "--door") out.door = v;
    else if (a === "--job") out.job = v;
    else if (a === "--plan") out.plan = v;
    else if (a === "--executed") out.executed = v;
    else if (a === "--screenshot") out.screenshot = v;
    else if (a === "--timeout-s") out.timeoutS = Number(v);
    else { console.error(`viewer_page_check: unknown argument ${a}`); process.exit(2); }
    i++;
  }
  if (!out.url) { console.error("viewer_page_check: --url is required"); process.exit(2); }
  return out;
}

const sleep = ms => new Promise(r => setTimeout(r, ms));

class DevTools {
  constructor(child) {
    this.next = 1;
    this.waiting = new Map();
    this.listeners = [];
    this.input = child.stdio[3];
    let pending = "";
    child.stdio[4].on("data", chunk => {
      pending += chunk.toString("utf8");
      let end;
      while ((end = pending.indexOf("\0")) >= 0) {
        const msg = JSON.parse(pending.slice(0, end));
        pending = pending.slice(end + 1);
        if (msg.id && this.waiting.has(msg.id)) {
          const { resolve, reject } = this.waiting.get(msg.id);
          this.waiting.delete(msg.id);
          if (msg.error) reject(new Error(JSON.stringify(msg.error))); else resolve(msg.result);
        } else if (msg.method) {
          for (const l of this.listeners) l(msg);
        }
      }
    });
  }
  send(method, params = {}, sessionId = undefined) {
    const id = this.next++;
    const msg = { id, method, params };
    if (sessionId) msg.sessionId = sessionId;
    this.input.write(JSON.stringify(msg) + "\0");
    return new Promise((resolve, reject) => this.waiting.set(id, { resolve, reject }));
  }
  on(listener) { this.listeners.push(listener); }
}

async function main() {
  const args = parseArgs(process.argv);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), "viewer-chromium-"));
  const child = spawn(args.chromium, [
    "--headless=new", "--remote-debugging-pipe", "--no-sandbox", "--disable-gpu", "--no-first-run",
    "--no-default-browser-check", "--disable-extensions", "--disable-background-networking",
    "--window-size=1280,800", `--user-data-dir=${profile}`, "about:blank"],
    { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
  let chromiumErr = "";
  child.stderr.on("data", d => { chromiumErr += d.toString(); });
  const results = [];
  const check = (name, ok, detail) => { results.push({ name, ok, detail }); console.log(`${ok ? "ok  " : "FAIL"} ${name}: ${detail}`); };
  const deadline = Date.now() + args.timeoutS * 1000;
  try {
    const cdp = new DevTools(child);
    const { targetId } = await cdp.send("Target.createTarget", { url: "about:blank" });
    const { sessionId } = await cdp.send("Target.attachToTarget", { targetId, flatten: true });
    const problems = [];
    cdp.on(msg => {
      if (msg.sessionId !== sessionId) return;
      if (msg.method === "Runtime.exceptionThrown") {
        const d = msg.params.exceptionDetails;
        problems.push(`exception: ${d.exception ? d.exception.description : d.text}`);
      } else if (msg.method === "Runtime.consoleAPICalled" && msg.params.type === "error") {
        problems.push(`console.error: ${msg.params.args.map(a => a.value || a.description).join(" ")}`);
      } else if (msg.method === "Log.entryAdded" && msg.params.entry.level === "error") {
        problems.push(`log: ${msg.params.entry.text} ${msg.params.entry.url || ""}`);
      }
    });
    await cdp.send("Runtime.enable", {}, sessionId);
    await cdp.send("Log.enable", {}, sessionId);
    await cdp.send("Page.enable", {}, sessionId);
    await cdp.send("Page.navigate", { url: args.url }, sessionId);
    const evaluate = async expression => {
      const r = await cdp.send("Runtime.evaluate", { expression, returnByValue: true }, sessionId);
      if (r.exceptionDetails) throw new Error(`evaluate ${expression}: ${r.exceptionDetails.text}`);
      return r.result.value;
    };
    const waitFor = async (what, expression) => {
      while (Date.now() < deadline) {
        const v = await evaluate(expression).catch(() => null);
        if (v) return v;
        await sleep(200);
      }
      throw new Error(`timed out waiting for ${what}`);
    };

    await waitFor("the map and a state with a robot",
      "window.viewer && viewer.map && viewer.map.known && viewer.state && viewer.state.robots.length > 0");
    const robotsNow = "JSON.stringify(viewer.state.robots.map(r => [r.id, r.x, r.y]))";
    const first = JSON.parse(await evaluate(robotsNow));
    let moved = null;
    while (!moved && Date.now() < deadline) {
      await sleep(500);
      const now = JSON.parse(await evaluate(robotsNow));
      for (const [id, x, y] of now) {
        const before = first.find(r => r[0] === id);
        if (before && Math.hypot(x - before[1], y - before[2]) > 0.05) moved = `${id} from (${before[1]}, ${before[2]}) to (${x}, ${y})`;
      }
    }
    check("robot drawn at a new position", !!moved, moved || `no robot moved: ${JSON.stringify(first)}`);

    if (args.door) {
      const id = JSON.stringify(args.door);
      const pixel = await waitFor(`door ${args.door} closed`, `(() => {
        const d = viewer.state.doors.find(d => d.id === ${id});
        if (!d || !d.closed || !d.leaf) return null;
        const [sx, sy] = toScreen((d.leaf[0] + d.leaf[2]) / 2, (d.leaf[1] + d.leaf[3]) / 2);
        const p = document.getElementById("map").getContext("2d").getImageData(Math.round(sx), Math.round(sy), 1, 1).data;
        return [p[0], p[1], p[2]];
      })()`).catch(e => e.message);
      // The closed leaf is drawn #a00 (170, 0, 0); allow for anti-aliasing.
      const ok = Array.isArray(pixel) && pixel[0] > 120 && pixel[1] < 60 && pixel[2] < 60;
      check(`door ${args.door} drawn closed`, ok, `leaf pixel ${JSON.stringify(pixel)}`);
    }

    if (args.job) {
      // What a person reads: the state badge in the job's row of the table.
      const shownState = `(() => {
        const row = [...document.querySelectorAll("tr[data-job]")].find(r => r.dataset.job === ${JSON.stringify(args.job)});
        return row ? row.querySelector(".st").textContent : null;
      })()`;
      const first = await waitFor(`job ${args.job} in the table`, shownState).catch(e => null);
      console.log(`job ${args.job} seen: ${first}`);
      let later = first;
      while (first && later === first && Date.now() < deadline) {
        await sleep(200);
        later = await evaluate(shownState);
      }
      check(`job ${args.job} state change drawn`, !!first && later !== first, `${first} -> ${later}`);
    }

    if (args.plan) {
      const at = args.plan.lastIndexOf(":");
      const requester = args.plan.slice(0, at), tokens = Number(args.plan.slice(at + 1));
      const drawn = await waitFor(`the plan of ${requester} as a timeline`, `(() => {
        const c = [...document.querySelectorAll("canvas.plan-timeline")].find(c => c.dataset.requester === ${JSON.stringify(requester)});
        if (!c || !c.bars || !c.bars.length) return null;
        const g = c.getContext("2d");
        return c.bars.map(b => {
          const p = g.getImageData(Math.round(b.x + b.w / 2), Math.round(b.y + b.h / 2), 1, 1).data;
          return { predicate: b.predicate, filled: p[3] > 0 && !(p[0] > 240 && p[1] > 240 && p[2] > 240) };
        });
      })()`).catch(e => e.message);
      const ok = Array.isArray(drawn) && drawn.length === tokens && drawn.every(b => b.filled);
      check(`plan of ${requester} drawn as a timeline of ${tokens} tokens`, ok, JSON.stringify(drawn));
    }

    if (args.executed) {
      const at = args.executed.lastIndexOf(":");
      const executive = args.executed.slice(0, at), tokens = Number(args.executed.slice(at + 1));
      const painted = "p[3] > 0 && !(p[0] > 235 && p[1] > 235 && p[2] > 235)";
      const drawn = await waitFor(`${tokens} executed tokens of ${executive}`, `(() => {
        const c = [...document.querySelectorAll("canvas.execution")].find(c => c.dataset.executive === ${JSON.stringify(executive)});
        if (!c || !c.executed || c.executed.length < ${tokens} || !c.planned.length) return null;
        const g = c.getContext("2d"), mid = b => g.getImageData(Math.round(b.x + b.w / 2), Math.round(b.y + b.h / 2), 1, 1).data;
        // The mouse over the first executed bar names it (the chart's tooltip).
        const r = c.getBoundingClientRect(), b0 = c.executed[0];
        c.dispatchEvent(new MouseEvent("mousemove", { bubbles: true, clientX: r.left + b0.x + b0.w / 2, clientY: r.top + b0.y + b0.h / 2 }));
        return { planned: c.planned.map(b => { const p = mid(b); return ${painted}; }), hover: c.title,
                 executed: c.executed.map(b => { const p = mid(b); return { token: b.token, running: b.running, filled: ${painted} }; }) };
      })()`).catch(e => e.message);
      const ok = drawn && Array.isArray(drawn.executed) && drawn.executed.length === tokens &&
                 drawn.executed.every(b => b.filled) && drawn.planned.length > 0 && drawn.planned.every(f => f) &&
                 drawn.hover.includes(" #" + drawn.executed[0].token + ":");
      check(`${executive}'s plan drawn against ${tokens} executed tokens`, !!ok, JSON.stringify(drawn));
    }

    if (args.screenshot) {
      await sleep(300);
      const shot = await cdp.send("Page.captureScreenshot", { format: "png" }, sessionId);
      fs.writeFileSync(args.screenshot, Buffer.from(shot.data, "base64"));
      console.log(`screenshot: ${args.screenshot}`);
    }
    const frames = await evaluate("viewer.frames");
    check("no console errors or exceptions", problems.length === 0, problems.length ? problems.join("; ") : `${frames} frames received`);
    await cdp.send("Browser.close").catch(() => {});
  } catch (e) {
    check("page check ran", false, `${e.message}${chromiumErr ? "; chromium: " + chromiumErr.slice(-500) : ""}`);
  } finally {
    // Chromium's helpers may still write into the profile: remove it once the browser ended.
    const ended = child.exitCode !== null || child.signalCode !== null
      ? Promise.resolve() : new Promise(resolve => child.once("exit", resolve));
    child.kill("SIGKILL");
    await Promise.race([ended, sleep(5000)]);
    try { fs.rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 200 }); }
    catch (e) { console.log(`note: could not remove ${profile}: ${e.message}`); }
  }
  const ok = results.every(r => r.ok);
  console.log(JSON.stringify({ ok, results }));
  process.exit(ok ? 0 : 1);
}

main();
