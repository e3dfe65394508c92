// Lockstep ticks per second with the real processes: the simulator (built-in demo scenario,
// lockstep, --wait-for every behavior, --max-ticks N) and 1 or 3 behavior processes, each given a
// goal on the far side of the wall. When a robot reaches (or fails) its goal this bench sends it
// back to where it came from, so every robot drives and plans for the whole run.
//
// Figures, from autonomy/sim/status (5 Hz): ticks/s over the measured window (after warm-up),
// the simulator's mean_step_us, and CPU time per tick of every process (from /proc).
// Baselines in the same run: the raw Cyclone round trip on RobotState (ticks/s cannot exceed
// about 1/RTT: every tick is at least one simulator -> behavior -> simulator round trip), and the
// same lockstep run with one robot.
// Every run publishes every tick (the simulator's --every-tick): a robot between two goals declares
// itself quiet, and a world of quiet participants steps ticks without a round trip (2 million a
// second when idle), which made the one-robot baseline count free ticks. --quiet-ticks measures
// with them, to see what they save.
//
// Usage: lockstep_bench [--domain 161] [--ticks 20000] [--warmup-ticks 300] [--robots 1,3]
//                       [--dds-extra file.xml] [--quiet-ticks] [--quick] [--old-bin DIR]
//                       [--run-domains K]
//   --old-bin DIR runs every case with the simulator and behavior executables in DIR first (a copy
//   of an earlier build), so a change is measured against its baseline in the same run.
//   --run-domains K: the lockstep runs take the domains after --domain in turn, K of them (one
//   after the other, each run's processes gone before the next starts); without it, those up to
//   169 (bench/run.sh's range), or only the next one above 168.
//   --dds-extra appends a Cyclone config snippet (a file:// URI or inline XML, e.g.
//   '<Tracing><Verbosity>warning</Verbosity></Tracing>') to
//   CYCLONEDDS_URI for the lockstep processes, and runs the same cases without it first, for
//   comparison.
//   --secure DIR runs the same cases once more with DDS Security: every process on its own
//   identity from DIR (deploy/security/security.sh set DIR deploy/sets/demo-lockstep.set; the bench
//   itself as operator), each on the loopback profile plus its identity.
// Needs the simulator and behavior executables next to this one (build/bin).
#include "bench/bench_support.hpp"
#include "bench/pingpong.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/waitset.hpp"
#include "common/dds/writer.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

using namespace autonomy;
using namespace autonomy::bench;

namespace {

struct Options {
  int domain = 161;
  int64_t ticks = 20000;
  int64_t warmup_ticks = 300;
  std::vector<int> robot_counts = {1, 3};
  std::string dds_extra;
  std::string secure_dir;
  bool quiet_ticks = false;
  int rtt_count = 3000;
  std::string old_bin;  // a folder with an earlier build's simulator and behavior, if set
  int run_domains = 0;  // 0: the domains after --domain up to 169
};

struct RobotSpec {
  const char* id;
  double gx, gy;  // goal beyond the wall
  double bx, by;  // way back (the scenario's start)
};
constexpr RobotSpec kRobots[] = {{"r1", 18, 2, 2, 2}, {"r2", 18, 6, 2, 5}, {"r3", 18, 10, 2, 10}};

// CPU time (user + system) of a process and all its threads, in seconds.
double cpu_seconds(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return 0.0;
  std::istringstream in(line.substr(line.rfind(')') + 2));
  std::string field;
  unsigned long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && in >> field; ++i) {
    if (i == 14) utime = std::stoul(field);
    if (i == 15) stime = std::stoul(field);
  }
  return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// Voluntary + involuntary context switches summed over the threads of a process
// (/proc/PID/status counts only the main thread).
uint64_t context_switches(pid_t pid) {
  uint64_t total = 0;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task", ec)) {
    std::ifstream ts(task.path() / "status");
    std::string l;
    while (std::getline(ts, l))
      if (l.rfind("voluntary_ctxt_switches:", 0) == 0 || l.rfind("nonvoluntary_ctxt_switches:", 0) == 0)
        total += std::stoull(l.substr(l.find(':') + 1));
  }
  return total;
}

