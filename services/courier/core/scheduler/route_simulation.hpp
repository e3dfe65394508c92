#pragma once
// Internal to the scheduler library: the one place where a stop's timing and cost are computed.
// evaluate_order and every engine step routes with RouteSimulator, so they cannot disagree on what
// a schedule costs. Jobs are flattened into JobData once per solve (no strings, no lookups).
#include "services/courier/core/scheduler/job_schedule.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace autonomy::courier::scheduling::detail {

// Couriers carry at most this many objects (problem_error enforces it): the aboard set is inline.
constexpr int kMaxCapacity = 16;

struct JobData {
  int pick_loc = -1;
  int del_loc = -1;
  int pick_person = -1;
  int del_person = -1;
  double pick_dur = 0.0;
  double del_dur = 0.0;
  double deadline = kNoRoute;  // +inf = none
  // Presence windows of the person at each end; nullptr = always available (station, or a person
  // without windows).
  const std::vector<TimeWindow>* pick_windows = nullptr;
  const std::vector<TimeWindow>* del_windows = nullptr;
  int cls = 0;             // look-alike class id
  int fixed_courier = -1;  // the courier it is aboard, or -1
  bool aboard = false;
};

// earliest_handover_start on flattened windows (the hot path of every engine).
inline double start_within(const std::vector<TimeWindow>* windows, double arrival,
                           double duration) {
  if (!windows) return arrival;
  for (const TimeWindow& w : *windows) {
    const double begin = arrival > w.start_s ? arrival : w.start_s;
    if (begin + duration <= w.end_s) return begin;
  }
  return kNoRoute;
}

struct RouteState {
  double t = 0.0;
  int loc = -1;
  bool visited = false;  // at least one stop done (so a stop at `loc` joins the current visit)
  int load = 0;
  std::array<int, kMaxCapacity> aboard{};  // job indices, first `load` valid
  Objective cost;

  bool carries(int job) const;
  void drop(int job);
};

class RouteSimulator {
 public:
  explicit RouteSimulator(const SchedulingProblem& problem);

  const SchedulingProblem& problem() const { return *p_; }
  const std::vector<JobData>& jobs() const { return jobs_; }
  const JobData& job(int j) const { return jobs_[static_cast<std::size_t>(j)]; }
  double travel(int from, int to) const {
    return p_->travel.at(static_cast<std::size_t>(from), static_cast<std::size_t>(to));
  }
  int courier_count() const { return static_cast<int>(p_->couriers.size()); }

  // Before the first stop (forced prefix not applied). Objects aboard are the jobs aboard it.
  RouteState start(int courier) const;

  // Why `stop` cannot be done next from `s` (capacity, look-alike, not aboard / already aboard);
  // nullptr when it can. Timing is not checked here.
  const char* refusal(const RouteState& s, StopRef stop) const;
  // Capacity and look-alike only (the engines know the stop order is otherwise right).
  bool may_pick_up(const RouteState& s, int job) const;

  // Drives to the stop and does the handover: false (s unspecified) when there is no route or no
  // presence window fits. Does not check refusal(). Fills `out` when given.
  bool advance(RouteState& s, StopRef stop, ScheduledStop* out = nullptr) const;
  // advance's timing and cost only, on the parts of a state they depend on (the exact engine
  // keeps the aboard set as masks and checks the rules on them).
  bool timed_step(double& t, int& at, bool& visited, Objective& cost, StopRef stop,
                  ScheduledStop* out = nullptr) const;

  // Lower bound on the finish of job j's delivery from state s (ignoring all other jobs).
  double earliest_completion(const RouteState& s, int j) const;

  // Lower bound on each handover's duration (for completion-time bounds).
  double min_delivery_duration() const { return min_del_dur_; }

 private:
  const SchedulingProblem* p_;
  std::vector<JobData> jobs_;
  double min_del_dur_ = 0.0;
};

// Appends the rooms entered by one courier's route to `out` (see RoomAssumption).
void collect_assumptions(const SchedulingProblem& problem, const CourierRoute& route,
                         std::vector<RoomAssumption>& out);

}  // namespace autonomy::courier::scheduling::detail
