#include "bench/executive_replan_paced.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include <unistd.h>

#include "bench/bench_support.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"

namespace autonomy::bench {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

void replace_once(std::string& text, const std::string& from, const std::string& to, const std::string& file) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error(file + " has no '" + from + "'");
  text.replace(at, from.size(), to);
}

// ds1.model with room for `blocks` DSN passes (its pass parameters stop at 24, one day).
std::string model_for(const std::string& repo, const std::string& folder, int blocks) {
  const std::string file = repo + "/services/planner/examples/ds1.model";
  std::string text = read_text(file);
  const std::string range = "pass: int[1, 24]";
  for (int i = 0; i < 2; ++i) replace_once(text, range, "pass: int[1, " + std::to_string(blocks) + "]", file);
  const std::string out = folder + "/ds1-" + std::to_string(blocks) + "-blocks.model";
  write_text(out, text);
  return out;
}

// The blocks of services/planner/examples/ds1_day.py (without the optional science images):
// per two-hour block a DSN schedule (hidden, then a 40-minute pass), a thrust arc in its first
// hour, four optical-navigation pictures before the pass and a downlink in it.
std::string problem_for(const std::string& folder, int blocks) {
  const char* imaging[] = {"braille", "annefrank", "eros", "vesta", "ceres", "ida", "gaspra", "mathilde"};
  const long block = 7200, pass = 2400;
  std::ostringstream out;
  out << "// " << blocks * 2 << " hours of DS1-like cruise (executive_replan_bench --paced)\n"
      << "problem ds1_" << blocks << "_blocks\nhorizon " << block * blocks << "\nobject dsone : Spacecraft\n"
      << "initial dsone.attitude == pointAt(earth)\ninitial dsone.camera == ready\ninitial dsone.engine == off\n";
  for (int k = 0; k < blocks; ++k) {
    const long t0 = k * block, rise = t0 + block - pass, end = t0 + block;
    const int p = k + 1;
    out << "goal hidden" << p << ": dsone.dsn == hidden() start [" << t0 << ", " << t0 << "] end [" << rise << ", "
        << rise << "]\n";
    out << "goal pass" << p << ": dsone.dsn == inView(" << p << ") start [" << rise << ", " << rise << "] end [" << end
        << ", " << end << "]\n";
    // The first arc starts in the first minute and may last a minute (ds1_day.py: within the first hour, 40
    // minutes at least), so that the engine stuck on at its end shows a minute after the start.
    out << "goal thrust" << p << ": dsone.engine == thrusting(" << 1 + k % 3 << ") start [" << t0 << ", "
        << (k == 0 ? t0 + 60 : t0 + 3600) << "] duration [" << (k == 0 ? 60 : 2400) << ", 3000]\n";
    for (int i = 0; i < 4; ++i)
      out << "goal nav" << p << "_" << i + 1 << ": dsone.camera == picture(" << imaging[(4 * k + i) % 8] << ") start ["
          << t0 << ", " << rise << "] end [0, " << rise << "]\n";
    out << "goal down" << p << ": dsone.radio == downlink(" << p << ") start [" << rise << ", " << end << "]\n";
  }
  const std::string file = folder + "/ds1-" + std::to_string(blocks) + "-blocks.problem";
  write_text(file, out.str());
  return file;
}

// services/executive/examples/ds1.pbtxt with this model and problem and plans of horizon_s.
std::string config_for(const std::string& repo, const std::string& folder, const std::string& model,
                       const std::string& problem, long horizon_s) {
  const std::string file = repo + "/services/executive/examples/ds1.pbtxt";
  std::istringstream in(read_text(file));
  std::ostringstream out;
  int replaced = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model:", 0) == 0) line = "model: \"" + model + "\"", ++replaced;
    else if (line.rfind("problem:", 0) == 0) line = "problem: \"" + problem + "\"", ++replaced;
    else if (line.rfind("horizon_s:", 0) == 0) line = "horizon_s: " + std::to_string(horizon_s), ++replaced;
    // A plan of 1,000 tokens takes the planner 0.5 to 3 s here: not cut short at 2 s.
    else if (line.rfind("planner_budget_ms:", 0) == 0) line = "planner_budget_ms: 10000", ++replaced;
    out << line << "\n";
  }
  if (replaced != 4)
    throw std::runtime_error(file + ": expected one model, problem, horizon_s and planner_budget_ms line each");
  const std::string config = folder + "/ds1-" + std::to_string(horizon_s) + "s.pbtxt";
  write_text(config, out.str());
  return config;
}