// UDP datagrams received by this host so far (/proc/net/snmp; loopback traffic of every process).
uint64_t udp_in_datagrams() {
  std::ifstream f("/proc/net/snmp");
  std::string header, values;
  while (std::getline(f, header)) {
    if (header.rfind("Udp:", 0) != 0) continue;
    std::getline(f, values);
    std::istringstream hn(header), hv(values);
    std::string name, value;
    while (hn >> name && hv >> value)
      if (name == "InDatagrams") return std::stoull(value);
  }
  return 0;
}

struct RunResult {
  int robots = 0;
  double ticks_per_s = 0.0;
  double mean_step_us = 0.0;
  int64_t measured_ticks = 0;
  double measured_s = 0.0;
  double sim_cpu_us_per_tick = 0.0;
  double behavior_cpu_us_per_tick = 0.0;  // sum over the behavior processes
  double sim_cs_per_tick = 0.0;
  double behavior_cs_per_tick = 0.0;
  double udp_per_tick = 0.0;
  uint64_t goals_sent = 0;
  uint64_t commands_applied = 0;
  uint64_t commands_rejected = 0;
  uint64_t participants_dropped = 0;
};

// CYCLONEDDS_URI for the next participant or child: with DDS Security (secure_dir set), `base`
// plus the identity NAME's section; otherwise left as the run's configuration set it.
void use_identity(const std::string& secure_dir, const std::string& base, const std::string& name) {
  if (secure_dir.empty()) return;
  const std::string uri = base + ",file://" + secure_dir + "/identities/" + name + "/cyclone.xml";
  setenv("CYCLONEDDS_URI", uri.c_str(), 1);
}

