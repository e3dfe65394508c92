// experiment_runner: the six configurations of Wagner & Arkin's Table 1, N trials each, through
// the real processes (simulator + three behavior controllers) over DDS in lockstep. Writes
// OUT/trials.csv (one row per trial), OUT/report.md (mean ± sd, Welch t-tests) and per trial the
// simulator's metrics (OUT/<cfg>-<trial>.json/.csv) and picture (OUT/<cfg>-<trial>.svg).
#include "tools/experiments/stats/report.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using autonomy::stats::TrialRecord;

namespace {

const std::vector<std::string> kRobots = {"r1", "r2", "r3"};

// A started child: stdout and stderr into `log`, SIGKILL when the runner dies.
pid_t spawn(const std::string& program, const std::vector<std::string>& args,
            const std::string& log) {
  std::vector<std::string> argv_s = {program};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(program.c_str(), argv.data());
    std::perror(("exec " + program).c_str());
    _exit(127);
  }
  return pid;
}

// Waits up to `timeout` for pid; returns true with the raw status when it ended.
bool wait_for(pid_t pid, std::chrono::seconds timeout, int* status) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    const pid_t r = waitpid(pid, status, WNOHANG);
    if (r == pid) return true;
    if (r < 0) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

void stop(pid_t pid) {
  int status = 0;
  if (waitpid(pid, &status, WNOHANG) != 0) return;
  kill(pid, SIGTERM);
  if (!wait_for(pid, std::chrono::seconds(3), &status)) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

// The scenario without its own robots (the behavior processes attach r1..r3 at --start) and with
// map paths made absolute so the copy can live in the output folder.
std::string scenario_for_attached_robots(const fs::path& scenario) {
  std::string text = read_text(scenario);
  // Remove top-level `robots { ... }` blocks (brace-matched).
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    const bool line_start = i == 0 || text[i - 1] == '\n';
    if (line_start && text.compare(i, 6, "robots") == 0) {
      const size_t open = text.find('{', i);
      if (open == std::string::npos) break;
      int depth = 0;
      size_t j = open;
      for (; j < text.size(); ++j) {
        if (text[j] == '{') ++depth;
        if (text[j] == '}' && --depth == 0) break;
      }
      i = j + 1;
      continue;
    }
    out += text[i++];
  }
  const std::string base = fs::absolute(scenario).parent_path().string() + "/";
  static const std::regex kYaml(R"re(yaml:\s*"([^/"][^"]*)")re");
  return std::regex_replace(out, kYaml, "yaml: \"" + base + "$1\"");
}

struct Options {
  int trials = 30;
  uint64_t seed = 1;
  std::string out = "experiment-out";
  std::string bin_dir;
  std::string source_dir;
  std::string scenario = "deploy/scenarios/recon.pbtxt";
  int max_ticks = 4000;
  int domain = 60;
  double start_min_x = 10.0, start_max_x = 240.0, start_y = 3.0;
  int timeout_s = 900;
  std::vector<std::string> only;
};

