#pragma once
// The executive's view of a scheduler: it asks for a plan of the open jobs from the current state
// and gets an ordered route per robot. One implementation wraps the scheduler engines
// (services/courier/core/scheduler) with travel times from the map and the doors believed closed;
// unit tests use hand-written plans.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace autonomy::courier {

struct PlanRobot {
  std::string id;
  double x = 0.0, y = 0.0;  // where it is now
  int capacity = 1;
  // When it can set out (at once when not after now): later while it waits for a room another
  // robot of the fleet holds, when that robot is expected to have left (room_claims.cpp). So the
  // schedule counts the wait, and may give the job to a robot that need not wait.
  double available_s = 0.0;
};

struct PlanJob {
  std::string id;
  std::string lookalike_class;
  std::string pickup;       // where the object lies (ignored while aboard)
  std::string destination;  // where it must go (the return place while returning)
  std::optional<double> deadline_s;
  std::string aboard;  // the robot carrying the object, or ""
  std::string robot;   // the robot it is assigned to, or "": where a forced first pickup goes
  // Aboard and not to be delivered now (an opportunistic job waiting for its door or for an
  // opportunity): it only takes its place aboard (capacity, look-alikes); the schedule leaves its
  // delivery out.
  bool keep_aboard = false;
};

struct PlanRequest {
  double now_s = 0.0;  // seconds of the day
  std::vector<PlanRobot> robots;
  std::vector<PlanJob> jobs;
  std::set<std::string> closed_doors;  // doors believed closed: obstacles for travel times
  // Doors seen open in the last ten minutes: what they usually are at this hour does not matter.
  std::set<std::string> doors_seen_open;
  // Jobs whose first open step must come first on their robot (the opportunity check).
  std::vector<std::string> first;
};

struct PlanStop {
  std::string job_id;
  bool load = true;  // false: unload
  std::string place;
  std::string room;
  double arrival_s = 0.0;
  double finish_s = 0.0;
};

struct Plan {
  std::map<std::string, std::vector<PlanStop>> routes;  // robot -> stops in order
  std::map<std::string, std::string> unschedulable;     // job -> why (e.g. "A-120 closed")
  // Of those, the jobs that can no longer be done today: a person they need is not present again.
  std::set<std::string> gone_for_good;
  std::map<std::string, double> completion_s;           // job -> predicted completion
  // job -> why its robot (several robots only): "assigned to rhino2: 3 min earlier than rhino1"
  std::map<std::string, std::string> allocation;
  int late_jobs = 0;
  double total_lateness_s = 0.0;
  std::string engine;
  bool proved_optimal = false;
  // No schedule at all (out of budget before the first one, an invalid problem): routes are empty
  // and the executive keeps the ones it drives, trying again a moment later.
  bool failed = false;
  std::string failure;
};

class ScheduleSource {
 public:
  virtual ~ScheduleSource() = default;
  virtual Plan plan(const PlanRequest& request) = 0;
};

}  // namespace autonomy::courier