RunResult run_lockstep(const Options& o, int robots, int domain, const std::string& label, const std::string& bin,
                       const std::string& secure_dir = "") {
  const char* env_uri = std::getenv("CYCLONEDDS_URI");
  const std::string base = env_uri ? env_uri : "";
  // The identities are set per process below; the next run starts from the run's own setting.
  struct RestoreUri {
    std::string uri;
    ~RestoreUri() { setenv("CYCLONEDDS_URI", uri.c_str(), 1); }
  } restore{base};
  const std::string log_dir = "/tmp/autonomy-bench/lockstep-" + std::to_string(getpid()) + "-" + label;
  std::system(("mkdir -p " + log_dir).c_str());
  const std::string dom = std::to_string(domain);

  // The bench's own participant: status in, goals out.
  use_identity(secure_dir, base, "operator");
  dds::Participant participant(domain);
  dds::Topic<msg::SimulatorStatus> status_topic(participant, dds::topics::sim_status);
  dds::Topic<msg::GoalStatus> goal_status_topic(participant, dds::topics::goal_status);
  dds::Topic<msg::NavGoal> goal_topic(participant, dds::topics::nav_goal);
  dds::Reader<msg::SimulatorStatus> status_reader(participant, status_topic);
  dds::Reader<msg::GoalStatus> goal_status_reader(participant, goal_status_topic);
  dds::Writer<msg::NavGoal> goal_writer(participant, goal_topic);
  dds::WaitSet ws(participant);
  ws.attach(status_reader.data_condition(), 1);
  ws.attach(goal_status_reader.data_condition(), 2);

  std::vector<std::string> sim_args = {bin + "/simulator", "--domain", dom, "--max-ticks", std::to_string(o.ticks),
                                       "--log-level", "warn", "--log-dir", log_dir};
  if (!o.quiet_ticks) sim_args.push_back("--every-tick");
  sim_args.push_back("--wait-for");
  for (int i = 0; i < robots; ++i) sim_args.push_back(std::string("behavior/") + kRobots[i].id);
  use_identity(secure_dir, base, "simulator-main");
  ChildProcess sim(sim_args, false, log_dir + "/simulator.out");
  std::vector<ChildProcess> behaviors;
  behaviors.reserve(robots);
  for (int i = 0; i < robots; ++i) {
    const RobotSpec& r = kRobots[i];
    use_identity(secure_dir, base, std::string("behavior-") + r.id);
    behaviors.emplace_back(std::vector<std::string>{bin + "/behavior", "--robot", r.id, "--domain", dom, "--goal",
                                                    std::to_string(r.gx), std::to_string(r.gy), "--log-level",
                                                    "warn", "--log-dir", log_dir},
                           false, log_dir + "/behavior-" + r.id + ".out");
  }

  // Goal bookkeeping: the goal each robot pursues and whether it is heading out or back.
  std::map<std::string, std::string> current_goal;  // robot -> goal id
  std::map<std::string, int> legs;
  for (int i = 0; i < robots; ++i) current_goal[kRobots[i].id] = "cli-goal";

  RunResult res;
  res.robots = robots;
  bool measuring = false, done = false;
  int64_t tick0 = 0, last_tick = 0;
  Clock::time_point t0{}, t_last{};
  double sim_cpu0 = 0, beh_cpu0 = 0, sim_cpu_last = 0, beh_cpu_last = 0;
  uint64_t sim_cs0 = 0, beh_cs0 = 0, sim_cs_last = 0, beh_cs_last = 0, udp0 = 0, udp_last = 0;
  const auto started = Clock::now();
  auto last_progress = started;

  auto behavior_cpu = [&] {
    double s = 0;
    for (const auto& b : behaviors) s += cpu_seconds(b.pid());
    return s;
  };
  auto behavior_cs = [&] {
    uint64_t s = 0;
    for (const auto& b : behaviors) s += context_switches(b.pid());
    return s;
  };

  while (!done) {
    if (seconds_since(started) > 300) throw std::runtime_error("lockstep run did not finish within 300 s");
    ws.wait(std::chrono::milliseconds(500));
    for (const auto& s : goal_status_reader.take()) {
      if (!s.valid) continue;
      const auto& g = s.value;
      const auto it = current_goal.find(g.robot_id);
      if (it == current_goal.end() || it->second != g.goal_id) continue;
      if (g.state != msg::GoalState::Reached && g.state != msg::GoalState::Blocked &&
          g.state != msg::GoalState::Rejected)
        continue;
      // Send the robot the other way.
      for (int i = 0; i < robots; ++i) {
        if (g.robot_id != kRobots[i].id) continue;
        const int leg = ++legs[g.robot_id];
        const bool back = leg % 2 == 1;
        msg::NavGoal next{g.robot_id, "bench-" + std::to_string(leg), back ? kRobots[i].bx : kRobots[i].gx,
                          back ? kRobots[i].by : kRobots[i].gy, 0.0};
        it->second = next.goal_id;
        goal_writer.write(next);
        ++res.goals_sent;
      }
    }
    for (const auto& s : status_reader.take()) {
      if (!s.valid) continue;
      const auto& st = s.value;
      const auto now = Clock::now();
      const bool all_in = static_cast<int>(st.lockstep_participants.size()) == robots;
      if (!measuring && all_in && st.tick >= o.warmup_ticks && st.tick < o.ticks) {
        measuring = true;
        tick0 = st.tick;
        t0 = now;
        sim_cpu0 = cpu_seconds(sim.pid());
        beh_cpu0 = behavior_cpu();
        sim_cs0 = context_switches(sim.pid());
        beh_cs0 = behavior_cs();
        udp0 = udp_in_datagrams();
      } else if (measuring && st.tick <= o.ticks && st.tick > last_tick) {
        // The last sample (tick == --ticks) is published as the simulator stops: still on time.
        last_tick = st.tick;
        t_last = now;
        sim_cpu_last = cpu_seconds(sim.pid());
        beh_cpu_last = behavior_cpu();
        sim_cs_last = context_switches(sim.pid());
        beh_cs_last = behavior_cs();
        udp_last = udp_in_datagrams();
      }
      res.mean_step_us = st.mean_step_us;
      res.commands_applied = st.commands_applied;
      res.commands_rejected = st.commands_rejected;
      res.participants_dropped = st.participants_dropped;
      if (st.tick >= o.ticks) done = true;
      if (seconds_since(last_progress) >= 1.0) {
        last_progress = now;
        progress("  [%s] tick %lld, %zu participants, %.0f ticks/s so far, mean step %.1f us", label.c_str(),
                 static_cast<long long>(st.tick), st.lockstep_participants.size(),
                 measuring && last_tick > tick0
                     ? static_cast<double>(last_tick - tick0) / std::chrono::duration<double>(t_last - t0).count()
                     : 0.0,
                 st.mean_step_us);
      }
    }
  }
  if (!measuring || last_tick <= tick0) throw std::runtime_error("run too short to measure; raise --ticks");
  res.measured_ticks = last_tick - tick0;
  res.measured_s = std::chrono::duration<double>(t_last - t0).count();
  res.ticks_per_s = static_cast<double>(res.measured_ticks) / res.measured_s;
  const double n = static_cast<double>(res.measured_ticks);
  res.sim_cpu_us_per_tick = (sim_cpu_last - sim_cpu0) * 1e6 / n;
  res.behavior_cpu_us_per_tick = (beh_cpu_last - beh_cpu0) * 1e6 / n;
  res.sim_cs_per_tick = static_cast<double>(sim_cs_last - sim_cs0) / n;
  res.behavior_cs_per_tick = static_cast<double>(beh_cs_last - beh_cs0) / n;
  res.udp_per_tick = static_cast<double>(udp_last - udp0) / n;
  sim.wait(std::chrono::seconds(10));
  for (auto& b : behaviors) b.terminate();
  return res;
}

