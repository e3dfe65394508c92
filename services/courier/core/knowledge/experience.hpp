#pragma once
// What the courier learns from experience (the paper's closing wish: "the expected duration of
// loading and unloading, when people are usually in their offices, when doors are open or
// closed"): per person the handover durations (running statistics) and whether they answered,
// by half hour of the day; per door open or closed by half hour; per pair of places the travel
// times driven. Pure data with queries; the journal keeps it across runs, the scheduler's
// problem builder uses it (engine_schedule_source), `autonomy courier knowledge` prints it.
//
// Times of day vote once per day: a door watched for an hour is one observation per half hour
// of that day, not one per sighting, so a habit needs several days to form (kHabitDays).
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

namespace autonomy::courier {

// Welford's running mean and variance.
struct RunningStats {
  std::int64_t n = 0;
  double mean = 0.0;
  double m2 = 0.0;
  void add(double x);
  double stddev() const;  // sample standard deviation; 0 below two samples
};

// Votes for "yes" (present, open) and "no" per half hour of the day.
struct HalfHourCounts {
  static constexpr int kSlots = 48;
  static constexpr double kSlotS = 86400.0 / kSlots;
  std::array<int, kSlots> yes{}, no{};
  static int slot_of(double seconds_of_day);  // wraps into [0, 48)
};

class Experience {
 public:
  // Days of evidence in a half hour before it overrules what the office file says.
  static constexpr int kHabitDays = 3;
  // Samples before a learned handover time or travel time replaces the nominal one.
  static constexpr int kMinSamples = 3;

  // Observations. `day` tells days apart for the once-per-day votes (any number that changes
  // from day to day: the journal's run, or the day count of a long-running clock).
  void handover(const std::string& person, double seconds);
  void presence(const std::string& person, double seconds_of_day, bool present, std::int64_t day);
  void door(const std::string& door, double seconds_of_day, bool open, std::int64_t day);
  void travel(const std::string& from, const std::string& to, double seconds);

  // Queries.
  // The mean of the handovers seen once kMinSamples were seen, else `nominal`.
  double expected_handover(const std::string& person, double nominal) const;
  // Chance the door is open in that half hour: open votes + 2 over all votes + 3 (a prior of two
  // days open, one closed: doors never seen are assumed open, as the schedule assumes).
  double p_open(const std::string& door, double seconds_of_day) const;
  double p_present(const std::string& person, double seconds_of_day) const;  // prior: 2 of 3
  // A habit: at least kHabitDays votes in the half hour and the chance below 1/2.
  bool usually_closed(const std::string& door, double seconds_of_day) const;
  bool usually_absent(const std::string& person, double seconds_of_day) const;
  // The mean driving time from -> to once kMinSamples were seen.
  std::optional<double> travel_time(const std::string& from, const std::string& to) const;

  bool empty() const { return handovers_.empty() && presence_.empty() && doors_.empty() && travel_.empty(); }
  // Observations since the last mark_saved() (the node saves when there are any).
  std::uint64_t unsaved() const { return unsaved_; }
  void mark_saved() { unsaved_ = 0; }

  // For the journal and for printing.
  const std::map<std::string, RunningStats>& handovers() const { return handovers_; }
  const std::map<std::string, HalfHourCounts>& presence() const { return presence_; }
  const std::map<std::string, HalfHourCounts>& doors() const { return doors_; }
  const std::map<std::pair<std::string, std::string>, RunningStats>& travel() const { return travel_; }
  void restore_handover(const std::string& person, RunningStats s) { handovers_[person] = s; }
  void restore_presence(const std::string& person, int slot, int yes, int no);
  void restore_door(const std::string& door, int slot, int open, int closed);
  void restore_travel(const std::string& from, const std::string& to, RunningStats s) { travel_[{from, to}] = s; }

 private:
  static bool vote(HalfHourCounts& counts, std::set<std::tuple<std::string, std::int64_t, int>>& voted,
                   const std::string& who, double seconds_of_day, bool yes, std::int64_t day);

  std::map<std::string, RunningStats> handovers_;
  std::map<std::string, HalfHourCounts> presence_, doors_;
  std::map<std::pair<std::string, std::string>, RunningStats> travel_;
  // (who, day, slot) already voted, this run only.
  std::set<std::tuple<std::string, std::int64_t, int>> presence_voted_, door_voted_;
  std::uint64_t unsaved_ = 0;
};

}  // namespace autonomy::courier
