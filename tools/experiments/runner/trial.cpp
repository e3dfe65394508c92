#include "tools/experiments/runner/trial.hpp"

#include "common/process/child_process.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <list>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace autonomy::experiments {

namespace fs = std::filesystem;
using process::ChildProcess;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

// SIGTERM, a grace period, then SIGKILL (the destructor's).
void stop(ChildProcess& child) {
  if (!child.running()) return;
  child.signal(SIGTERM);
  child.wait_for_exit(std::chrono::seconds(3));
}

}  // namespace

std::vector<double> start_positions(const TrialSetup& setup, std::uint64_t seed) {
  const size_t n = setup.robots.size();
  const double spacing = setup.min_start_spacing_m;
  const double slack = setup.start_max_x - setup.start_min_x - spacing * static_cast<double>(n > 0 ? n - 1 : 0);
  if (!(slack >= 0.0))
    throw std::invalid_argument(std::to_string(n) + " robots do not fit " + fixed(spacing) + " m apart between x = " +
                                fixed(setup.start_min_x) + " and " + fixed(setup.start_max_x));
  // Uniform over the spaced arrangements without rejection: n sorted draws in a line shortened
  // by the gaps, then the k-th moved up by k gaps.
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(0.0, slack);
  std::vector<double> xs;
  for (size_t k = 0; k < n; ++k) xs.push_back(x(rng));
  std::sort(xs.begin(), xs.end());
  for (size_t k = 0; k < n; ++k) xs[k] += setup.start_min_x + spacing * static_cast<double>(k);
  return xs;
}

stats::TrialRecord run_trial(const TrialSetup& setup, const std::string& configuration, int trial,
                             std::uint64_t seed, int domain, bool check_for_other_world) {
  const std::string stem = configuration + "-" + std::to_string(trial);
  const fs::path logs = setup.out_dir / "logs";
  const auto log = [&](const std::string& who) { return (logs / (stem + "-" + who + ".out")).string(); };
  std::map<std::string, std::string> env;
  if (!setup.dds_uri.empty()) env["CYCLONEDDS_URI"] = setup.dds_uri;
  const std::string dom = std::to_string(domain);

  std::vector<std::string> sim_args = {"--config", setup.scenario.string(), "--without-robots", "--domain", dom,
                                       "--log-dir", logs.string(), "--max-ticks", std::to_string(setup.max_ticks),
                                       "--stop-when-finished", "--metrics", (setup.out_dir / stem).string(),
                                       "--svg", (setup.out_dir / (stem + ".svg")).string(), "--wait-for"};
  for (const auto& r : setup.robots) sim_args.push_back("behavior/" + r);
  if (!check_for_other_world) {
    sim_args.push_back("--world-check");
    sim_args.push_back("0");
  }
  fs::remove(setup.out_dir / (stem + ".json"));

  std::vector<std::vector<std::string>> behavior_args;
  const std::vector<double> xs = start_positions(setup, seed);
  for (size_t k = 0; k < setup.robots.size(); ++k) {
    const std::string& r = setup.robots[k];
    const fs::path mission = setup.missions_dir / (configuration + "_" + r + ".pbtxt");
    behavior_args.push_back({"--robot", r, "--mission", mission.string(), "--start", fixed(xs[k]), fixed(setup.start_y),
                             "--resolution", fixed(setup.grid_resolution_m), "--domain", dom, "--log-dir",
                             logs.string()});
  }

  // std::list: children do not move once started. One process: the host is `sim` (it ends when
  // its simulator does), with no behavior processes beside it.
  std::list<ChildProcess> behaviors;
  std::optional<ChildProcess> sim;
  if (setup.one_process) {
    std::vector<std::string> host_args = {"--log-dir", logs.string(), "--name", stem, "+simulator"};
    host_args.insert(host_args.end(), sim_args.begin(), sim_args.end());
    for (const auto& b : behavior_args) {
      host_args.push_back("+behavior");
      host_args.insert(host_args.end(), b.begin(), b.end());
    }
    sim.emplace("trial host", setup.bin_dir + "/experiment_trial_host", host_args, env, log("trial"));
  } else {
    sim.emplace("simulator", setup.bin_dir + "/simulator", sim_args, env, log("sim"));
    for (size_t k = 0; k < setup.robots.size(); ++k)
      behaviors.emplace_back("behavior " + setup.robots[k], setup.bin_dir + "/behavior", behavior_args[k], env,
                             log(setup.robots[k]));
  }

  // The simulator ends the run; a behavior that ends before it has failed.
  const auto deadline = std::chrono::steady_clock::now() + setup.timeout;
  std::string failed;
  while (sim->running() && failed.empty()) {
    for (auto& b : behaviors)
      if (!b.running()) failed = b.name() + " ended early: " + b.status()->describe() + " (see " + b.log_file() + ")";
    if (std::chrono::steady_clock::now() >= deadline) failed = "did not finish within the trial timeout";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  stop(*sim);
  for (auto& b : behaviors) stop(b);
  if (!failed.empty()) throw std::runtime_error(stem + ": " + failed);
  if (!sim->status()->exited || sim->status()->code != 0)
    throw std::runtime_error(stem + ": " + sim->name() + " failed, " + sim->status()->describe() + " (see " +
                             sim->log_file() + ")");

  const auto j = nlohmann::json::parse(read_text(setup.out_dir / (stem + ".json")));
  stats::TrialRecord rec;
  rec.configuration = configuration;
  rec.trial = trial;
  rec.seed = seed;
  rec.mission_time_s = j.at("team").at("mission_time_s").get<double>();
  rec.distance_m = j.at("team").at("distance_m").get<double>();
  // Time connected: summed over the robots (each robot's time in contact with some teammate).
  for (const auto& r : j.at("robots")) rec.time_connected_s += r.at("time_connected_s").get<double>();
  rec.percent_time_fully_connected = j.at("team").at("percent_time_fully_connected").get<double>();
  rec.coverage_percent = j.at("team").at("percent_covered").get<double>();
  rec.all_finished = j.at("team").at("all_finished").get<bool>();
  return rec;
}

}  // namespace autonomy::experiments