// Exits (help text or argument error, CLI11's exit code) when the arguments do not make a run.
Options parse(int argc, char** argv) {
  Options o;
  bool quick = false;
  CLI::App app{"Lockstep ticks per second: the real simulator with 1 and 3 real behavior processes"};
  app.add_option("--domain", o.domain, "First DDS domain id (the runs use the next few too)")
      ->check(CLI::Range(0, 224))  // + up to 8 run domains: at most 232 (Cyclone's ports)
      ->capture_default_str();
  app.add_option("--ticks", o.ticks, "Ticks per run")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--warmup-ticks", o.warmup_ticks, "Ticks before measuring")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--robots", o.robot_counts, "Robot counts to run, 1 to 3 each (e.g. 1,3)")
      ->delimiter(',')
      ->check(CLI::Range(1, 3));
  app.add_option("--dds-extra", o.dds_extra, "A Cyclone config snippet to compare against the default");
  app.add_option("--secure", o.secure_dir,
                 "Also run with DDS Security: identities in this folder (security.sh set DIR demo-lockstep.set)");
  app.add_flag("--quiet-ticks", o.quiet_ticks,
               "Let the world step ticks every participant declared quiet without a round trip (not comparable"
               " with the 1/RTT bound)");
  app.add_option("--old-bin", o.old_bin,
                 "Also run every case with the simulator and behavior in this folder (an earlier build), first")
      ->check(CLI::ExistingDirectory);
  app.add_option("--run-domains", o.run_domains,
                 "How many domains after --domain the lockstep runs take in turn (default: those up to 169)")
      ->check(CLI::Range(1, 8));
  app.add_flag("--quick", quick, "Short runs, for a smoke test");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e));
  }
  if (quick) {
    o.ticks = 5000;
    o.warmup_ticks = 200;
    o.rtt_count = 1000;
  }
  return o;
}