double between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// The ion engine stuck on at its first arc (docs/spacecraft.md: `stuck_on` on ips), switched on in
// ds1.pbtxt's scenario in paced time at `warp`. Not the camera of the lockstep bench: without
// pictures no downlink can be planned (each consumes stored data), and the planner's search for
// which goals to leave out of a multi-block replan runs out of its budget (measured: the 8-hour
// replan after the camera fault, 2 s, no plan). The engine's arcs are lost; pictures, turns, DSN
// schedule and downlinks stay: about 21 tokens per block.
std::string scenario_with_stuck_engine(const std::string& repo, const std::string& folder, double warp) {
  const std::string file = repo + "/deploy/scenarios/ds1.pbtxt";
  std::string text = read_text(file);
  replace_once(text, "# faults { id: \"ips-unconfirmed\"",
               "faults { id: \"ips-stuck-on\" kind: STUCK_ON subject: \"ips\" on_command: \"ips thrust\" }\n"
               "  # faults { id: \"ips-unconfirmed\"",
               file);
  std::ostringstream paced;
  paced << "simulation { mode: PACED warp: " << warp;
  replace_once(text, "simulation { mode: LOCKSTEP", paced.str(), file);
  const std::string out = folder + "/ds1-ips-stuck-paced.pbtxt";
  write_text(out, text);
  return out;
}

// One flight's stages, wall seconds as seen from here (each process's samples stamped on arrival).
struct Flight {
  std::size_t first_tokens = 0, replan_tokens = 0;
  double first_plan = -1;       // first horizon: request -> plan executing (from scratch)
  double detection = -1;        // the arc's end tick (engine should be in standby) -> the abort's tick
  double safing = -1;           // the abort's tick -> the safing command (ips standby) on the bus
  double request = -1;          // the abort's tick -> the request on the bus (after a turn under way)
  bool settled = false;         // the request waited for a turn under way to end
  double planner = -1;          // request -> reply (DDS both ways and the planner's search)
  double search = -1;           // the planner's own search time (its reply's statistics)
  double splice = -1;           // reply -> plan executing (the executive: dispatchable form, start)
  double first_tick = -1;       // plan executing -> the next tick (dispatched with the new plan)
  double total = -1;            // the arc's end tick -> that tick
  double from_request = -1;     // the request on the bus -> that tick
  double executive_own = -1;    // the executive's own figure: abort -> plan executing
  int aborts = 0, violations = 0;  // counted until 3 s (wall) after the new plan's first tick
};

