#pragma once
// The executive's ScheduleSource on top of the scheduler engines: turns a PlanRequest (robots
// where they are, open jobs, doors believed closed) into a SchedulingProblem with travel times from
// the map — one exact cost-to-go field per place over the behavior's occupancy grid with the
// doors believed closed as walls, cached per set of closed doors — presence windows and expected
// handover times from the office knowledge, runs the exact engine on small job sets and the
// large-scale one above that, each within a time budget, and turns the JobSchedule back into
// routes. A job whose place cannot be reached comes back unschedulable with the door to blame.
// With several robots each job comes back with the allocation rule's words (allocation_rule.hpp).
#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/occupancy_grid.hpp"
#include "services/behavior/core/world_map.hpp"
#include "services/courier/core/execution/floor.hpp"
#include "services/courier/core/execution/schedule_source.hpp"
#include "services/courier/core/knowledge/experience.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace autonomy::courier {

struct EngineSourceSettings {
  double speed_mps = 0.5;        // expected driving speed for travel times
  double robot_radius_m = 0.3;   // obstacles grown by it
  double resolution_m = 0.1;     // of the travel-time grid
  std::string engine = "exact";  // below exact_max_jobs open jobs
  int exact_max_jobs = 8;
  double budget_ms = 50.0;       // wall clock per engine call
};

class EngineScheduleSource : public ScheduleSource {
 public:
  // Throws std::invalid_argument when a place of the floor lies in an obstacle of the map.
  EngineScheduleSource(const OfficeKnowledge& knowledge, const Floor& floor, const behavior::WorldMap& map,
                       EngineSourceSettings settings);
  ~EngineScheduleSource() override;

  Plan plan(const PlanRequest& request) override;

  // Plans with what experience taught (learned_problem.hpp) from now on; nullptr: the office
  // file's nominal values only. The experience must outlive this source.
  void use_experience(const Experience* experience) { experience_ = experience; }

  // The scheduling problem plan() solves for `request` (benchmarks run other allocations on it).
  scheduling::SchedulingProblem problem_for(const PlanRequest& request);
  // The engine plan() uses: `engine` below exact_max_jobs open jobs and while the couriers'
  // assignments can be enumerated (couriers^jobs <= 2^14), else "large".
  std::string engine_for(const scheduling::SchedulingProblem& problem) const;

  // Seconds from place a to place b with the given doors closed (+inf: no way); for tests.
  double travel_s(const std::string& from, const std::string& to, const std::set<std::string>& closed_doors);

 private:
  struct Fields;  // one field per place for one set of closed doors
  const Fields& fields_for(const std::set<std::string>& closed_doors);

  const OfficeKnowledge& knowledge_;
  const Floor& floor_;
  behavior::WorldMap map_;
  EngineSourceSettings settings_;
  std::vector<std::string> place_names_;  // location order of every problem
  std::map<std::set<std::string>, std::unique_ptr<Fields>> cache_;
  // The last plan's routes (robot -> (job, pickup?) in order): the warm start of the next one.
  std::map<std::string, std::vector<std::pair<std::string, bool>>> last_routes_;
  const Experience* experience_ = nullptr;
  std::map<std::string, std::string> learned_notes_;  // of the last problem: person -> what cut their hours
};

}  // namespace autonomy::courier
