#pragma once
// The mission the executive flies: the planner model and the whole problem (a day, say), cut
// into planning requests for one horizon at a time or for the rest of a horizon after an
// abort. The problem's times are mission time (0 = the mission's start); a request moves them
// to its own origin (plan time 0 = `origin`), drops the goals already settled (achieved or
// lost) and those a disabled device makes impossible, and reports goals whose window has
// passed. No DDS: the node sends what this builds.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/msg/planner.hpp"
#include "idl/planner_model.pb.h"

namespace autonomy::executive {

namespace pb = planner::pb;

using MissionTime = std::int64_t;

struct GoalWindowCut {
  msg::PlanningRequest request;
  std::vector<std::string> goals;                    // labels asked for, in problem order
  std::map<std::string, std::string> lost;           // label -> why it cannot be asked for
};

class Mission {
 public:
  // Reads both files; nullopt with "file:line:column: message" lines in `error` otherwise.
  static std::optional<Mission> load(const std::string& model_path, const std::string& problem_path,
                                     std::string* error);
  // From texts already read (tests).
  static std::optional<Mission> parse(std::string model_text, const std::string& model_file,
                                      const std::string& problem_text, const std::string& problem_file,
                                      std::string* error);

  MissionTime horizon() const { return problem_.horizon(); }
  const pb::Problem& problem() const { return problem_; }
  std::vector<std::string> goal_labels() const;
  // The timeline ("object.attribute") of a goal, "" when unknown.
  std::string goal_timeline(const std::string& label) const;

  // A request for the plan of mission time [origin, end): every goal not in `settled` whose
  // start can still be at or after `origin` and may begin before `end`; the timelines in
  // `impossible` (their device is no longer commanded) get none. Goals in `executing` (begun
  // under the plan being replaced) start again at plan time 0. `state` replaces initial
  // values (plan time 0 = origin). `every_goal_optional`: after an infeasible answer, the
  // planner may leave goals out (penalty 1 each) and keeps what the faults still allow.
  GoalWindowCut request(MissionTime origin, MissionTime end,
                        const std::vector<msg::PlannerTimelineValue>& state,
                        const std::set<std::string>& settled,
                        const std::map<std::string, std::string>& impossible,
                        const std::set<std::string>& executing = {},
                        bool every_goal_optional = false) const;
  // Timelines the problem gives an initial value: the spacecraft's state, carried from one
  // plan into the next (the others, like a ground-station schedule, come from goals).
  std::set<std::string> state_timelines() const;
  // The problem's initial value of a timeline: what it rests at when no token holds it (the
  // engine off after its last thrust arc).
  std::optional<msg::PlannerTimelineValue> initial_value(const std::string& timeline) const;

 private:
  Mission(std::string model_text, std::string model_file, pb::Problem problem, std::string problem_file)
      : model_text_(std::move(model_text)),
        model_file_(std::move(model_file)),
        problem_(std::move(problem)),
        problem_file_(std::move(problem_file)) {}

  std::string model_text_, model_file_;
  pb::Problem problem_;
  std::string problem_file_;
};

}  // namespace autonomy::executive