TrialRecord run_trial(const Options& o, const autonomy::stats::Configuration& cfg, int trial,
                      uint64_t seed, const fs::path& scenario_copy) {
  const fs::path out(o.out);
  const std::string stem = cfg.id + "-" + std::to_string(trial);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x_dist(o.start_min_x, o.start_max_x);
  std::vector<double> xs;
  for (size_t k = 0; k < kRobots.size(); ++k) xs.push_back(x_dist(rng));

  const std::string domain = std::to_string(o.domain);
  const fs::path logs = out / "logs";
  std::vector<std::string> sim_args = {"--config", scenario_copy.string(), "--domain", domain,
                                       "--log-dir", logs.string(), "--max-ticks",
                                       std::to_string(o.max_ticks), "--metrics",
                                       (out / stem).string(), "--svg",
                                       (out / (stem + ".svg")).string(), "--wait-for"};
  for (const auto& r : kRobots) sim_args.push_back("behavior/" + r);
  fs::remove(out / (stem + ".json"));
  const pid_t sim = spawn(o.bin_dir + "/simulator", sim_args, (logs / (stem + "-sim.out")).string());
  std::vector<pid_t> behaviors;
  for (size_t k = 0; k < kRobots.size(); ++k) {
    const std::string& r = kRobots[k];
    const fs::path mission =
        fs::path(o.source_dir) / "deploy/missions" / (cfg.id + "_" + r + ".pbtxt");
    char x[32], y[32];
    std::snprintf(x, sizeof x, "%.3f", xs[k]);
    std::snprintf(y, sizeof y, "%.3f", o.start_y);
    behaviors.push_back(spawn(o.bin_dir + "/behavior",
                              {"--robot", r, "--mission", mission.string(), "--start", x, y,
                               "--domain", domain, "--log-dir", logs.string()},
                              (logs / (stem + "-" + r + ".out")).string()));
  }
  // Wait for the simulator (it stops at --max-ticks); a behavior that ends first is a failure.
  int status = 0;
  bool ended = false;
  std::string early;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(o.timeout_s);
  while (!ended && early.empty() && std::chrono::steady_clock::now() < deadline) {
    ended = waitpid(sim, &status, WNOHANG) == sim;
    for (size_t k = 0; k < behaviors.size() && !ended; ++k) {
      int bs = 0;
      if (behaviors[k] > 0 && waitpid(behaviors[k], &bs, WNOHANG) == behaviors[k]) {
        behaviors[k] = -1;
        early = kRobots[k];
      }
    }
    if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (!ended) stop(sim);
  for (pid_t b : behaviors) {
    if (b > 0) stop(b);
  }
  if (!early.empty()) {
    throw std::runtime_error(stem + ": behavior " + early + " ended early (see " +
                             (logs / (stem + "-" + early + ".out")).string() + ")");
  }
  if (!ended) throw std::runtime_error(stem + ": simulator did not finish in time");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(stem + ": simulator failed (see " + (logs / (stem + "-sim.out")).string() + ")");
  }
  const auto j = nlohmann::json::parse(read_text(out / (stem + ".json")));
  TrialRecord rec;
  rec.configuration = cfg.id;
  rec.trial = trial;
  rec.seed = seed;
  rec.mission_time_s = j.at("team").at("mission_time_s").get<double>();
  rec.distance_m = j.at("team").at("distance_m").get<double>();
  // Time connected: summed over the robots (each robot's time connected to a teammate).
  for (const auto& r : j.at("robots")) rec.time_connected_s += r.at("time_connected_s").get<double>();
  rec.percent_time_fully_connected = j.at("team").at("percent_time_fully_connected").get<double>();
  rec.coverage_percent = j.at("team").at("percent_covered").get<double>();
  return rec;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  const fs::path self = fs::canonical("/proc/self/exe");
  o.bin_dir = self.parent_path().string();
  o.source_dir = AUTONOMY_SOURCE_DIR;
  CLI::App app{"Runs the six configurations of the robot-teams paper's Table 1 through the real processes"};
  app.add_option("--trials", o.trials, "Trials per configuration")->check(CLI::PositiveNumber);
  app.add_option("--seed", o.seed, "Seed of the random start positions");
  app.add_option("--out", o.out, "Output folder");
  app.add_option("--max-ticks", o.max_ticks, "Simulator ticks per trial (0.1 s each in recon)");
  app.add_option("--domain", o.domain, "DDS domain id for the runs")->check(CLI::Range(0, 232));
  app.add_option("--bin-dir", o.bin_dir, "Folder holding simulator and behavior");
  app.add_option("--source-dir", o.source_dir, "Project folder (deploy/ lives there)");
  app.add_option("--timeout", o.timeout_s, "Seconds one trial may take");
  app.add_option("--only", o.only, "Run only these configuration ids");
  CLI11_PARSE(app, argc, argv);

  try {
    fs::create_directories(fs::path(o.out) / "logs");
    const fs::path scenario_copy = fs::path(o.out) / "scenario.pbtxt";
    write_text(scenario_copy,
               scenario_for_attached_robots(fs::path(o.source_dir) / o.scenario));

    std::vector<TrialRecord> records;
    std::ofstream csv(fs::path(o.out) / "trials.csv");
    csv << autonomy::stats::csv_header() << std::flush;
    std::mt19937_64 seeds(o.seed);
    int failures = 0;
    for (const auto& cfg : autonomy::stats::table1_configurations()) {
      if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), cfg.id) == o.only.end()) continue;
      for (int t = 0; t < o.trials; ++t) {
        const uint64_t seed = seeds();
        const auto begin = std::chrono::steady_clock::now();
        try {
          const TrialRecord rec = run_trial(o, cfg, t, seed, scenario_copy);
          records.push_back(rec);
          csv << autonomy::stats::csv_row(rec) << std::flush;
          const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
          std::printf("%-14s trial %3d/%d  mission %.1f s  distance %.1f m  fully connected %.1f%%  coverage %.1f%%  (%.0f s)\n",
                      cfg.id.c_str(), t + 1, o.trials, rec.mission_time_s, rec.distance_m,
                      rec.percent_time_fully_connected, rec.coverage_percent, secs);
        } catch (const std::exception& e) {
          ++failures;
          std::printf("%-14s trial %3d/%d  FAILED: %s\n", cfg.id.c_str(), t + 1, o.trials, e.what());
        }
        std::fflush(stdout);
      }
    }
    // One typical run per configuration: the trial whose mission time is nearest the median.
    std::string pictures = "\n## Typical runs\n\nThe trial whose mission time is nearest the "
                           "configuration's median.\n\n";
    for (const auto& cfg : autonomy::stats::table1_configurations()) {
      std::vector<const TrialRecord*> mine;
      for (const auto& r : records) {
        if (r.configuration == cfg.id) mine.push_back(&r);
      }
      if (mine.empty()) continue;
      std::vector<double> times;
      for (const auto* r : mine) times.push_back(r->mission_time_s);
      std::sort(times.begin(), times.end());
      const double median = times[times.size() / 2];
      const TrialRecord* typical = mine.front();
      for (const auto* r : mine) {
        if (std::fabs(r->mission_time_s - median) < std::fabs(typical->mission_time_s - median)) typical = r;
      }
      const std::string from = cfg.id + "-" + std::to_string(typical->trial) + ".svg";
      const std::string to = "typical-" + cfg.id + ".svg";
      std::error_code ec;
      fs::copy_file(fs::path(o.out) / from, fs::path(o.out) / to,
                    fs::copy_options::overwrite_existing, ec);
      if (!ec) pictures += "- " + cfg.label + " (trial " + std::to_string(typical->trial) + "): ![" + cfg.id + "](" + to + ")\n";
    }
    write_text(fs::path(o.out) / "report.md",
               autonomy::stats::write_markdown_report(records) + pictures);
    std::printf("wrote %s/trials.csv and %s/report.md (%zu trials, %d failed)\n", o.out.c_str(),
                o.out.c_str(), records.size(), failures);
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "experiment_runner: %s\n", e.what());
    return 2;
  }
}
