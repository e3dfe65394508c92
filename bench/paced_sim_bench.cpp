// The real simulator process on the stress scenario (deploy/scenarios/stress.pbtxt: 100 robots
// with 32-ray range sensors, 1000 x 1000 m, 2000 buildings) in PACED mode at 10 Hz (step 0.1 s,
// warp 1), radio link table for all pairs every tick (or every --radio-period ticks), while this
// bench drives all 100 robots with velocity commands from one DDS participant (every robot in a
// slowly turning direction, so robots move, meet walls and each other, and scans and links
// change) and reads what a team's controllers would read (robot states, range scans, radio links,
// the clock).
//
// Figures over a fixed wall-time window after a warm-up: the simulator process's CPU time (user +
// system, all threads, from /proc/PID/stat) as a share of one core, ticks published per second
// (from autonomy/clock samples), samples received per second per topic, the simulator's own
// mean_step_us, the CPU split by thread (main loop vs Cyclone's threads), and the ratio to the
// goal: 100 robots at 10 Hz in paced real time using under half of one core.
// Baseline in the same run: the same work in-process without DDS (World::step, a range scan and a
// pose estimate per robot, the radio link table and team connectivity), per tick.
//
// Scale (issue 28): --robots N replaces the scenario's robots by N on a lattice over the same map
// (moved off buildings), so 100, 300, 1,000 and 3,000 robots run on one world; the report adds
// the simulator's resident memory. The in-process baseline then also runs the all-pairs reference
// (World::use_all_pairs_reference, the full LinkTable) for --reference-ticks ticks, beside the
// spatial index and NearLinkTable the simulator uses; --simulator runs another build of the
// simulator (e.g. the previous commit's) under the same command.
//
// Usage: paced_sim_bench [--domain 170] [--seconds 20] [--warmup 3] [--radio-period 1] [--quick]
//                        [--robots N] [--reference-ticks 5] [--simulator PATH]
// Needs the simulator executable next to this one (build/bin). Uses DDS domain --domain only
// (170 by default; 171 is left for a second concurrent run).
#include "bench/bench_support.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/waitset.hpp"
#include "common/dds/writer.hpp"
#include "simulator/core/world.hpp"
#include "simulator/dds/radio_setup.hpp"
#include "simulator/radio/connectivity.hpp"
#include "simulator/radio/near_links.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

using namespace autonomy;
using namespace autonomy::bench;

namespace {

constexpr double kGoalCoreShare = 0.5;  // the goal: under half of one core

struct Options {
  int domain = 170;
  double seconds = 20.0;
  double warmup_s = 3.0;
  int radio_period = 1;
  double command_hz = 10.0;
  std::string scenario = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/stress.pbtxt";
  int robots = 0;  // 0: the scenario's own robots
  int reference_ticks = 5;
  std::string simulator;  // empty: the one next to this bench
};

Options parse(int argc, char** argv) {
  Options o;
  bool quick = false;
  CLI::App app{"The real simulator, paced at 10 Hz with 100 robots driven over DDS: CPU share of one core"};
  app.add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232))->capture_default_str();
  app.add_option("--seconds", o.seconds, "Measured wall time")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--warmup", o.warmup_s, "Wall time driving before measuring")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--radio-period", o.radio_period, "The simulator's --radio-period (ticks per link table)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--command-hz", o.command_hz, "Velocity commands per robot per second")
      ->check(CLI::Range(2.5, 100.0))
      ->capture_default_str();
  app.add_option("--scenario", o.scenario, "Scenario file (paced mode, step and warp are taken from it)")
      ->check(CLI::ExistingFile);
  app.add_option("--robots", o.robots, "Replace the scenario's robots by this many on a lattice (0: keep them)")
      ->check(CLI::Range(0, 20000));
  app.add_option("--reference-ticks", o.reference_ticks, "In-process ticks of the all-pairs reference (0: skip)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  app.add_option("--simulator", o.simulator, "The simulator executable (default: next to this bench)")
      ->check(CLI::ExistingFile);
  app.add_flag("--quick", quick, "Short run (6 s measured), for a smoke test");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e));
  }
  if (quick) {
    o.seconds = 6.0;
    o.warmup_s = 2.0;
  }
  return o;
}

