#include "services/courier/core/knowledge/experience.hpp"

#include <cmath>

namespace autonomy::courier {

void RunningStats::add(double x) {
  ++n;
  const double delta = x - mean;
  mean += delta / static_cast<double>(n);
  m2 += delta * (x - mean);
}

double RunningStats::stddev() const { return n < 2 ? 0.0 : std::sqrt(m2 / static_cast<double>(n - 1)); }

int HalfHourCounts::slot_of(double seconds_of_day) {
  const double day = std::fmod(seconds_of_day, 86400.0);
  const int slot = static_cast<int>(std::floor((day < 0 ? day + 86400.0 : day) / kSlotS));
  return slot < 0 ? 0 : slot >= kSlots ? kSlots - 1 : slot;
}

bool Experience::vote(HalfHourCounts& counts, std::set<std::tuple<std::string, std::int64_t, int>>& voted,
                      const std::string& who, double seconds_of_day, bool yes, std::int64_t day) {
  const int slot = HalfHourCounts::slot_of(seconds_of_day);
  if (!voted.insert({who, day, slot}).second) return false;
  (yes ? counts.yes : counts.no)[static_cast<std::size_t>(slot)] += 1;
  return true;
}

void Experience::handover(const std::string& person, double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return;
  handovers_[person].add(seconds);
  ++unsaved_;
}

void Experience::presence(const std::string& person, double seconds_of_day, bool present, std::int64_t day) {
  if (vote(presence_[person], presence_voted_, person, seconds_of_day, present, day)) ++unsaved_;
}

void Experience::door(const std::string& door, double seconds_of_day, bool open, std::int64_t day) {
  if (vote(doors_[door], door_voted_, door, seconds_of_day, open, day)) ++unsaved_;
}

void Experience::travel(const std::string& from, const std::string& to, double seconds) {
  if (!std::isfinite(seconds) || seconds < 0 || from == to) return;
  travel_[{from, to}].add(seconds);
  ++unsaved_;
}

double Experience::expected_handover(const std::string& person, double nominal) const {
  const auto it = handovers_.find(person);
  return it == handovers_.end() || it->second.n < kMinSamples ? nominal : it->second.mean;
}

namespace {

// Votes in the slot and the chance of "yes" with a prior of two yes, one no.
std::pair<int, double> chance(const std::map<std::string, HalfHourCounts>& all, const std::string& who,
                              double seconds_of_day) {
  const auto it = all.find(who);
  if (it == all.end()) return {0, 2.0 / 3.0};
  const auto slot = static_cast<std::size_t>(HalfHourCounts::slot_of(seconds_of_day));
  const int yes = it->second.yes[slot], no = it->second.no[slot];
  return {yes + no, (yes + 2.0) / (yes + no + 3.0)};
}

}  // namespace

double Experience::p_open(const std::string& door, double seconds_of_day) const {
  return chance(doors_, door, seconds_of_day).second;
}

double Experience::p_present(const std::string& person, double seconds_of_day) const {
  return chance(presence_, person, seconds_of_day).second;
}

bool Experience::usually_closed(const std::string& door, double seconds_of_day) const {
  const auto [votes, p] = chance(doors_, door, seconds_of_day);
  return votes >= kHabitDays && p < 0.5;
}

bool Experience::usually_absent(const std::string& person, double seconds_of_day) const {
  const auto [votes, p] = chance(presence_, person, seconds_of_day);
  return votes >= kHabitDays && p < 0.5;
}

std::optional<double> Experience::travel_time(const std::string& from, const std::string& to) const {
  const auto it = travel_.find({from, to});
  if (it == travel_.end() || it->second.n < kMinSamples) return std::nullopt;
  return it->second.mean;
}

void Experience::restore_presence(const std::string& person, int slot, int yes, int no) {
  if (slot < 0 || slot >= HalfHourCounts::kSlots) return;
  presence_[person].yes[static_cast<std::size_t>(slot)] = yes;
  presence_[person].no[static_cast<std::size_t>(slot)] = no;
}

void Experience::restore_door(const std::string& door, int slot, int open, int closed) {
  if (slot < 0 || slot >= HalfHourCounts::kSlots) return;
  doors_[door].yes[static_cast<std::size_t>(slot)] = open;
  doors_[door].no[static_cast<std::size_t>(slot)] = closed;
}

}  // namespace autonomy::courier
