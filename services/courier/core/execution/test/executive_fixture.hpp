#pragma once
// The executive against a scripted scheduler, for the executive's unit tests: InOrderScheduler
// (jobs in the order asked, 60 s per stop, doors, capacity and objects kept aboard respected) and the ExecutiveTest
// fixture (rhino on the paper's floor, stepping, arriving, handing over).
#include "services/courier/core/execution/courier_executive.hpp"
#include "services/courier/core/execution/test/paper_floor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace autonomy::courier::test_support {

// Serves the jobs in the order of the request (forced ones first); a job behind a closed door is
// unschedulable. Each stop takes 60 s.
class InOrderScheduler : public ScheduleSource {
 public:
  explicit InOrderScheduler(const Floor& floor) : floor_(floor) {}
  Plan plan(const PlanRequest& request) override {
    ++calls;
    last_request = request;
    Plan plan;
    plan.engine = "in-order";
    std::vector<PlanJob> jobs = request.jobs;
    if (newest_first) std::reverse(jobs.begin(), jobs.end());
    std::stable_sort(jobs.begin(), jobs.end(), [&](const PlanJob& a, const PlanJob& b) {
      const auto first = [&](const PlanJob& j) {
        return std::find(request.first.begin(), request.first.end(), j.id) != request.first.end();
      };
      return first(a) > first(b);
    });
    const std::string robot = request.robots.front().id;
    // Objects aboard that cannot be delivered (behind a closed door) keep their place aboard:
    // no pickup beyond what is left.
    const int aboard = static_cast<int>(std::count_if(request.jobs.begin(), request.jobs.end(), [&](const PlanJob& j) {
      const auto door = floor_.door_to(j.destination);
      return !j.aboard.empty() && (j.keep_aboard || (door && request.closed_doors.count(*door)));
    }));
    double t = request.now_s;
    for (const PlanJob& j : jobs) {
      const auto closed = [&](const std::string& place) {
        const auto door = floor_.door_to(place);
        return door && request.closed_doors.count(*door);
      };
      if ((j.aboard.empty() && closed(j.pickup)) || closed(j.destination)) {
        plan.unschedulable[j.id] = "behind a closed door";
        continue;
      }
      if (j.keep_aboard) {
        plan.unschedulable[j.id] = "kept aboard";
        continue;
      }
      if (clashes.count(j.id)) {
        plan.unschedulable[j.id] = clashes.at(j.id);
        continue;
      }
      if (gone.count(j.destination)) {
        plan.unschedulable[j.id] = "nobody at " + j.destination + " again today";
        plan.gone_for_good.insert(j.id);
        continue;
      }
      if (j.aboard.empty() && aboard >= request.robots.front().capacity) {
        plan.unschedulable[j.id] = "no room aboard";
        continue;
      }
      if (j.aboard.empty()) {
        t += 60;
        plan.routes[robot].push_back({j.id, true, j.pickup, floor_.place(j.pickup)->room, t, t});
      }
      t += 60;
      plan.routes[robot].push_back({j.id, false, j.destination, floor_.place(j.destination)->room, t, t});
      plan.completion_s[j.id] = t;
    }
    return plan;
  }
  int calls = 0;
  PlanRequest last_request;
  bool newest_first = false;  // the jobs in the reverse order of the request
  std::set<std::string> gone;  // places whose person is not there again today
  std::map<std::string, std::string> clashes;  // jobs left out -> why (no door, not gone)

 private:
  const Floor& floor_;
};

inline Job delivery(const std::string& id, const std::string& object, const std::string& colour, const std::string& kind,
             const std::string& from, const std::string& to) {
  Job j;
  j.id = id;
  j.command_id = "c-" + id;
  j.object = {object, kind, colour};
  j.pickup = from;
  j.destination = to;
  return j;
}

class ExecutiveTest : public ::testing::Test {
 protected:
  ExecutiveTest() : floor_(paper_floor()), scheduler_(floor_), exec_(floor_, scheduler_) {
    exec_.add_robot("rhino", 3);
    exec_.on_pose("rhino", 1.5, 8.0);
  }

  // Steps once and keeps what happened.
  Orders step() {
    Orders o = exec_.step(now_);
    for (const auto& e : o.events) events_.push_back(e.text);
    for (const auto& g : o.goals) last_goal_ = g;
    for (const auto& h : o.handovers) last_handover_ = h;
    return o;
  }
  // The robot reaches the place of its last goal.
  void arrive() {
    now_ += 30;
    exec_.on_goal("rhino", last_goal_.goal_id, GoalOutcome::reached, "", now_);
    step();
  }
  // Job j1 from the meeting table: its room's door A-111 is seen closed on the way.
  void meeting_room_seen_closed() {
    exec_.add_job(delivery("j1", "letter-red", "red", "letter", "meeting-table", "michael-desk"), now_);
    step();
    exec_.on_door("rhino", "A-111", 0.0, now_);
    step();
  }
  // Job j1 from the librarian's desk: the robot gets there at 09:01, nobody is in until 10:00.
  void librarian_is_out_until_ten() {
    exec_.add_job(delivery("j1", "book-green", "green", "book", "librarian-desk", "a114-desk"), now_);
    step();
    arrive();
    exec_.on_handover(last_handover_.request_id, HandoverOutcome::rejected, "nobody_present",
                      "nobody at librarian-desk at 09:01 (somebody is back at 10:00)", now_);
    step();
  }
  void complete_handover() {
    now_ += 10;
    exec_.on_handover(last_handover_.request_id, HandoverOutcome::accepted, "", "", now_);
    exec_.on_handover(last_handover_.request_id, HandoverOutcome::completed, "", "", now_);
    step();
  }
  std::string goal_place() const { return last_goal_.goal_id.substr(6, last_goal_.goal_id.rfind('/') - 6); }
  bool happened(const std::string& text) const {
    return std::find(events_.begin(), events_.end(), text) != events_.end();
  }
  size_t index_of(const std::string& prefix) const {
    for (size_t i = 0; i < events_.size(); ++i)
      if (events_[i].rfind(prefix, 0) == 0) return i;
    ADD_FAILURE() << "no event starting with '" << prefix << "'";
    return events_.size();
  }

  Floor floor_;
  InOrderScheduler scheduler_;
  CourierExecutive exec_;
  double now_ = 9 * 3600.0;
  std::vector<std::string> events_;
  NavGoalOrder last_goal_;
  HandoverOrder last_handover_;
};

}  // namespace autonomy::courier::test_support