double process_cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// utime + stime of /proc/PID/stat or /proc/PID/task/TID/stat, in seconds; the name in `comm`.
double stat_cpu_seconds(const std::string& stat_path, std::string* comm = nullptr) {
  std::ifstream f(stat_path);
  std::string line;
  if (!std::getline(f, line)) return 0.0;
  const size_t open = line.find('(');
  const size_t close = line.rfind(')');
  if (comm != nullptr && open != std::string::npos) *comm = line.substr(open + 1, close - open - 1);
  std::istringstream in(line.substr(close + 2));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && in >> field; ++i) {
    if (i == 14) utime = std::stoull(field);
    if (i == 15) stime = std::stoull(field);
  }
  return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

double process_cpu_seconds(pid_t pid) { return stat_cpu_seconds("/proc/" + std::to_string(pid) + "/stat"); }

// CPU seconds per thread name (threads of the same name summed).
std::map<std::string, double> thread_cpu_seconds(pid_t pid) {
  std::map<std::string, double> out;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task", ec)) {
    std::string comm;
    const double s = stat_cpu_seconds(task.path().string() + "/stat", &comm);
    out[comm] += s;
  }
  return out;
}

// Each robot drives in a slowly turning direction (the same pattern as world_bench).
msg::VelocityCommand drive(const std::string& id, double t_s) {
  const double phase = 0.5 * t_s + static_cast<double>(std::hash<std::string>{}(id) % 628) / 100.0;
  return {id, "paced_sim_bench", 0, 1.5 * std::cos(phase), 1.5 * std::sin(phase), 0.0};
}

struct InProcess {
  double step_ms = 0.0;
  double sense_ms = 0.0;  // range scans and pose estimates
  double radio_ms = 0.0;  // link table and connectivity
  int ticks = 0;
  double pairs_computed = 0.0;  // radio pairs whose link was computed, per tick
  double connected = 0.0;       // connected pairs, per tick
  double total_ms() const { return step_ms + sense_ms + radio_ms; }
};

// The simulator's per-tick work without DDS, on the same scenario: with the spatial index and
// the near-link table (as the simulator does it), or with the all-pairs reference.
InProcess in_process(const sim::Scenario& scenario, int ticks, bool all_pairs) {
  sim::World world(scenario.world);
  world.use_all_pairs_reference(all_pairs);
  const sim::radio::RadioModel radio = sim::make_radio_model(scenario);
  sim::radio::LinkTable table;
  sim::radio::NearLinkTable near;
  std::vector<geometry::Vec2> positions;
  InProcess r;
  r.ticks = ticks;
  if (ticks == 0) return r;
  volatile double sink = 0.0;
  for (int t = 0; t < ticks; ++t) {
    double c0 = process_cpu_now();
    for (const sim::RobotStatus& s : world.robots()) {
      const msg::VelocityCommand m = drive(s.id, 0.1 * t);
      (void)world.submit({m.robot_id, m.source, m.tick, m.vx, m.vy, m.omega});
    }
    world.step(0.1);
    double c1 = process_cpu_now();
    r.step_ms += 1e3 * (c1 - c0);
    const std::vector<sim::RobotStatus> robots = world.robots();
    for (const sim::RobotStatus& s : robots) {
      if (auto scan = world.sense(s.id)) sink = sink + scan->ranges[0];
      if (auto pose = world.observe_pose(s.id)) sink = sink + pose->x;
    }
    double c2 = process_cpu_now();
    r.sense_ms += 1e3 * (c2 - c1);
    positions.clear();
    for (const sim::RobotStatus& s : robots) positions.push_back(s.pose.position());
    if (all_pairs) {
      radio.update(positions, table);
      const sim::radio::Connectivity connectivity(table);
      sink = sink + static_cast<double>(connectivity.components().size());
      r.pairs_computed += static_cast<double>(table.pair_count());
      for (size_t i = 0; i < positions.size(); ++i)
        for (size_t j = i + 1; j < positions.size(); ++j) r.connected += table.connected(i, j) ? 1.0 : 0.0;
      r.radio_ms += 1e3 * (process_cpu_now() - c2);
    } else {
      near.update(radio, positions);
      const sim::radio::Connectivity connectivity(near);
      sink = sink + static_cast<double>(connectivity.components().size());
      r.radio_ms += 1e3 * (process_cpu_now() - c2);
      r.pairs_computed += static_cast<double>(near.pairs_in_range());
      r.connected += static_cast<double>(near.links().size());
    }
  }
  for (double* v : {&r.step_ms, &r.sense_ms, &r.radio_ms, &r.pairs_computed, &r.connected}) *v /= ticks;
  return r;
}

