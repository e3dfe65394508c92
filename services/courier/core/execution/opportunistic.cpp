// Jobs behind closed doors (the paper's opportunistic primaries): a job whose room, for its pickup
// or its delivery, is closed waits for the door; an object aboard stays aboard while the rules
// allow, and a robot with nothing else to do waits in sight of the door (in a fleet with parking
// spots: parked). The object goes back only
// when the job can no longer be done: its deadline given up by the policy
// (ExecutiveSettings::give_up_after_deadline_s), a person it needs gone for the day (the scheduler
// says so), or its place aboard needed by a job that could not be planned otherwise.
#include "services/courier/core/execution/courier_executive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace autonomy::courier {

namespace {

// The start of every reason given when the policy gives up waiting for a door: a return started
// for it is turned back into a delivery when the door is seen open before the object is back.
std::string gave_up_waiting_for(const std::string& door) { return "gave up waiting for " + door + ": "; }

}  // namespace

bool CourierExecutive::idle_policy(Robot& robot, double now_s) {
  bool busy = false;
  std::optional<std::string> door_to_watch;
  std::optional<double> most_urgent;
  for (auto& [id, job] : jobs_) {
    if (job.state != JobState::opportunistic) continue;
    if (!job.aboard()) {
      // A pickup behind a closed door, last planned for this robot: worth watching too, after
      // what is aboard.
      const auto door = job.robot == robot.id && next_step(job) == NextStep::load ? closed_door_for(job.object_place)
                                                                                  : std::nullopt;
      if (door && !door_to_watch) door_to_watch = door;
      continue;
    }
    if (job.object_carrier != robot.id) continue;
    const auto door = closed_door_for(job.target_place());
    if (!door) {
      // Its room is believed open again (an opportunity once declined): deliver it after all.
      job.state = JobState::queued;
      job.reason.clear();
      event(ExecutionEvent::Kind::opportunity_taken,
            "job " + id + " taken up again: " + job.target_place() + " is open and nothing else waits");
      changed(job);
      reschedule_needed_ = true;
      busy = true;
      continue;
    }
    // Waits for its door with the object aboard; the robot watches the door of the most urgent.
    const double urgency = job.deadline_s.value_or(std::numeric_limits<double>::infinity());
    if (!most_urgent || urgency < *most_urgent) {
      most_urgent = urgency;
      door_to_watch = door;
    }
  }
  if (busy) return true;
  if (door_to_watch) {
    // In a fleet a robot standing beside a door for a long wait narrows the hallway for the
    // others (the 12-jobs-an-hour day: robots stuck behind one waiting for A-120 for minutes). It
    // parks instead: the other robots see the door as they pass, and a sighting goes stale after
    // closed_door_stale_s, which makes the opportunity check run all the same.
    if (robots_.size() > 1 && !floor_.parking.empty()) return false;
    watch_door(robot, *door_to_watch, now_s);
    return floor_.door_lookouts.count(*door_to_watch) != 0;
  }
  return false;
}

void CourierExecutive::watch_door(Robot& robot, const std::string& door, double now_s) {
  go_to_lookout(robot, door, robot.id + " waits in sight of " + door + " until it opens (" + clock_text(now_s) + ")",
                now_s);
}

void CourierExecutive::give_up_job(Job& job, const std::string& reason, double now_s) {
  if (job.finished() || handover_in_flight(job.id)) return;
  if (job.aboard())
    start_return(job, JobState::failed, reason, now_s);
  else
    finish(job, JobState::failed, reason, now_s);
  reschedule_needed_ = true;
}

void CourierExecutive::give_up_overdue(double now_s) {
  if (settings_.give_up_after_deadline_s < 0.0) return;
  for (auto& [id, job] : jobs_) {
    if (job.state != JobState::opportunistic || !job.deadline_s) continue;
    if (now_s < *job.deadline_s + settings_.give_up_after_deadline_s) continue;
    const NextStep step = next_step(job);
    const auto door = closed_door_for(step == NextStep::load ? job.object_place : job.target_place());
    if (!door) continue;  // believed open: the opportunity check or the idle policy takes it up
    const long minutes = std::lround((now_s - *job.deadline_s) / 60.0);
    give_up_job(job,
                gave_up_waiting_for(*door) + "deadline " + clock_text(*job.deadline_s) + " passed " +
                    std::to_string(minutes) + " min ago (" + closed_reason(*door) + ")",
                now_s);
  }
}

void CourierExecutive::reconsider_returns(const std::string& door_id, double now_s) {
  for (auto& [id, job] : jobs_) {
    if (job.finished() || job.return_to.empty() || !job.aboard() || handover_in_flight(id)) continue;
    if (job.end_state_after_return != JobState::failed) continue;  // a cancel stays a cancel
    if (job.return_reason.rfind(gave_up_waiting_for(door_id), 0) != 0) continue;
    if (floor_.door_to(job.destination) != door_id) continue;
    job.return_to.clear();
    job.return_reason.clear();
    make_opportunistic(job, door_id + " seen open at " + clock_text(now_s) + " while " + job.object.id + " was on its way back",
                       now_s);
    opportunity_pending_ = true;
  }
}

bool CourierExecutive::make_room(const Plan& plan, double now_s) {
  // Objects of opportunistic jobs that are in the request (aboard, behind a door believed closed).
  std::map<std::string, std::vector<std::string>> waiting_aboard;  // robot -> jobs
  for (const auto& [id, job] : jobs_)
    if (job.state == JobState::opportunistic && job.aboard() && closed_door_for(job.target_place()))
      waiting_aboard[job.object_carrier].push_back(id);
  if (waiting_aboard.empty()) return false;
  // Jobs the plan could not fit that no door and no absent person explain.
  std::set<std::string> left_out;
  for (const auto& [id, job] : jobs_) {
    if (job.finished() || job.state == JobState::opportunistic || job.state == JobState::stranded || job.aboard())
      continue;
    if (next_step(job) != NextStep::load) continue;
    const bool planned = std::any_of(plan.routes.begin(), plan.routes.end(), [&](const auto& route) {
      return std::any_of(route.second.begin(), route.second.end(), [&](const PlanStop& s) { return s.job_id == id; });
    });
    if (planned && !plan.failed) continue;
    if (plan.gone_for_good.count(id) || closed_door_for(job.object_place) || closed_door_for(job.destination)) continue;
    left_out.insert(id);
  }
  if (left_out.empty()) return false;
  PlanRequest roomy = request_for(now_s, {});
  roomy.jobs.erase(std::remove_if(roomy.jobs.begin(), roomy.jobs.end(),
                                  [&](const PlanJob& j) {
                                    const Job& job = jobs_.at(j.id);
                                    return job.state == JobState::opportunistic;
                                  }),
                   roomy.jobs.end());
  const Plan with_room = scheduler_.plan(roomy);
  if (with_room.failed) return false;
  bool returned = false;
  for (const auto& [robot, stops] : with_room.routes) {
    const auto waiting = waiting_aboard.find(robot);
    if (waiting == waiting_aboard.end()) continue;
    std::string needed_by;
    for (const PlanStop& s : stops)
      if (s.load && left_out.count(s.job_id)) {
        needed_by = s.job_id;
        break;
      }
    if (needed_by.empty()) continue;
    for (const std::string& id : waiting->second) {
      Job& job = jobs_.at(id);
      give_up_job(job, "its place aboard " + robot + " is needed for job " + needed_by + " (" + job.reason + ")", now_s);
      returned = true;
    }
  }
  return returned;
}

}  // namespace autonomy::courier