Flight fly(const PacedOptions& o, const std::string& config, const std::string& scenario, const std::string& log) {
  const std::string bin = self_dir(), dom = std::to_string(o.domain);
  dds::Participant participant(o.domain);
  dds::Topic<msg::ExecutiveEvent> event_topic(participant, dds::topics::executive_event);
  dds::Reader<msg::ExecutiveEvent> events(participant, event_topic);
  dds::Topic<msg::SimClock> clock_topic(participant, dds::topics::clock);
  dds::Reader<msg::SimClock> clock(participant, clock_topic);
  dds::Topic<msg::PlanningReply> reply_topic(participant, dds::topics::planner_reply);
  dds::Reader<msg::PlanningReply> replies(participant, reply_topic);
  dds::Topic<msg::SpacecraftCommand> command_topic(participant, dds::topics::spacecraft_command);
  dds::Reader<msg::SpacecraftCommand> commands(participant, command_topic);
  ChildProcess planner({bin + "/planner", "--domain", dom, "--log-dir", o.folder}, false, log + "-planner.out");
  ChildProcess executive({bin + "/executive", "--domain", dom, "--log-dir", o.folder, "--config", config,
                          "--plan-timeout-s", "15"},
                         false,
                         log + "-executive.out");
  ChildProcess simulator({bin + "/simulator", "--domain", dom, "--log-dir", o.folder, "--config", scenario}, false,
                         log + "-simulator.out");

  std::map<std::int64_t, Clock::time_point> tick_at;  // first arrival of each tick
  std::vector<std::pair<Clock::time_point, msg::PlanningReply>> replies_seen;
  std::optional<Clock::time_point> first_asked, abort_seen, requested, executing, safed, done;
  std::optional<std::int64_t> fault_tick, abort_tick, executing_tick;
  Flight f;
  const std::regex own("executing ([0-9.]+) s \\(wall\\) after the fault");
  const auto t0 = Clock::now();
  while (seconds_since(t0) < 120 && !(done && between(*done, Clock::now()) > 3)) {
    const auto now = Clock::now();
    for (auto& s : clock.take())
      if (s.valid) tick_at.emplace(s.value.tick, now);
    for (auto& s : replies.take())
      if (s.valid) replies_seen.emplace_back(now, std::move(s.value));
    for (auto& s : commands.take())
      if (s.valid && abort_seen && !safed && s.value.device == "ips" && s.value.command == "standby") safed = now;
    for (auto& s : events.take()) {
      if (!s.valid) continue;
      const msg::ExecutiveEvent& e = s.value;
      if (e.kind == "plan_requested" && !first_asked) first_asked = now;
      if (e.kind == "plan_executing" && f.first_plan < 0 && first_asked && !abort_seen)
        f.first_plan = between(*first_asked, now);
      if (e.kind == "ended" && !abort_seen && !fault_tick && e.text.find("dsone.engine == thrusting(") == 0)
        fault_tick = e.tick;
      if (e.kind == "aborted") {
        ++f.aborts;
        if (!abort_seen) abort_seen = now, abort_tick = e.tick;
      }
      if (e.kind == "violation" && abort_seen) ++f.violations;
      if (e.kind == "settling" && abort_seen && !requested) f.settled = true;
      if (e.kind == "plan_requested" && abort_seen && !requested) requested = now;
      std::smatch m;
      if (e.kind == "plan_executing" && !executing && std::regex_search(e.text, m, own)) {
        executing = now;
        executing_tick = e.tick;
        f.executive_own = std::stod(m[1]);
      }
    }
    if (executing && !done) {
      const auto next = tick_at.upper_bound(*executing_tick);
      // A tick sent while the executive was starting the plan may be seen here first: it is
      // stepped with the new plan once the plan executes.
      if (next != tick_at.end()) done = std::max(next->second, *executing);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (!replies_seen.empty()) f.first_tokens = replies_seen.front().second.plan.tokens.size();
  if (!fault_tick || !abort_tick || !requested || !executing || !done || !tick_at.count(*fault_tick) ||
      !tick_at.count(*abort_tick))
    return f;
  const auto fault_at = tick_at[*fault_tick], abort_at = tick_at[*abort_tick];
  f.detection = between(fault_at, abort_at);
  if (safed) f.safing = between(abort_at, *safed);
  f.request = between(abort_at, *requested);
  // The executed reply: the last one before the plan executed (a request asked again has
  // several; the planner answers them in order).
  std::optional<Clock::time_point> replied;
  for (const auto& [at, r] : replies_seen) {
    if (at >= *requested && at <= *executing) {
      replied = at;
      f.replan_tokens = r.plan.tokens.size();
      f.search = r.statistics.elapsed_ms / 1000.0;
    }
  }
  if (replied) {
    f.planner = between(*requested, *replied);
    f.splice = between(*replied, *executing);
  }
  f.first_tick = between(*executing, *done);
  f.total = between(fault_at, *done);
  f.from_request = between(*requested, *done);
  return f;
}

}  // namespace

int run_paced(const PacedOptions& o) {
  const int blocks = o.large_blocks + 1;  // one block more than the large plan: its replan ends early
  const std::string model = model_for(o.repo, o.folder, blocks);
  const std::string problem = problem_for(o.folder, blocks);
  const std::string scenario = scenario_with_stuck_engine(o.repo, o.folder, o.warp);
  const int sizes[] = {o.small_blocks, o.large_blocks};
  std::printf("executive_replan_bench --paced: DS1-like blocks in plans of %d and %d blocks, ion engine stuck on at "
              "its first arc, paced at warp %.0f (1 s ticks every %.0f ms), %d run(s) each\n",
              o.small_blocks, o.large_blocks, o.warp, 1000.0 / o.warp, o.runs);
  std::printf("%6s %4s %6s %6s %7s %7s %8s %8s %7s %7s %6s %7s %8s %8s %5s\n", "blocks", "run", "first", "tokens",
              "detect", "safing", "request", "planner", "search", "splice", "tick", "total", "from req", "exec own",
              "broke");
  std::map<int, std::vector<Flight>> flights;
  bool all = true;
  for (int run = 0; run < o.runs; ++run)
    for (int size : sizes) {
      progress("executive_replan_bench --paced: %d blocks, run %d of %d\n", size, run + 1, o.runs);
      const std::string config = config_for(o.repo, o.folder, model, problem, size * 7200L);
      const Flight f = fly(o, config, scenario, o.folder + "/paced-" + std::to_string(size) + "-" + std::to_string(run));
      std::printf("%6d %4d %6zu %6zu %7.3f %7.3f %7.3f%s %8.3f %7.3f %7.3f %6.3f %7.3f %8.3f %8.3f %5s\n", size,
                  run + 1, f.first_tokens, f.replan_tokens, f.detection, f.safing, f.request, f.settled ? "*" : " ",
                  f.planner, f.search, f.splice, f.first_tick, f.total, f.from_request, f.executive_own,
                  f.aborts > 1 || f.violations > 0 ? "yes" : "no");
      if (f.total < 0) all = false;
      else flights[size].push_back(f);
    }
  std::printf("wall s; first/tokens: the first plan's / the new plan's; detect: the arc's end tick -> the abort's "
              "tick; safing, request: the abort's tick -> on the bus (* waited for a turn under way to end); planner: "
              "request -> reply (search: the planner's own); splice: reply -> plan executing (the executive's "
              "dispatchable form, start); tick: -> the next tick; total: the arc's end tick -> the new plan's first "
              "tick; from req: the request -> that tick; exec own: the executive's abort -> plan executing; broke: a "
              "violation or a second abort within 3 s\n");
  auto med = [&](int size, double Flight::*field) {
    std::vector<double> x;
    for (const Flight& f : flights[size]) x.push_back(f.*field);
    return median(x);
  };
  for (int size : sizes) {
    if (flights[size].empty()) continue;
    std::printf("median %d blocks (%zu tokens): total %.3f s = detection %.3f + request %.3f + planner %.3f (search "
                "%.3f) + splice %.3f + tick %.3f; the first plan (%zu tokens, from scratch): request -> executing "
                "%.3f s\n",
                size, flights[size].front().replan_tokens, med(size, &Flight::total), med(size, &Flight::detection),
                med(size, &Flight::request), med(size, &Flight::planner), med(size, &Flight::search),
                med(size, &Flight::splice), med(size, &Flight::first_tick), flights[size].front().first_tokens,
                med(size, &Flight::first_plan));
  }
  if (!flights[o.small_blocks].empty() && !flights[o.large_blocks].empty()) {
    const double large = med(o.large_blocks, &Flight::total), small = med(o.small_blocks, &Flight::total);
    std::printf("fault -> new plan executing, paced: %.3f s at %zu tokens (goal < 1 s: %s), baseline %.3f s at %zu "
                "tokens, %.2fx\n",
                large, flights[o.large_blocks].front().replan_tokens, large < 1 ? "met" : "not met", small,
                flights[o.small_blocks].front().replan_tokens, large / small);
  }
  std::printf("logs: %s\n", o.folder.c_str());
  return all ? 0 : 1;
}

}  // namespace autonomy::bench