// The scenario file with its robots replaced by `count` robots on a lattice over the world, each
// moved (in steps of a seventh of the spacing) to the nearest place clear of buildings.
std::string scenario_with_robots(const std::string& path, const sim::Scenario& scenario, int count,
                                 const std::string& out_path) {
  sim::WorldSpec empty = scenario.world;
  empty.robots_at_start.clear();
  sim::World world(empty);
  std::vector<std::string> lines;
  for (int side = static_cast<int>(std::ceil(std::sqrt(count))); static_cast<int>(lines.size()) < count; ++side) {
    lines.clear();
    world = sim::World(empty);
    const double sx = scenario.world.width / side, sy = scenario.world.height / side;
    std::vector<std::pair<int, int>> nudges;
    for (int a = -3; a <= 3; ++a)
      for (int b = -3; b <= 3; ++b) nudges.emplace_back(a, b);
    std::stable_sort(nudges.begin(), nudges.end(), [](auto p, auto q) {
      return p.first * p.first + p.second * p.second < q.first * q.first + q.second * q.second;
    });
    for (int j = 0; j < side && static_cast<int>(lines.size()) < count; ++j) {
      for (int i = 0; i < side && static_cast<int>(lines.size()) < count; ++i) {
        char id[16];
        std::snprintf(id, sizeof id, "r%05zu", lines.size());
        for (const auto& [a, b] : nudges) {
          const double x = (i + 0.5) * sx + a * sx / 7.0, y = (j + 0.5) * sy + b * sy / 7.0;
          if (!world.spawn(id, geometry::Pose2{x, y, 0.0}).accepted) continue;
          char line[160];
          std::snprintf(line, sizeof line,
                        "robots { id: \"%s\" kinematics: HOLONOMIC start { x: %.3f y: %.3f } spawn_at_start: true }", id,
                        x, y);
          lines.emplace_back(line);
          break;
        }
      }
    }
  }
  std::ifstream in(path);
  std::ofstream out(out_path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("robots {", 0) != 0) out << line << "\n";
  for (const auto& l : lines) out << l << "\n";
  if (!out) throw std::runtime_error("cannot write " + out_path);
  return out_path;
}

// VmRSS and VmHWM of a process, in MiB.
std::pair<double, double> resident_mib(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  double rss = 0.0, peak = 0.0;
  while (std::getline(f, line)) {
    if (line.rfind("VmRSS:", 0) == 0) rss = std::stod(line.substr(6)) / 1024.0;
    if (line.rfind("VmHWM:", 0) == 0) peak = std::stod(line.substr(6)) / 1024.0;
  }
  return {rss, peak};
}

struct Counts {
  uint64_t clock = 0, states = 0, scans = 0, links = 0;
};

}  // namespace

