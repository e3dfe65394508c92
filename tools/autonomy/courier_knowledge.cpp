// autonomy courier knowledge: what a courier learned from experience, read from its journal
// (the SQLite file of services/courier/journal, opened read-only): handover times per person,
// who answered by half hour of the day, doors open or closed by half hour, driving times between
// places. Text for people, --json for programs.
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "services/courier/core/execution/courier_executive.hpp"
#include "services/courier/journal/journal.hpp"
#include "tools/autonomy/commands.hpp"

namespace autonomy::tools {

namespace {

using courier::Experience;
using courier::HalfHourCounts;

struct KnowledgeOptions {
  std::string journal;
  bool json = false;
};

std::string half_hour(int slot) { return courier::clock_text(slot * 1800.0).substr(0, 5); }

nlohmann::json votes_json(const HalfHourCounts& c, const char* yes, const char* no) {
  nlohmann::json out = nlohmann::json::array();
  for (int s = 0; s < HalfHourCounts::kSlots; ++s) {
    const auto i = static_cast<std::size_t>(s);
    if (c.yes[i] || c.no[i]) out.push_back({{"from", half_hour(s)}, {yes, c.yes[i]}, {no, c.no[i]}});
  }
  return out;
}

// "09:30 2/0  10:00 0/3 usually closed" for the half hours with votes.
void print_votes(const std::string& who, const HalfHourCounts& c, bool (Experience::*habit)(const std::string&, double) const,
                 const Experience& e, const char* habit_words) {
  std::printf("  %-16s", who.c_str());
  int shown = 0;
  for (int s = 0; s < HalfHourCounts::kSlots; ++s) {
    const auto i = static_cast<std::size_t>(s);
    if (!c.yes[i] && !c.no[i]) continue;
    if (shown++ % 4 == 0 && shown > 1) std::printf("\n  %-16s", "");
    std::printf("  %s %d/%d%s", half_hour(s).c_str(), c.yes[i], c.no[i],
                (e.*habit)(who, s * 1800.0 + 1) ? std::string(" ").append(habit_words).c_str() : "");
  }
  std::printf("\n");
}

int show(const KnowledgeOptions& o) {
  Experience e;
  try {
    e = courier::Journal::read_experience(o.journal);
  } catch (const std::exception& err) {
    std::cerr << "autonomy courier knowledge: " << err.what() << "\n";
    return 1;
  }
  if (o.json) {
    nlohmann::json out;
    out["journal"] = o.journal;
    for (const auto& [person, s] : e.handovers())
      out["handovers"][person] = {{"n", s.n}, {"mean_s", s.mean}, {"stddev_s", s.stddev()}};
    for (const auto& [person, c] : e.presence()) out["presence"][person] = votes_json(c, "present", "absent");
    for (const auto& [door, c] : e.doors()) out["doors"][door] = votes_json(c, "open", "closed");
    for (const auto& [pair, s] : e.travel())
      out["travel"].push_back({{"from", pair.first}, {"to", pair.second}, {"n", s.n}, {"mean_s", s.mean}, {"stddev_s", s.stddev()}});
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::printf("What the courier learned (%s)\n", o.journal.c_str());
  if (e.empty()) {
    std::printf("  nothing yet: no handover, door or drive was seen with learning on\n");
    return 0;
  }
  std::printf("\nHandover times (used once %d were seen):\n  %-16s %5s %8s %8s\n", Experience::kMinSamples, "person", "n",
              "mean s", "sd s");
  for (const auto& [person, s] : e.handovers())
    std::printf("  %-16s %5lld %8.1f %8.1f\n", person.c_str(), static_cast<long long>(s.n), s.mean, s.stddev());
  std::printf("\nPresence by half hour (days answered/not; a habit after %d days):\n", Experience::kHabitDays);
  for (const auto& [person, c] : e.presence()) print_votes(person, c, &Experience::usually_absent, e, "usually away");
  std::printf("\nDoors by half hour (days open/closed):\n");
  for (const auto& [door, c] : e.doors()) print_votes(door, c, &Experience::usually_closed, e, "usually closed");
  std::printf("\nDriving times between places (used once %d were seen):\n  %-24s %-24s %5s %8s %8s\n",
              Experience::kMinSamples, "from", "to", "n", "mean s", "sd s");
  for (const auto& [pair, s] : e.travel())
    std::printf("  %-24s %-24s %5lld %8.1f %8.1f\n", pair.first.c_str(), pair.second.c_str(),
                static_cast<long long>(s.n), s.mean, s.stddev());
  return 0;
}

}  // namespace

Command add_courier_knowledge(CLI::App& courier) {
  auto o = std::make_shared<KnowledgeOptions>();
  auto* cmd = courier.add_subcommand("knowledge", "What a courier learned: handover times, presence, door habits, drives");
  cmd->add_option("journal", o->journal, "The courier's journal (courier --journal, default <log-dir>/courier-main.db)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_flag("--json", o->json, "Print JSON instead of tables");
  return {cmd, [o](Context&) { return show(*o); }};
}

}  // namespace autonomy::tools
