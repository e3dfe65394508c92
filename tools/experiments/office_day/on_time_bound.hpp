#pragma once
// How many of a day's jobs any courier fleet could have finished by their deadline: an upper
// bound on the on-time rate, from the doors as they really were that day (the simulator's
// ground truth) and the people's hours. A strategy's on-time rate is read against it: the part
// of the gap that no number of robots and no schedule can close is the office's, not the fleet's.
//
// The ideal courier of the bound has a robot waiting wherever it is needed at the command's
// time, carries one job at a time with no other work, drives straight lines at the robot's top
// speed, and needs a room's door open only at the moment it arrives (not while leaving); its
// handovers take the shortest time the person's model allows. So a job it cannot finish on
// time cannot be finished on time by any real fleet. Pure.
#include <limits>
#include <string>
#include <vector>

#include "tools/experiments/office_day/day_plan.hpp"

namespace autonomy::office_day {

// A door closed over [from_s, to_s) (seconds after the day's start; to_s infinite when it was
// still closed at the end).
struct DoorClosure {
  std::string door;
  double from_s = 0;
  double to_s = std::numeric_limits<double>::infinity();
};

// Folds the door's ground-truth samples (in tick order per door: closed or not, at tick * step_s)
// into closures. A door whose first sample says closed was closed from the day's start.
class DoorHistory {
 public:
  void observe(const std::string& door, double at_s, bool closed);
  std::vector<DoorClosure> closures() const;

 private:
  struct Open {
    std::string door;
    double since_s;
  };
  std::vector<DoorClosure> done_;
  std::vector<Open> closed_now_;
};

struct JobBound {
  std::string command_id;
  bool possible = false;   // an ideal courier finishes it by its deadline
  double earliest_s = 0;   // the ideal courier's completion (infinite: never that day)
  std::string why;         // when not possible: what stops it ("A-120 closed 10:02-11:31")
};

// One entry per command, in the plan's order. Throws std::invalid_argument when a command names
// a place the scenario does not have.
std::vector<JobBound> on_time_bound(const DayPlan& plan, const std::vector<DoorClosure>& closures, double day_end_s);

}  // namespace autonomy::office_day
