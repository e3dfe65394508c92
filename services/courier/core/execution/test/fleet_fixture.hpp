#pragma once
// The executive with several robots against a scripted fleet scheduler: FleetScheduler (jobs to
// the robot a test prefers, else to the one with the fewest) and the FleetTest fixture (stepping,
// reaching places, completing handovers, the events by kind). fleet_test.cpp, room_claims_test.cpp.
#include "services/courier/core/execution/courier_executive.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "services/courier/core/execution/test/paper_floor.hpp"

namespace autonomy::courier::test_support {

// Jobs aboard stay with their carrier; the others go to the robot `prefer` names when it is
// planned for, else to the robot with the fewest jobs so far. 60 s per stop. Records requests.
class FleetScheduler : public ScheduleSource {
 public:
  Plan plan(const PlanRequest& request) override {
    requests.push_back(request);
    Plan plan;
    plan.engine = "fleet-test";
    std::map<std::string, double> t;
    for (const auto& r : request.robots) t[r.id] = request.now_s;
    if (t.empty()) return plan;
    for (const PlanJob& j : request.jobs) {
      if (j.keep_aboard) {
        plan.unschedulable[j.id] = "kept aboard";
        continue;
      }
      std::string robot = j.aboard;
      if (robot.empty()) {
        const auto p = prefer.find(j.id);
        if (p != prefer.end() && t.count(p->second)) {
          robot = p->second;
        } else {
          robot = t.begin()->first;
          for (const auto& [id, when] : t)
            if (plan.routes[id].size() < plan.routes[robot].size()) robot = id;
        }
      }
      if (j.aboard.empty())
        plan.routes[robot].push_back({j.id, true, j.pickup, "", t[robot] += 60, t[robot]});
      plan.routes[robot].push_back({j.id, false, j.destination, "", t[robot] += 60, t[robot]});
      plan.completion_s[j.id] = t[robot];
      plan.allocation[j.id] = "assigned to " + robot + ": test";
    }
    return plan;
  }
  std::vector<PlanRequest> requests;
  std::map<std::string, std::string> prefer;
};

inline Job delivery(const std::string& id, const std::string& object, const std::string& from,
             const std::string& to) {
  Job j;
  j.id = id;
  j.command_id = "c-" + id;
  j.object = {object, "letter", object};
  j.pickup = from;
  j.destination = to;
  return j;
}

class FleetTest : public ::testing::Test {
 protected:
  explicit FleetTest(Floor floor = paper_floor()) : exec_(std::move(floor), scheduler_) {}

  Orders step() {
    Orders o = exec_.step(now_);
    for (const auto& e : o.events) events_.push_back({e.kind, e.text});
    for (const auto& g : o.goals) goals_[g.robot] = g;
    for (const auto& h : o.handovers) handovers_[h.robot] = h;
    return o;
  }
  void reach(const std::string& robot, double x, double y) {
    now_ += 30;
    exec_.on_pose(robot, x, y);
    exec_.on_goal(robot, goals_.at(robot).goal_id, GoalOutcome::reached, "", now_);
    step();
  }
  void complete(const std::string& robot) {
    now_ += 10;
    exec_.on_handover(handovers_.at(robot).request_id, HandoverOutcome::completed, "", "", now_);
    step();
  }
  std::vector<std::string> texts(ExecutionEvent::Kind kind) const {
    std::vector<std::string> out;
    for (const auto& [k, text] : events_)
      if (k == kind) out.push_back(text);
    return out;
  }

  FleetScheduler scheduler_;
  CourierExecutive exec_;
  double now_ = 9 * 3600.0;
  std::vector<std::pair<ExecutionEvent::Kind, std::string>> events_;
  std::map<std::string, NavGoalOrder> goals_;
  std::map<std::string, HandoverOrder> handovers_;
};

}  // namespace autonomy::courier::test_support