int main(int argc, char** argv) {
  try {
    Options o = parse(argc, argv);
    if (!std::getenv("CYCLONEDDS_URI"))
      progress("note: CYCLONEDDS_URI is not set; Cyclone picks its default network interface");
    const std::string log_dir = "/tmp/autonomy-bench/paced-" + std::to_string(getpid());
    std::filesystem::create_directories(log_dir);
    if (o.robots > 0) {
      const sim::ScenarioLoadResult original = sim::load_scenario_file(o.scenario);
      if (!original.ok()) throw std::runtime_error(original.error_text());
      progress("[scenario] %d robots on the map of %s", o.robots, o.scenario.c_str());
      o.scenario = scenario_with_robots(o.scenario, *original.scenario, o.robots, log_dir + "/scenario.pbtxt");
    }
    const sim::ScenarioLoadResult loaded = sim::load_scenario_file(o.scenario);
    if (!loaded.ok()) throw std::runtime_error(loaded.error_text());
    const sim::Scenario& scenario = *loaded.scenario;
    std::vector<std::string> ids;
    for (const auto& r : scenario.world.robots_at_start) ids.push_back(r.id);
    const double step_s = scenario.simulation.step_s;
    const double warp = scenario.simulation.warp;
    const double tick_hz = warp / step_s;

    // Baseline: the same work in-process.
    progress("[in-process] world step, sensing and radio for %zu robots", ids.size());
    const InProcess base = in_process(scenario, 50, false);
    progress("[in-process] the same with the all-pairs reference, %d ticks", o.reference_ticks);
    const InProcess reference = in_process(scenario, o.reference_ticks, true);

    // The simulator process.
    const std::string dom = std::to_string(o.domain);
    dds::Participant participant(o.domain);
    dds::Topic<msg::SimClock> clock_topic(participant, dds::topics::clock);
    dds::Topic<msg::SimulatorStatus> status_topic(participant, dds::topics::sim_status);
    dds::Topic<msg::VelocityCommand> cmd_topic(participant, dds::topics::cmd_vel);
    dds::Topic<msg::RobotState> state_topic(participant, dds::topics::robot_state);
    dds::Topic<msg::RangeScan> scan_topic(participant, dds::topics::range_scan);
    dds::Topic<msg::RadioLink> link_topic(participant, dds::topics::radio_link);
    dds::Reader<msg::SimClock> clock_reader(participant, clock_topic);
    dds::Reader<msg::SimulatorStatus> status_reader(participant, status_topic);
    dds::Reader<msg::RobotState> state_reader(participant, state_topic);
    dds::Reader<msg::RangeScan> scan_reader(participant, scan_topic);
    dds::Reader<msg::RadioLink> link_reader(participant, link_topic);
    dds::Writer<msg::VelocityCommand> cmd_writer(participant, cmd_topic);
    dds::WaitSet ws(participant);
    ws.attach(clock_reader.data_condition(), 1);

    progress("[simulator] %s, paced, step %.3g s, warp %.3g, radio every %d tick(s), domain %d", o.scenario.c_str(),
             step_s, warp, o.radio_period, o.domain);
    const std::string simulator_exe = o.simulator.empty() ? self_dir() + "/simulator" : o.simulator;
    ChildProcess sim({simulator_exe, "--config", o.scenario, "--mode", "paced", "--domain", dom,
                      "--radio-period", std::to_string(o.radio_period), "--log-level", "warn", "--log-dir", log_dir},
                     false, log_dir + "/simulator.out");

    Counts counts;
    int64_t latest_tick = -1;
    double mean_step_us = 0.0;
    uint64_t commands_applied = 0, commands_rejected = 0;
    const auto drain = [&] {
      for (const auto& s : clock_reader.take()) {
        if (!s.valid) continue;
        ++counts.clock;
        latest_tick = std::max(latest_tick, s.value.tick);
      }
      for (const auto& s : status_reader.take()) {
        if (!s.valid) continue;
        mean_step_us = s.value.mean_step_us;
        commands_applied = s.value.commands_applied;
        commands_rejected = s.value.commands_rejected;
      }
      counts.states += state_reader.take().size();
      counts.scans += scan_reader.take().size();
      counts.links += link_reader.take().size();
    };

    const auto started = Clock::now();
    while (latest_tick < 0) {
      if (seconds_since(started) > 60) throw std::runtime_error("no clock from the simulator within 60 s");
      ws.wait(std::chrono::milliseconds(200));
      drain();
    }
    progress("[simulator] ticking (tick %lld after %.1f s); driving %zu robots at %.0f Hz", static_cast<long long>(latest_tick),
             seconds_since(started), ids.size(), o.command_hz);

    // Drive for warm-up + window; commands go out at command_hz for every robot.
    const auto drive_start = Clock::now();
    const auto command_period = std::chrono::duration<double>(1.0 / o.command_hz);
    auto next_command = drive_start;
    bool measuring = false;
    Counts counts0;
    int64_t tick0 = 0;
    double cpu0 = 0.0;
    std::map<std::string, double> threads0;
    Clock::time_point t0{};
    uint64_t commands_sent = 0;
    const auto drive_until = [&](double end_s) {
      while (seconds_since(drive_start) < end_s) {
        const auto now = Clock::now();
        if (now >= next_command) {
          const double t = seconds_since(drive_start);
          for (const auto& id : ids) cmd_writer.write(drive(id, t));
          commands_sent += ids.size();
          next_command += std::chrono::duration_cast<Clock::duration>(command_period);
          if (next_command < now) next_command = now;
        }
        const auto wait = std::max(std::chrono::nanoseconds(0),
                                   std::chrono::duration_cast<std::chrono::nanoseconds>(next_command - Clock::now()));
        ws.wait(std::min(wait, std::chrono::nanoseconds(std::chrono::milliseconds(20))));
        drain();
      }
    };
    drive_until(o.warmup_s);
    drain();
    measuring = true;
    t0 = Clock::now();
    cpu0 = process_cpu_seconds(sim.pid());
    threads0 = thread_cpu_seconds(sim.pid());
    tick0 = latest_tick;
    counts0 = counts;
    const double bench_cpu0 = process_cpu_now();
    progress("[measure] %.0f s from tick %lld", o.seconds, static_cast<long long>(tick0));
    drive_until(o.warmup_s + o.seconds);
    drain();
    const double window_s = seconds_since(t0);
    const double cpu1 = process_cpu_seconds(sim.pid());
    const std::map<std::string, double> threads1 = thread_cpu_seconds(sim.pid());
    const int64_t tick1 = latest_tick;
    const double bench_cpu = process_cpu_now() - bench_cpu0;
    const auto [rss_mib, peak_mib] = resident_mib(sim.pid());
    (void)measuring;
    sim.terminate();

    const double sim_share = (cpu1 - cpu0) / window_s;
    const double ticks_per_s = static_cast<double>(tick1 - tick0) / window_s;
    const auto rate = [&](uint64_t Counts::*field) {
      return static_cast<double>(counts.*field - counts0.*field) / window_s;
    };
    char load[64] = "?";
    if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
      if (std::fgets(load, sizeof load, f) == nullptr) load[0] = '\0';
      std::fclose(f);
    }
    std::printf("\n== paced_sim_bench: %s, %zu robots, paced %.3g Hz (step %.3g s, warp %.3g), radio every %d tick(s) ==\n",
                scenario.world.name.c_str(), ids.size(), tick_hz, step_s, warp, o.radio_period);
    std::printf("load average at the end: %s", load);
    std::printf("simulator: %s\n", simulator_exe.c_str());
    const auto print_in_process = [&](const char* name, const InProcess& r) {
      std::printf("%s, in-process (no DDS), per tick over %d ticks: step %.2f ms, scans + poses %.2f ms, radio "
                  "%.2f ms (%.0f pairs computed, %.0f connected) = %.2f ms -> %.1f %% of a core at %.3g Hz\n",
                  name, r.ticks, r.step_ms, r.sense_ms, r.radio_ms, r.pairs_computed, r.connected, r.total_ms(),
                  r.total_ms() * tick_hz / 10.0, tick_hz);
    };
    print_in_process("spatial index + near links", base);
    if (reference.ticks > 0) {
      print_in_process("baseline all pairs         ", reference);
      std::printf("  all pairs / index: step %.1f x, scans %.1f x, radio %.1f x, total %.1f x\n",
                  reference.step_ms / std::max(base.step_ms, 1e-9), reference.sense_ms / std::max(base.sense_ms, 1e-9),
                  reference.radio_ms / std::max(base.radio_ms, 1e-9), reference.total_ms() / std::max(base.total_ms(), 1e-9));
    }
    std::printf("simulator process over %.1f s: CPU %.1f %% of one core (%.2f ms per tick), %.2f ticks/s published "
                "(target %.3g), mean step %.0f us (its own count)\n",
                window_s, 100.0 * sim_share, ticks_per_s > 0 ? 1e3 * (cpu1 - cpu0) / (ticks_per_s * window_s) : 0.0,
                ticks_per_s, tick_hz, mean_step_us);
    std::printf("  resident memory at the end: %.0f MiB (peak %.0f MiB)\n", rss_mib, peak_mib);
    std::printf("SCALE robots=%zu ticks_per_s=%.2f cpu_share=%.3f rss_mib=%.0f peak_mib=%.0f links_per_s=%.0f "
                "inproc_ms=%.2f allpairs_ms=%.2f\n",
                ids.size(), ticks_per_s, sim_share, rss_mib, peak_mib, rate(&Counts::links), base.total_ms(),
                reference.ticks > 0 ? reference.total_ms() : 0.0);
    std::printf("  by thread:");
    for (const auto& [name, s] : threads1) {
      const auto it = threads0.find(name);
      const double d = s - (it == threads0.end() ? 0.0 : it->second);
      if (d > 0.0) std::printf(" %s %.1f %%", name.c_str(), 100.0 * d / window_s);
    }
    std::printf("\n  received per second: clock %.1f, robot states %.0f, range scans %.0f, radio links %.0f; "
                "commands sent %.0f/s, applied %llu, rejected %llu (totals)\n",
                rate(&Counts::clock), rate(&Counts::states), rate(&Counts::scans), rate(&Counts::links),
                static_cast<double>(commands_sent) / (o.warmup_s + o.seconds),
                static_cast<unsigned long long>(commands_applied), static_cast<unsigned long long>(commands_rejected));
    std::printf("  this bench's own CPU: %.1f %% of a core\n", 100.0 * bench_cpu / window_s);
    std::printf("goal: under %.0f %% of one core -> simulator uses %.2f x the budget (%s); in-process work alone "
                "is %.2f x it\n",
                100.0 * kGoalCoreShare, sim_share / kGoalCoreShare, sim_share < kGoalCoreShare ? "met" : "NOT met",
                base.total_ms() * tick_hz / 1e3 / kGoalCoreShare);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "paced_sim_bench: %s\n", e.what());
    return 1;
  }
}
