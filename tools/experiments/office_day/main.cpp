// office_day: the day-in-office experiment (issue 10). Each strategy works the same seeded days
// of the office through the real simulator, behavior and courier processes over DDS in lockstep;
// writes days.csv (one row per day and strategy), report.md (means, standard deviations, Welch
// t-tests of the findings), on-time.svg, on-time-by-day.svg, and the first day's trajectory and
// Gantt per strategy (courier_plot).
//
//   build/bin/office_day --out runs/office-day                 # the default: 20 days, a..e
//   build/bin/office_day --days 3 --strategies b,c,d --hours 2   # a quick look
#include <CLI/CLI.hpp>
#include <google/protobuf/text_format.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "common/process/child_process.hpp"
#include "services/courier/journal/journal.hpp"
#include "tools/experiments/office_day/day_report.hpp"
#include "tools/experiments/office_day/day_run.hpp"

namespace fs = std::filesystem;
using namespace autonomy;
using namespace autonomy::office_day;

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) out.push_back(part);
  return out;
}

// The knowledge of yesterday's journal, alone, in today's fresh one (yesterday's jobs stay there).
void carry_knowledge(const fs::path& from, const fs::path& to) {
  const courier::Experience learned = courier::Journal::read_experience(from.string());
  courier::Journal(to.string()).save_experience(learned);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The day-in-office experiment: courier strategies a..e over seeded simulated working days"};
  int days = 20, parallel = 5, domain_base = 120;
  std::uint64_t seed = 1;
  std::string strategy_list = "a,b,c,d,e";
  fs::path out = "runs/office-day";
  RunSetup setup;
  setup.bin_dir = fs::canonical("/proc/self/exe").parent_path().string();
  DaySettings day;
  day.habits = default_habits();
  std::string office = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt";
  double hours = day.hours;
  app.add_option("--days", days, "Days per strategy")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_option("--strategies", strategy_list, "Comma-separated ids among a, b, c, d, e")->capture_default_str();
  app.add_option("--seed", seed, "Day k of every strategy uses seed * 1000 + k")->capture_default_str();
  app.add_option("--hours", hours, "Length of a day")->check(CLI::Range(0.25, 12.0))->capture_default_str();
  app.add_option("--jobs-per-hour", day.jobs_per_hour, "Commands per hour (Poisson)")->check(CLI::Range(0.1, 60.0))->capture_default_str();
  // Up to 0.5 s: at 1 s a tick the behavior controller no longer makes progress in the office
  // (every goal ends blocked: measured 2026-12-02), so the range stops where the day was verified.
  app.add_option("--step-s", day.step_s, "Simulated seconds per tick (0.02 to 0.5)")
      ->check(CLI::Range(0.02, 0.5))
      ->capture_default_str();
  app.add_option("--parallel", parallel, "Strategies run side by side (each its own DDS domain)")->check(CLI::Range(1, 8))->capture_default_str();
  app.add_option("--domain-base", domain_base, "DDS domains domain-base .. domain-base + 4")->check(CLI::Range(0, 220))->capture_default_str();
  app.add_option("--office", office, "The office scenario the days are made from")->check(CLI::ExistingFile);
  app.add_option("--out", out, "Output folder")->capture_default_str();
  app.add_flag("--every-tick", setup.every_tick,
               "Publish every tick, also those nobody needs (slower; the same day: for comparison)");
  app.add_option("--bin-dir", setup.bin_dir, "Folder of simulator, behavior, courier, courier_plot")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  day.hours = hours;
  setup.day_s = hours * 3600.0;
  setup.out_dir = fs::absolute(out);
  setup.trajectory = true;  // only day 1 is drawn; the CSV is small next to the logs

  std::vector<const Strategy*> chosen;
  for (const std::string& id : split(strategy_list)) {
    const Strategy* s = strategy(id);
    if (!s) {
      std::cerr << "office_day: no strategy '" << id << "' (a, b, c, d, e)\n";
      return 2;
    }
    chosen.push_back(s);
  }
  config::Scenario base;
  {
    std::ifstream in(office);
    std::stringstream text;
    text << in.rdbuf();
    if (!google::protobuf::TextFormat::ParseFromString(text.str(), &base)) {
      std::cerr << "office_day: " << office << " is not a scenario (see simulator --config " << office << ")\n";
      return 2;
    }
  }
  if (!std::getenv("CYCLONEDDS_URI"))
    setenv("CYCLONEDDS_URI", ("file://" + std::string(AUTONOMY_SOURCE_DIR) + "/deploy/dds/loopback.xml").c_str(), 1);
  fs::create_directories(setup.out_dir / "days");

  std::mutex mutex;
  std::vector<DayRecord> records;
  std::vector<std::string> failures;
  std::atomic<std::size_t> next_lane{0};
  const auto experiment_start = std::chrono::steady_clock::now();
  const auto lane = [&](int worker) {
    for (std::size_t i; (i = next_lane++) < chosen.size();) {
      const Strategy& s = *chosen[i];
      DaySettings settings = day;
      settings.couriers = s.couriers;
      // The journal of the last day that ran to its end: a failed day does not end the learning.
      fs::path knowledge_from;
      for (int k = 1; k <= days; ++k) {
        const std::uint64_t day_seed = seed * 1000 + static_cast<std::uint64_t>(k);
        try {
          const DayPlan plan = plan_day(base, settings, day_seed);
          const fs::path journal = day_file(setup, s.id, k, "db");
          for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(journal.string() + suffix);
          if (s.carries_knowledge && !knowledge_from.empty()) carry_knowledge(knowledge_from, journal);
          RunSetup mine = setup;
          mine.trajectory = k == 1;
          const DayRecord r = run_day(mine, s, plan, k, day_seed, domain_base + worker, journal);
          knowledge_from = journal;
          std::lock_guard<std::mutex> lock(mutex);
          records.push_back(r);
          std::printf("office_day: (%s) day %d/%d: %d jobs, %d on time (%.0f %%), mean lateness %.1f min, %.0f m, "
                      "%.0f s wall [%.0f s so far]\n",
                      s.id.c_str(), k, days, r.jobs, r.on_time, r.on_time_percent, r.mean_lateness_s / 60,
                      r.distance_m, r.wall_s,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - experiment_start).count());
          std::fflush(stdout);
        } catch (const std::exception& e) {
          std::lock_guard<std::mutex> lock(mutex);
          failures.push_back("(" + s.id + ") day " + std::to_string(k) + ": " + e.what());
          std::fprintf(stderr, "office_day: %s\n", failures.back().c_str());
        }
      }
    }
  };
  std::vector<std::thread> workers;
  for (int w = 0; w < std::min<int>(parallel, static_cast<int>(chosen.size())); ++w) workers.emplace_back(lane, w);
  for (auto& w : workers) w.join();
  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - experiment_start).count();

  std::sort(records.begin(), records.end(), [](const DayRecord& a, const DayRecord& b) {
    return std::tie(a.strategy, a.day) < std::tie(b.strategy, b.day);
  });
  std::ofstream(setup.out_dir / "days.csv") << csv_header() << [&] {
    std::string rows;
    for (const DayRecord& r : records) rows += csv_row(r);
    return rows;
  }();
  std::ostringstream how;
  how << "`office_day --days " << days << " --strategies " << strategy_list << " --seed " << seed << " --hours "
      << hours << " --jobs-per-hour " << day.jobs_per_hour << " --step-s " << day.step_s << " --parallel " << parallel
      << "`: " << records.size() << " days in " << static_cast<int>(total_s) << " s of wall time";
  std::vector<std::string> notes = {how.str() + ".", ""};
  notes.push_back("Door habits (each on 80 % of days, ends moved by up to 10 min): A-120 10:00-11:30, A-114 "
                  "13:00-14:30, A-118 15:00-16:00; A-116 and A-113 open and close at random (the office floor's own).");
  for (const std::string& f : failures) notes.push_back("- failed: " + f);
  std::ofstream(setup.out_dir / "report.md") << write_report(records, "A day in the office: courier strategies", notes);
  std::ofstream(setup.out_dir / "on-time.svg") << on_time_svg(records);
  std::ofstream(setup.out_dir / "on-time-by-day.svg") << on_time_by_day_svg(records);

  // The first day of each strategy drawn: trajectories and the jobs' Gantt.
  for (const Strategy* s : chosen) {
    const fs::path trajectory = day_file(setup, s->id, 1, "trajectory.csv");
    if (!fs::exists(trajectory)) continue;
    process::ChildProcess plot(
        "courier_plot", (fs::path(setup.bin_dir) / "courier_plot").string(),
        {"--scenario", day_file(setup, s->id, 1, "pbtxt").string(), "--trajectory", trajectory.string(), "--events",
         day_file(setup, s->id, 1, "events.jsonl").string(), "--trajectory-svg",
         (setup.out_dir / ("day1-" + s->id + "-trajectory.svg")).string(), "--gantt-svg",
         (setup.out_dir / ("day1-" + s->id + "-gantt.svg")).string(), "--caption",
         "day 1, strategy (" + s->id + "): " + s->label},
        {}, (setup.out_dir / "logs" / ("plot-" + s->id + ".out")).string());
    plot.wait_for_exit(std::chrono::seconds(120));
  }
  std::printf("office_day: %zu days in %.0f s; %s/report.md\n", records.size(), total_s, setup.out_dir.c_str());
  return failures.empty() ? 0 : 1;
}
