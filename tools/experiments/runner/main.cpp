// experiment_runner: the six configurations of Wagner & Arkin's Table 1, N trials each, through
// the real simulator and three behavior controllers over DDS in lockstep (in one process per trial,
// or with --processes separate a process per node). Trials run
// several at a time, each on a DDS domain of its own. Writes OUT/trials.csv (one row per trial, in
// trial order), OUT/report.md (mean ± sd, Welch t-tests, a typical run's picture per
// configuration) and per trial the simulator's metrics and picture (OUT/<cfg>-<trial>.json/.svg).
#include "tools/experiments/runner/trial.hpp"
#include "tools/experiments/stats/findings.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using autonomy::experiments::TrialSetup;
using autonomy::stats::TrialRecord;

namespace {

struct PlannedTrial {
  std::string configuration;
  int trial = 0;
  uint64_t seed = 0;
};

struct Options {
  int trials = 30;
  uint64_t seed = 1;
  std::string out = "experiment-out";
  std::string source_dir = AUTONOMY_SOURCE_DIR;
  std::string scenario = "deploy/scenarios/recon.pbtxt";
  int domain = 60;
  int jobs = 4;
  std::vector<std::string> only;
};

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

// Every trial of the selected configurations, in the paper's order, seeds drawn in that order
// (so a trial's seed does not depend on how many run at once).
std::vector<PlannedTrial> plan_trials(const Options& o) {
  std::vector<PlannedTrial> out;
  std::mt19937_64 seeds(o.seed);
  for (const auto& cfg : autonomy::stats::table1_configurations()) {
    const bool selected = o.only.empty() || std::find(o.only.begin(), o.only.end(), cfg.id) != o.only.end();
    for (int t = 0; t < o.trials; ++t) {
      const uint64_t seed = seeds();
      if (selected) out.push_back({cfg.id, t, seed});
    }
  }
  return out;
}

// One typical run per configuration (the trial whose mission time is nearest the median), its
// picture copied to typical-<cfg>.svg; returns the report's section.
std::string typical_runs(const std::vector<TrialRecord>& records, const fs::path& out) {
  std::string md = "\n## Typical runs\n\nThe trial whose mission time is nearest the configuration's median.\n\n";
  for (const auto& cfg : autonomy::stats::table1_configurations()) {
    std::vector<const TrialRecord*> mine;
    for (const auto& r : records)
      if (r.configuration == cfg.id) mine.push_back(&r);
    if (mine.empty()) continue;
    std::vector<double> times;
    for (const auto* r : mine) times.push_back(r->mission_time_s);
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    const TrialRecord* typical = mine.front();
    for (const auto* r : mine)
      if (std::fabs(r->mission_time_s - median) < std::fabs(typical->mission_time_s - median)) typical = r;
    const std::string to = "typical-" + cfg.id + ".svg";
    std::error_code ec;
    fs::copy_file(out / (cfg.id + "-" + std::to_string(typical->trial) + ".svg"), out / to,
                  fs::copy_options::overwrite_existing, ec);
    if (!ec) md += "- " + cfg.label + " (trial " + std::to_string(typical->trial) + "): ![" + cfg.id + "](" + to + ")\n";
  }
  return md;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  TrialSetup setup;
  setup.bin_dir = fs::canonical("/proc/self/exe").parent_path().string();
  int timeout_s = 600;
  CLI::App app{"Runs the six configurations of the robot-teams paper's Table 1 through the real processes"};
  app.add_option("--trials", o.trials, "Trials per configuration")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--seed", o.seed, "Seed of the random start positions")->capture_default_str();
  app.add_option("--out", o.out, "Output folder")->capture_default_str();
  app.add_option("--jobs", o.jobs, "Trials run at once (each on its own DDS domain)")
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  app.add_option("--max-ticks", setup.max_ticks, "Simulator ticks a trial may last (0.1 s each in recon)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--resolution", setup.grid_resolution_m, "The behaviors' planning grid resolution, m")
      ->check(CLI::Range(0.05, 5.0))
      ->capture_default_str();
  app.add_option("--domain", o.domain, "First DDS domain id; job k uses domain + k")
      ->check(CLI::Range(0, 232))
      ->capture_default_str();
  std::string processes = "one";
  app.add_option("--processes", processes,
                 "one: a trial's simulator and behaviors run in one process (experiment_trial_host); separate: "
                 "a process each, as deployed (same code and results, more CPU per tick)")
      ->check(CLI::IsMember({"one", "separate"}))
      ->capture_default_str();
  app.add_option("--bin-dir", setup.bin_dir, "Folder holding experiment_trial_host, simulator and behavior")
      ->capture_default_str();
  app.add_option("--source-dir", o.source_dir, "Project folder (deploy/ lives there)")->capture_default_str();
  app.add_option("--scenario", o.scenario, "Scenario, relative to the project folder")->capture_default_str();
  app.add_option("--timeout", timeout_s, "Seconds one trial may take")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--only", o.only, "Run only these configuration ids")
      ->check(CLI::IsMember([] {
        std::vector<std::string> ids;
        for (const auto& c : autonomy::stats::table1_configurations()) ids.push_back(c.id);
        return ids;
      }()));
  CLI11_PARSE(app, argc, argv);
  setup.one_process = processes == "one";
  if (o.domain + o.jobs - 1 > 232) {
    std::fprintf(stderr, "experiment_runner: --domain %d with --jobs %d needs domains up to %d (232 at most)\n",
                 o.domain, o.jobs, o.domain + o.jobs - 1);
    return 2;
  }

  try {
    const fs::path out(o.out);
    fs::create_directories(out / "logs");
    setup.out_dir = fs::absolute(out);
    setup.missions_dir = fs::path(o.source_dir) / "deploy/missions";
    setup.scenario = fs::absolute(fs::path(o.source_dir) / o.scenario);
    setup.timeout = std::chrono::seconds(timeout_s);
    // All children on this host: the loopback profile unless the caller chose one.
    if (std::getenv("CYCLONEDDS_URI") == nullptr)
      setup.dds_uri = "file://" + (fs::path(o.source_dir) / "deploy/dds/loopback.xml").string();

    // Everything the trials need, checked before the first one starts.
    const std::vector<std::string> programs =
        setup.one_process ? std::vector<std::string>{"experiment_trial_host"} : std::vector<std::string>{"simulator", "behavior"};
    for (const auto& program : programs) {
      const fs::path path = fs::path(setup.bin_dir) / program;
      if (access(path.c_str(), X_OK) != 0) throw std::runtime_error("no program " + path.string() + " (see --bin-dir)");
    }
    if (!fs::is_regular_file(setup.scenario)) throw std::runtime_error("no scenario " + setup.scenario.string());
    const std::vector<PlannedTrial> planned = plan_trials(o);
    for (const auto& p : planned) {
      for (const auto& r : setup.robots) {
        const fs::path mission = setup.missions_dir / (p.configuration + "_" + r + ".pbtxt");
        if (!fs::is_regular_file(mission)) throw std::runtime_error("no mission file " + mission.string());
      }
    }
    std::vector<std::optional<TrialRecord>> results(planned.size());
    std::atomic<size_t> next{0};
    std::mutex print;
    int done = 0, failures = 0;
    std::vector<std::string> failure_lines;  // for the report: a failed trial is not silently left out
    const auto begin = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(); };
    std::printf("%zu trials (%d per configuration), %d at a time, %s, output in %s\n", planned.size(), o.trials, o.jobs,
                setup.one_process ? "one process per trial" : "a process per node",
                o.out.c_str());
    std::fflush(stdout);

    std::vector<std::thread> slots;
    for (int slot = 0; slot < o.jobs; ++slot) {
      slots.emplace_back([&, slot] {
        bool first_on_domain = true;
        for (size_t i = next++; i < planned.size(); i = next++) {
          const PlannedTrial& p = planned[i];
          std::string line;
          try {
            results[i] = autonomy::experiments::run_trial(setup, p.configuration, p.trial, p.seed, o.domain + slot,
                                                          first_on_domain);
            first_on_domain = false;
            const TrialRecord& r = *results[i];
            char buf[256];
            std::snprintf(buf, sizeof buf, "mission %6.1f s%s  distance %6.1f m  fully connected %5.1f%%  coverage %4.1f%%",
                          r.mission_time_s, r.all_finished ? "" : " (unfinished)", r.distance_m,
                          r.percent_time_fully_connected, r.coverage_percent);
            line = buf;
          } catch (const std::exception& e) {
            line = std::string("FAILED: ") + e.what();
          }
          std::lock_guard<std::mutex> lock(print);
          ++done;
          if (!results[i]) {
            ++failures;
            failure_lines.push_back("- " + p.configuration + " trial " + std::to_string(p.trial) + ": " + line);
          }
          const double t = elapsed();
          std::printf("[%3d/%zu] %-14s trial %2d  %s  (%.0f s, about %.0f s left)\n", done, planned.size(),
                      p.configuration.c_str(), p.trial, line.c_str(), t, t / done * (planned.size() - done));
          std::fflush(stdout);
        }
      });
    }
    for (auto& s : slots) s.join();

    std::vector<TrialRecord> records;
    for (const auto& r : results)
      if (r) records.push_back(*r);
    write_text(out / "trials.csv", autonomy::stats::write_csv(records));
    std::string failed;
    if (!failure_lines.empty()) {
      std::sort(failure_lines.begin(), failure_lines.end());
      failed = "\n## Failed trials (not in the statistics)\n\n";
      for (const auto& l : failure_lines) failed += l + "\n";
    }
    write_text(out / "report.md",
               autonomy::stats::write_markdown_report(records) +
                   autonomy::stats::write_findings_markdown(autonomy::stats::check_paper_findings(records)) + failed +
                   typical_runs(records, out));
    std::printf("wrote %s/trials.csv and %s/report.md: %zu trials in %.1f s, %d failed\n", o.out.c_str(),
                o.out.c_str(), records.size(), elapsed(), failures);
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "experiment_runner: %s\n", e.what());
    return 2;
  }
}