void print_result(const char* config, const RunResult& r) {
  std::printf("  %-9s %6d %10.0f %10.1f %10.1f %12.1f %8.1f %8.1f %8.1f %8lld %7.2f  goals sent %llu, rejected %llu, dropped %llu\n",
              config, r.robots, r.ticks_per_s, 1e6 / r.ticks_per_s, r.mean_step_us, r.sim_cpu_us_per_tick,
              r.behavior_cpu_us_per_tick, r.sim_cs_per_tick + r.behavior_cs_per_tick, r.udp_per_tick,
              static_cast<long long>(r.measured_ticks), r.measured_s, static_cast<unsigned long long>(r.goals_sent),
              static_cast<unsigned long long>(r.commands_rejected),
              static_cast<unsigned long long>(r.participants_dropped));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--child") {
    // --child echo API PAYLOAD DOMAIN TAG: the far side of the raw round-trip baseline.
    try {
      if (argc != 7 || std::string(argv[2]) != "echo") throw std::runtime_error("bad --child arguments");
      echo(parse_api(argv[3]), parse_payload(argv[4]), std::atoi(argv[5]), argv[6]);
      return 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "lockstep_bench child: %s\n", e.what());
      return 1;
    }
  }
  try {
    const Options o = parse(argc, argv);
    const char* uri_env = std::getenv("CYCLONEDDS_URI");
    const std::string base_uri = uri_env ? uri_env : "";
    if (base_uri.empty()) progress("note: CYCLONEDDS_URI is not set; Cyclone picks its default network interface");

    // Baseline 1: raw Cyclone round trip, RobotState, same two-process topology.
    progress("[baseline] raw DDS round trip, RobotState, %d round trips", o.rtt_count);
    std::vector<double> rtt;
    {
      const std::string tag = "lockstep_baseline_" + std::to_string(getpid());
      ChildProcess echo_side({self_exe(), "--child", "echo", "raw", "robotstate", std::to_string(o.domain), tag}, false);
      rtt = ping(Api::Raw, Payload::RobotState, o.domain, tag, 300, o.rtt_count);
      echo_side.wait(std::chrono::seconds(10));
    }
    const double rtt_p50 = percentile(rtt, 50);
    progress("[baseline] raw RTT p50 %.1f us -> at most %.0f ticks/s", rtt_p50, 1e6 / rtt_p50);

    struct Config {
      std::string name, uri, secure_dir, bin;
    };
    const std::string bin = self_dir();
    std::vector<Config> configs;
    if (!o.old_bin.empty()) {
      for (const char* exe : {"/simulator", "/behavior"})
        if (access((o.old_bin + exe).c_str(), X_OK) != 0)
          throw std::runtime_error("--old-bin " + o.old_bin + ": no executable " + o.old_bin + exe);
      configs.push_back({"old", base_uri, "", o.old_bin});
    }
    configs.push_back({"default", base_uri, "", bin});
    if (!o.dds_extra.empty()) {
      const std::string extra = o.dds_extra.rfind("file://", 0) == 0 || o.dds_extra.rfind('<', 0) == 0
                                    ? o.dds_extra
                                    : "file://" + o.dds_extra;
      configs.push_back({"extra", base_uri.empty() ? extra : base_uri + "," + extra, "", bin});
    }
    if (!o.secure_dir.empty()) {
      const std::string dir = std::filesystem::absolute(o.secure_dir).string();
      if (!std::filesystem::exists(dir + "/identities/simulator-main/cyclone.xml"))
        throw std::runtime_error("--secure " + dir + ": no identities (security.sh set DIR deploy/sets/demo-lockstep.set)");
      configs.push_back({"secure", base_uri, dir, bin});
    }

    std::vector<std::pair<std::string, RunResult>> results;
    int domain = o.domain + 1;
    for (const auto& c : configs) {
      setenv("CYCLONEDDS_URI", c.uri.c_str(), 1);  // inherited by the simulator and behaviors
      for (int robots : o.robot_counts) {
        const std::string label = c.name + "-" + std::to_string(robots) + "robot";
        progress("[lockstep] %s: simulator + %d behavior, %lld ticks (domain %d)", label.c_str(), robots,
                 static_cast<long long>(o.ticks), domain);
        const RunResult r = run_lockstep(o, robots, domain, label, c.bin, c.secure_dir);
        progress("[lockstep] %s: %.0f ticks/s, mean step %.1f us", label.c_str(), r.ticks_per_s, r.mean_step_us);
        results.emplace_back(c.name, r);
        const int last = o.run_domains > 0 ? o.domain + o.run_domains : std::max(169, o.domain + 1);
        domain = domain + 1 > last ? o.domain + 1 : domain + 1;
      }
    }
    setenv("CYCLONEDDS_URI", base_uri.c_str(), 1);

    std::printf("\n== lockstep_bench: simulator + behavior processes, demo scenario, %lld ticks, warm-up %lld, %s ==\n",
                static_cast<long long>(o.ticks), static_cast<long long>(o.warmup_ticks),
                o.quiet_ticks ? "quiet ticks stepped without a round trip" : "every tick published");
    std::printf("baseline: raw Cyclone RTT (RobotState, 2 processes) p50 %.1f us, p99 %.1f us -> bound %.0f ticks/s\n",
                rtt_p50, percentile(rtt, 99), 1e6 / rtt_p50);
    if (!o.dds_extra.empty()) std::printf("extra Cyclone config: %s\n", o.dds_extra.c_str());
    std::printf("  %-9s %6s %10s %10s %10s %12s %8s %8s %8s %8s %7s\n", "config", "robots", "ticks/s", "us/tick",
                "step us", "sim cpu/tick", "beh cpu", "cs/tick", "udp/tick", "ticks", "s");
    std::printf("  (cpu: us of CPU per tick, all threads; beh cpu: sum over the behavior processes; cs/tick:\n"
                "   context switches per tick of those processes; udp/tick: datagrams received per tick, host-wide)\n");
    for (const auto& [name, r] : results) print_result(name.c_str(), r);
    std::printf("ratios:\n");
    for (const auto& [name, r] : results) {
      double one = 0;
      for (const auto& [n2, r2] : results)
        if (n2 == name && r2.robots == 1) one = r2.ticks_per_s;
      std::printf("  %-9s %d robots: %.0f ticks/s = %.2f x the 1/RTT bound", name.c_str(), r.robots, r.ticks_per_s,
                  r.ticks_per_s * rtt_p50 / 1e6);
      if (one > 0 && r.robots != 1) std::printf(", %.2f x the 1-robot rate", r.ticks_per_s / one);
      if (r.robots == 3) std::printf("  (goal: at least 10000 ticks/s with 3 robots)");
      std::printf("\n");
    }
    // Pairs measured in this run: (what, against what).
    const std::pair<const char*, const char*> pairs[] = {{"secure", "default"}, {"default", "old"}};
    for (const auto& [what, against] : pairs) {
      for (const auto& [name, r] : results) {
        if (name != what) continue;
        for (const auto& [n2, r2] : results)
          if (n2 == against && r2.robots == r.robots)
            std::printf("  %s against %s, %d robots: %.0f against %.0f ticks/s = %.2f x (CPU per tick: simulator"
                        " %.2f x, behaviors %.2f x)\n",
                        what, against, r.robots, r.ticks_per_s, r2.ticks_per_s, r.ticks_per_s / r2.ticks_per_s,
                        r.sim_cpu_us_per_tick / r2.sim_cpu_us_per_tick,
                        r.behavior_cpu_us_per_tick / r2.behavior_cpu_us_per_tick);
      }
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lockstep_bench: %s\n", e.what());
    return 1;
  }
}
