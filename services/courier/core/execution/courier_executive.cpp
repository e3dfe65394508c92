#include "services/courier/core/execution/courier_executive.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

namespace autonomy::courier {

std::string clock_text(double seconds_of_day) {
  const long total = std::lround(std::max(0.0, seconds_of_day));
  char text[16];
  std::snprintf(text, sizeof text, "%02ld:%02ld:%02ld", (total / 3600) % 100, (total / 60) % 60, total % 60);
  return text;
}

CourierExecutive::CourierExecutive(Floor floor, ScheduleSource& scheduler, ExecutiveSettings settings)
    : floor_(std::move(floor)), scheduler_(scheduler), settings_(std::move(settings)) {
  if (floor_.doors.empty())
    for (const auto& [room, door] : floor_.door_of_room) floor_.doors.insert(door);
}

const HandoverOrder* CourierExecutive::handover_in_flight(const std::string& job_id) const {
  for (const auto& [id, r] : robots_)
    if (r.handover && r.handover->order.job_id == job_id) return &r.handover->order;
  return nullptr;
}

bool CourierExecutive::exhausted(std::map<std::string, int>& counts, const std::string& key) {
  return ++counts[key] >= settings_.max_attempts;
}

std::string CourierExecutive::person_at(const std::string& place) const {
  const FloorPlace* p = floor_.place(place);
  return p ? p->person : std::string();
}

const Job* CourierExecutive::job(const std::string& id) const {
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? nullptr : &it->second;
}

std::vector<PlanStop> CourierExecutive::route(const std::string& robot) const {
  const auto it = robots_.find(robot);
  return it == robots_.end() ? std::vector<PlanStop>{} : it->second.route;
}

void CourierExecutive::event(ExecutionEvent::Kind kind, std::string text) {
  orders_.events.push_back({kind, std::move(text)});
}

const char* to_string(ExecutionEvent::Kind k) {
  switch (k) {
    case ExecutionEvent::Kind::accepted: return "accepted";
    case ExecutionEvent::Kind::revised: return "revised";
    case ExecutionEvent::Kind::heading: return "heading";
    case ExecutionEvent::Kind::loaded: return "loaded";
    case ExecutionEvent::Kind::unloaded: return "unloaded";
    case ExecutionEvent::Kind::door_closed: return "door_closed";
    case ExecutionEvent::Kind::door_opened: return "door_opened";
    case ExecutionEvent::Kind::goal_blocked: return "goal_blocked";
    case ExecutionEvent::Kind::goal_ended: return "goal_ended";
    case ExecutionEvent::Kind::handover_failed: return "handover_failed";
    case ExecutionEvent::Kind::handover_refused: return "handover_refused";
    case ExecutionEvent::Kind::failed_over: return "failed_over";
    case ExecutionEvent::Kind::opportunity_taken: return "opportunity_taken";
    case ExecutionEvent::Kind::opportunity_declined: return "opportunity_declined";
    case ExecutionEvent::Kind::returning: return "returning";
    case ExecutionEvent::Kind::finished: return "finished";
    case ExecutionEvent::Kind::schedule_failed: return "schedule_failed";
    case ExecutionEvent::Kind::robot_joined: return "robot_joined";
    case ExecutionEvent::Kind::robot_left: return "robot_left";
    case ExecutionEvent::Kind::reallocated: return "reallocated";
    case ExecutionEvent::Kind::stranded: return "stranded";
    case ExecutionEvent::Kind::resumed: return "resumed";
    case ExecutionEvent::Kind::goal_cancelled: return "goal_cancelled";
    case ExecutionEvent::Kind::waiting: return "waiting";
  }
  return "?";
}

void CourierExecutive::changed(const Job& job) {
  if (std::find(orders_.changed_jobs.begin(), orders_.changed_jobs.end(), job.id) == orders_.changed_jobs.end())
    orders_.changed_jobs.push_back(job.id);
}

void CourierExecutive::add_job(Job job, double now_s) {
  job.state = JobState::queued;
  job.phase = JobPhase::none;
  if (job.object_place.empty() && job.object_carrier.empty()) job.object_place = job.pickup;
  job.accepted_at_s = now_s;
  const std::string id = job.id;
  jobs_[id] = std::move(job);
  event(ExecutionEvent::Kind::accepted, "job " + id + " accepted");
  changed(jobs_[id]);
  reschedule_needed_ = true;
}

void CourierExecutive::restore_job(Job job) {
  if (job.object_place.empty() && job.object_carrier.empty()) job.object_place = job.pickup;
  const std::string id = job.id;
  jobs_[id] = std::move(job);
  reschedule_needed_ = true;
}

std::optional<std::string> CourierExecutive::cancel(const std::string& job_id, const std::string& reason,
                                                    double now_s) {
  const auto it = jobs_.find(job_id);
  if (it == jobs_.end()) return "no job '" + job_id + "'";
  Job& job = it->second;
  if (job.finished()) return "job " + job_id + " is already " + to_string(job.state);
  if (!job.return_to.empty()) return "job " + job_id + " is already returning its object to " + job.return_to;
  const std::string why = reason.empty() ? std::string("cancelled") : "cancelled: " + reason;
  if (job.state == JobState::stranded) {
    // Its robot is gone: nothing can be returned now, and the job says where the object is.
    finish(job, JobState::cancelled, why + "; " + job.reason, now_s);
    reschedule_needed_ = true;
    return std::nullopt;
  }
  const HandoverOrder* in_flight = handover_in_flight(job_id);
  if (in_flight && !in_flight->load && in_flight->place == job.destination)
    return "job " + job_id + " is being handed over at " + job.destination + " now: too late to cancel";
  // A load under way completes or fails first; the object belief then says what to do, and
  // settle() ends the job if the object never left its pickup.
  if (job.aboard() || (in_flight && in_flight->load)) {
    start_return(job, JobState::cancelled, why, now_s);
  } else {
    finish(job, JobState::cancelled, why, now_s);
  }
  reschedule_needed_ = true;
  return std::nullopt;
}

std::optional<std::string> CourierExecutive::revise(const std::string& job_id,
                                                    const std::optional<std::string>& destination,
                                                    const std::optional<std::optional<double>>& deadline_s,
                                                    double now_s) {
  const auto it = jobs_.find(job_id);
  if (it == jobs_.end()) return "no job '" + job_id + "'";
  Job& job = it->second;
  if (job.finished()) return "job " + job_id + " is already " + to_string(job.state);
  if (!job.return_to.empty()) return "job " + job_id + " is returning its object to " + job.return_to;
  if (destination) {
    if (!floor_.place(*destination)) return "no place '" + *destination + "'";
    if (!job.aboard() && *destination == job.object_place)
      return "job " + job_id + "'s object already lies at " + *destination;
    job.destination = *destination;
    event(ExecutionEvent::Kind::revised, "job " + job_id + " now goes to " + *destination);
  }
  if (deadline_s) {
    job.deadline_s = *deadline_s;
    event(ExecutionEvent::Kind::revised, "job " + job_id + " deadline " + (*deadline_s ? clock_text(**deadline_s) : std::string("none")));
  }
  // A job that waited for a door may be possible at its new destination.
  if (job.state == JobState::opportunistic && destination) {
    job.state = JobState::queued;
    job.reason.clear();
  }
  (void)now_s;
  changed(job);
  reschedule_needed_ = true;
  return std::nullopt;
}

void CourierExecutive::on_goal(const std::string& robot, const std::string& goal_id, GoalOutcome outcome,
                               const std::string& reason, double now_s) {
  const auto it = robots_.find(robot);
  if (it == robots_.end()) return;
  Robot& r = it->second;
  if (goal_id != r.goal_id || r.goal_id.empty()) return;  // not ours, or an older one
  r.goal_answered = true;
  switch (outcome) {
    case GoalOutcome::accepted:
    case GoalOutcome::active: return;
    case GoalOutcome::reached:
      if (floor_.place(r.goal_from) && floor_.place(r.goal_place))
        experience_.travel(r.goal_from, r.goal_place, now_s - r.goal_sent_s);
      r.blocked.erase(r.goal_place);
      r.refused.erase(r.goal_place);
      r.at_place = r.goal_place;
      r.goal_id.clear();
      r.goal_place.clear();
      return;
    case GoalOutcome::blocked: {
      const std::string place = r.goal_place;
      if (place == kHomePlace || is_lookout(place)) {
        // The way home or to a door's lookout is blocked (another robot in it): stay a while,
        // then try again.
        r.goal_id.clear();
        r.goal_place.clear();
        r.hold(now_s + settings_.home_retry_s);
        return;
      }
      r.goal_id.clear();
      r.goal_place.clear();
      if (!settings_.monitor_doors) {
        // Waiting at the door: the same goal again a moment later, whatever blocked it.
        event(ExecutionEvent::Kind::goal_blocked, "goal to " + place + " blocked for " + robot + ": " + reason +
                                                      "; waiting to try again");
        r.hold(now_s + settings_.door_wait_retry_s);
        return;
      }
      event(ExecutionEvent::Kind::goal_blocked, "goal to " + place + " blocked for " + robot + ": " + reason);
      // The behavior names the doors it saw closed ("... door A-120 closed", "... doors A-111,
      // A-120 closed"): its robot's eyes.
      for (const char* marker : {"door ", "doors "}) {
        const auto at = reason.find(marker);
        const auto end = reason.find(" closed", at);
        if (at == std::string::npos || end == std::string::npos) continue;
        std::string list = reason.substr(at + std::string(marker).size(), end - at - std::string(marker).size());
        for (size_t from = 0; from <= list.size();) {
          size_t comma = list.find(',', from);
          if (comma == std::string::npos) comma = list.size();
          std::string door = list.substr(from, comma - from);
          while (!door.empty() && door.front() == ' ') door.erase(door.begin());
          if (!door.empty()) on_door(robot, door, 0.0, now_s);
          from = comma + 1;
        }
      }
      // Other robots in the way (only a fleet has them): they move on, so it tries again soon.
      const bool traffic = robots_.size() > 1 && (reason.find("no progress") != std::string::npos ||
                                                   reason.find("robot ") != std::string::npos);
      const int limit = traffic ? settings_.max_traffic_blocked_goals : settings_.max_blocked_goals;
      if (!closed_door_for(place) && ++r.blocked[place] >= limit) {
        r.blocked.erase(place);
        give_up_on(place, "cannot reach " + place + ": " + reason, now_s);
      } else if (traffic && !closed_door_for(place)) {
        r.hold(now_s + settings_.traffic_retry_s * r.blocked[place]);
      }
      reschedule_needed_ = true;
      return;
    }
    case GoalOutcome::preempted:
    case GoalOutcome::rejected:
    case GoalOutcome::cancelled: {
      // Somebody else took the robot, or the goal was refused: ask again a moment later, and give
      // the place up after a few refusals in a row.
      const std::string place = r.goal_place;
      event(ExecutionEvent::Kind::goal_ended,
            "goal " + goal_id + " " + (outcome == GoalOutcome::rejected ? "rejected" : "ended") + ": " + reason);
      r.goal_id.clear();
      r.goal_place.clear();
      r.hold(now_s + settings_.goal_retry_s);
      if (exhausted(r.refused, place)) {
        r.refused.erase(place);
        give_up_on(place, "goal to " + place + " refused " + std::to_string(settings_.max_attempts) + " times: " + reason,
                   now_s);
        reschedule_needed_ = true;
      }
      return;
    }
  }
}

void CourierExecutive::on_handover(const std::string& request_id, HandoverOutcome outcome, const std::string& reason,
                                   const std::string& detail, double now_s) {
  for (auto& [rid, r] : robots_) {
    if (!r.handover || r.handover->order.request_id != request_id) continue;
    const HandoverOrder order = r.handover->order;
    const auto jt = jobs_.find(order.job_id);
    const std::string person = person_at(order.place);
    if (outcome == HandoverOutcome::accepted) {
      // A request asked again is accepted again: the handover's time counts from the first.
      if (r.handover->accepted) return;
      r.handover->accepted = true;
      r.handover->accepted_at_s = now_s;
      if (!person.empty()) experience_.presence(person, now_s, true, settings_.day);
      return;
    }
    if (outcome == HandoverOutcome::completed && !person.empty() && r.handover->accepted)
      experience_.handover(person, now_s - r.handover->accepted_at_s);
    if (outcome == HandoverOutcome::rejected && reason == "nobody_present" && !person.empty())
      experience_.presence(person, now_s, false, settings_.day);
    r.handover.reset();
    if (jt == jobs_.end()) return;
    Job& job = jt->second;
    const std::string what = std::string(order.load ? "load" : "unload") + " of " + order.object_id + " at " +
                             order.place;
    const std::string step_key = job.id + (order.load ? "/load" : "/unload");
    if (outcome == HandoverOutcome::completed) {
      handover_attempts_.erase(step_key);
      reschedule_needed_ = true;  // the object moved: the plan's next steps follow from where it is
      if (order.load) {
        job.object_place.clear();
        job.object_carrier = r.id;
        event(ExecutionEvent::Kind::loaded,
              job.object.id + " loaded at " + order.place + " by " + r.id + " at " + clock_text(now_s));
      } else {
        job.object_carrier.clear();
        job.object_place = order.place;
        event(ExecutionEvent::Kind::unloaded,
              job.object.id + " unloaded at " + order.place + " by " + r.id + " at " + clock_text(now_s));
      }
      if (job.finished()) {
        // The job ended while its load was under way (failed over, blocked elsewhere): the object
        // is aboard now and must not ride along unseen. It goes back, and that is reported.
        if (job.aboard()) start_return(job, job.state, job.reason + "; loaded after the job ended", now_s);
        changed(job);
        return;
      }
      if (job.return_to.empty() && job.state != JobState::opportunistic) job.reason.clear();
      if (!job.return_to.empty() && job.object_place == job.return_to) {
        finish(job, job.end_state_after_return, job.reason_after_return(), now_s);
      } else if (job.return_to.empty() && job.object_place == job.destination) {
        finish(job, JobState::completed, "", now_s);
      } else {
        if (job.state != JobState::opportunistic)
          job.phase = job.aboard() ? (job.return_to.empty() ? JobPhase::to_destination : JobPhase::returning)
                                   : JobPhase::to_pickup;
        changed(job);
      }
      return;
    }
    const std::string said = reason + (detail.empty() ? "" : " (" + detail + ")");
    if (outcome == HandoverOutcome::failed) {
      event(ExecutionEvent::Kind::handover_failed, what + " failed: " + said);
      if (exhausted(handover_attempts_, step_key)) {
        handover_attempts_.erase(step_key);
        give_up_on(order.place, what + " failed " + std::to_string(settings_.max_attempts) + " times: " + said, now_s);
      } else if (!job.finished()) {
        job.phase = JobPhase::none;
        changed(job);
      }
      return;  // tried again at the next dispatch
    }
    // Rejected.
    event(ExecutionEvent::Kind::handover_refused, what + " refused: " + said);
    if (reason == "robot_not_at_place" || reason == "robot_moved_away") {
      r.at_place.clear();  // drive there again
      return;
    }
    const bool waits = reason == "nobody_present" || reason == "helper_busy" || reason == "robot_busy" ||
                       reason == "object_in_handover";
    // "nobody at a118-desk at 12:10 (somebody is back at 14:00)": wait for that, it is no failure.
    std::optional<double> back_at;
    if (const auto at = detail.find("back at "); at != std::string::npos && detail.size() >= at + 13) {
      const std::string hhmm = detail.substr(at + 8, 5);
      if (hhmm[2] == ':' && std::isdigit(static_cast<unsigned char>(hhmm[0])) &&
          std::isdigit(static_cast<unsigned char>(hhmm[1])) && std::isdigit(static_cast<unsigned char>(hhmm[3])) &&
          std::isdigit(static_cast<unsigned char>(hhmm[4])))
        back_at = (hhmm[0] - '0') * 36000.0 + (hhmm[1] - '0') * 3600.0 + (hhmm[3] - '0') * 600.0 + (hhmm[4] - '0') * 60.0;
    }
    if (reason == "nobody_present" && back_at && *back_at > now_s) {
      r.hold(*back_at, order.place);
      if (!job.finished()) job.reason = "waiting: " + detail;
      changed(job);
      return;
    }
    if (waits && !exhausted(handover_attempts_, step_key)) {
      r.hold(now_s + settings_.retry_after_s);
      if (!job.finished()) job.reason = "waiting: " + (detail.empty() ? reason : detail);
      changed(job);
      reschedule_needed_ = true;
      return;
    }
    handover_attempts_.erase(step_key);
    if (job.finished()) return;
    if (order.load) {
      // The object is not where we believed (object_not_at_place, unknown_object, robot_full, ...),
      // or nobody came in time.
      finish(job, JobState::failed, "cannot load " + order.object_id + " at " + order.place + ": " + said, now_s);
    } else if (job.return_to.empty()) {
      start_return(job, JobState::failed, "cannot unload at " + order.place + ": " + said, now_s);
    } else {
      // Not even the way back works: the object stays aboard, and the job says so.
      finish(job, job.end_state_after_return,
             job.return_reason + "; " + job.object.id + " stays aboard " + r.id + ": cannot unload at " + order.place +
                 ": " + said,
             now_s);
    }
    reschedule_needed_ = true;
    return;
  }
}

void CourierExecutive::give_up_on(const std::string& place, const std::string& reason, double now_s) {
  for (auto& [id, job] : jobs_) {
    const NextStep step = next_step(job);
    const std::string& p = step == NextStep::load ? job.object_place : job.target_place();
    if (step == NextStep::none || p != place || handover_in_flight(id) || job.state == JobState::stranded) continue;
    if (job.aboard() && job.return_to.empty())
      start_return(job, JobState::failed, reason, now_s);
    else if (job.aboard())
      finish(job, job.end_state_after_return,
             job.return_reason + "; " + job.object.id + " stays aboard " + job.object_carrier + ": " + reason, now_s);
    else
      finish(job, JobState::failed, reason, now_s);
  }
  reschedule_needed_ = true;
}

void CourierExecutive::settle(double now_s) {
  for (auto& [id, job] : jobs_) {
    if (job.finished() || job.state == JobState::stranded || next_step(job) != NextStep::none || handover_in_flight(id))
      continue;
    if (!job.return_to.empty())
      finish(job, job.end_state_after_return, job.reason_after_return(), now_s);
    else if (job.object_place == job.destination)
      finish(job, JobState::completed, "", now_s);
  }
}

void CourierExecutive::make_opportunistic(Job& job, const std::string& reason, double now_s) {
  job.state = JobState::opportunistic;
  job.phase = JobPhase::none;
  job.reason = reason;
  job.estimated_completion_s.reset();
  event(ExecutionEvent::Kind::failed_over, "job " + job.id + " failed over to opportunistic: " + reason + " (" + clock_text(now_s) + ")");
  changed(job);
}

void CourierExecutive::start_return(Job& job, JobState end_state, const std::string& reason, double now_s) {
  job.return_to = job.pickup;
  job.end_state_after_return = end_state;
  job.return_reason = reason;
  job.state = JobState::underway;
  job.phase = JobPhase::returning;
  job.reason = reason + "; returning " + job.object.id + " to " + job.return_to;
  event(ExecutionEvent::Kind::returning, "job " + job.id + ": " + job.reason + " (" + clock_text(now_s) + ")");
  changed(job);
}

void CourierExecutive::finish(Job& job, JobState state, const std::string& reason, double now_s) {
  job.state = state;
  job.phase = JobPhase::none;
  job.reason = reason;
  job.estimated_completion_s = now_s;
  changed(job);
  ReportNote report{job.id, job.command_id, state == JobState::completed, ""};
  const std::string object = (job.object.colour.empty() ? "" : job.object.colour + " ") + job.object.kind;
  if (state == JobState::completed)
    report.text = "delivered the " + object + " (" + job.object.id + ") to " + job.destination + " at " +
                  clock_text(now_s);
  else
    report.text = std::string(to_string(state)) + ": " + reason + " (" + clock_text(now_s) + ")";
  event(ExecutionEvent::Kind::finished, "job " + job.id + " " + report.text);
  orders_.reports.push_back(std::move(report));
}

PlanRequest CourierExecutive::request_for(double now_s, const std::vector<std::string>& extra_jobs) const {
  PlanRequest req;
  req.now_s = now_s;
  // A robot whose pose has not arrived yet cannot be planned for (it would seem to stand at 0, 0).
  for (const auto& [id, r] : robots_)
    if (r.pose_known) req.robots.push_back({id, r.x, r.y, r.capacity, free_to_go_s(r, now_s)});
  for (const auto& [id, door] : doors_.doors()) {
    if (!door.open) req.closed_doors.insert(id);
    // Only a sighting overrides the door's learned habit; an expired closed sighting does not.
    else if (!door.open_assumed && now_s - door.seen_at_s <= 600.0) req.doors_seen_open.insert(id);
  }
  for (const auto& [id, job] : jobs_) {
    const bool extra = std::find(extra_jobs.begin(), extra_jobs.end(), id) != extra_jobs.end();
    if (job.finished() || job.state == JobState::stranded) continue;
    // An opportunistic job is planned only when asked for (the opportunity check), except that its
    // object aboard takes its place aboard (capacity, look-alikes) whatever its door is believed
    // to be: the scheduler leaves its delivery out. (Counted only while its door was believed
    // closed, a robot whose sighting had gone stale was planned pickups it had no room for:
    // 'robot_full' refusals failed their jobs in the 12-jobs-an-hour day.)
    const bool keep_aboard = job.state == JobState::opportunistic && !extra;
    if (keep_aboard && !job.aboard()) continue;
    if (next_step(job) == NextStep::none) continue;
    // A job aboard a robot that cannot be planned for yet waits for that robot's pose.
    if (job.aboard()) {
      const auto carrier = robots_.find(job.object_carrier);
      if (carrier == robots_.end() || !carrier->second.pose_known) continue;
    }
    req.jobs.push_back({id, job.object.lookalike_class(), job.object_place, job.target_place(), job.deadline_s,
                        job.object_carrier, job.robot, keep_aboard});
  }
  return req;
}

void CourierExecutive::adopt(const Plan& plan, double now_s) {
  for (auto& [id, r] : robots_) {
    const auto it = plan.routes.find(id);
    r.route = it == plan.routes.end() ? std::vector<PlanStop>{} : it->second;
    if (!r.held_for.empty() && (r.route.empty() || r.route.front().place != r.held_for)) {
      r.hold(0.0);  // the person is still out, but there is other work first
    }
    ScheduleNote note{id, r.route, {}, plan.engine, plan.proved_optimal, plan.late_jobs, plan.total_lateness_s};
    std::set<std::string> rooms;
    for (const PlanStop& s : r.route) {
      if (s.room.empty() || !floor_.door_of_room.count(s.room) || !rooms.insert(s.room).second) continue;
      note.assumptions.push_back(s.room + " open at " + clock_text(s.arrival_s));
    }
    orders_.schedules.push_back(std::move(note));
    for (const PlanStop& s : r.route) {
      auto jt = jobs_.find(s.job_id);
      if (jt == jobs_.end()) continue;
      Job& job = jt->second;
      const auto completion = plan.completion_s.find(job.id);
      const std::optional<double> eta =
          completion == plan.completion_s.end() ? std::nullopt : std::optional<double>(completion->second);
      // Why this robot: the scheduler's words with several robots; a job taken over from a robot
      // that left says so until its next step starts.
      const auto why = plan.allocation.find(job.id);
      std::string allocation = why != plan.allocation.end() ? why->second : std::string();
      if (job.reason.rfind("reallocated: ", 0) == 0) {
        if (allocation.empty()) allocation = "assigned to " + id;
        allocation += " (" + job.reason + ")";
      }
      if (job.reason.rfind(kNotScheduledPrefix, 0) == 0) {
        job.reason.clear();
        changed(job);
      }
      if (job.robot != id || job.estimated_completion_s != eta || job.allocation != allocation) {
        job.robot = id;
        job.estimated_completion_s = eta;
        job.allocation = allocation;
        changed(job);
      }
    }
  }
  for (const auto& [job_id, why] : plan.unschedulable) {
    auto jt = jobs_.find(job_id);
    if (jt == jobs_.end() || jt->second.finished()) continue;
    Job& job = jt->second;
    if (!job.return_to.empty()) {
      // Nowhere to return to through an open door: a loading station that is reachable is next
      // time's choice; until then the object stays aboard and the job says why.
      job.reason = job.return_reason + "; cannot return " + job.object.id + " yet: " + why;
      changed(job);
      continue;
    }
    if (plan.gone_for_good.count(job_id)) {
      give_up_job(job, "cannot be done today: " + why, now_s);
      continue;
    }
    if (job.state == JobState::opportunistic) continue;  // waits already
    const NextStep step = next_step(job);
    const std::string& place = step == NextStep::load ? job.object_place : job.target_place();
    const auto door = floor_.door_to(place);
    if (door && !doors_.believed_open(*door)) {
      make_opportunistic(job, closed_reason(*door), now_s);
      continue;
    }
    // No door to blame (it clashes with jobs accepted earlier, or its place cannot be reached):
    // it stays queued and is planned again at every reschedule, when the jobs before it are done.
    const std::string waiting = kNotScheduledPrefix + why;
    if (job.reason != waiting) {
      job.reason = waiting;
      job.estimated_completion_s.reset();
      changed(job);
    }
  }
}

void CourierExecutive::reschedule(double now_s) {
  reschedule_needed_ = false;
  schedule_retry_at_.reset();
  Plan plan = scheduler_.plan(request_for(now_s, {}));
  // Objects waiting aboard for a door that a job needs the place of go back, and the rest is
  // planned again without them.
  if (make_room(plan, now_s)) plan = scheduler_.plan(request_for(now_s, {}));
  if (plan.failed) {
    // Keep driving the routes there are; a failure of the whole plan says nothing about the jobs.
    event(ExecutionEvent::Kind::schedule_failed, "no schedule (" + plan.failure + "): the current routes go on, " +
                                                 "trying again at " + clock_text(now_s + settings_.schedule_retry_s));
    schedule_retry_at_ = now_s + settings_.schedule_retry_s;
    return;
  }
  adopt(plan, now_s);
}

bool CourierExecutive::at(const Robot& robot, const std::string& place) const {
  if (robot.at_place == place) return true;
  const FloorPlace* p = floor_.place(place);
  return p && robot.pose_known && std::hypot(robot.x - p->x, robot.y - p->y) <= p->radius * 0.9;
}

bool CourierExecutive::still_needed(const Robot& robot, const PlanStop& stop) const {
  const auto it = jobs_.find(stop.job_id);
  if (it == jobs_.end()) return false;
  const Job& job = it->second;
  if (job.finished() || job.state == JobState::opportunistic || job.state == JobState::stranded) return false;
  const NextStep step = next_step(job);
  if (stop.load) return step == NextStep::load && job.object_place == stop.place;
  return step == NextStep::unload && job.object_carrier == robot.id && job.target_place() == stop.place;
}

void CourierExecutive::send_goal(Robot& robot, const std::string& place, double now_s) {
  const FloorPlace* p = floor_.place(place);
  if (!p) return;
  robot.goal_id = robot.id + "/" + place + "/" + settings_.id_tag + "." + std::to_string(++robot.goal_seq);
  robot.goal_place = place;
  robot.parking.clear();  // at work: the spot is free for whoever is idle first
  robot.goal_from = robot.at_place;
  robot.goal_sent_s = now_s;
  robot.goal_answered = false;
  robot.at_place.clear();
  const double tolerance = std::min(settings_.goal_tolerance_m, 0.5 * p->radius);
  orders_.goals.push_back({robot.id, robot.goal_id, p->x, p->y, tolerance});
  event(ExecutionEvent::Kind::heading, robot.id + " heads for " + place + " (" + clock_text(now_s) + ")");
}

void CourierExecutive::send_handover(Robot& robot, const PlanStop& stop, double now_s) {
  Job& job = jobs_.at(stop.job_id);
  HandoverOrder order{robot.id, robot.id + "/" + job.id + "/" + (stop.load ? "load" : "unload") + "/" +
                                    settings_.id_tag + "." + std::to_string(++robot.request_seq),
                      stop.load, stop.place, job.object.id, job.id};
  robot.handover = PendingHandover{order, now_s, false};
  orders_.handovers.push_back(order);
  job.state = JobState::underway;
  job.phase = stop.load ? JobPhase::loading : (job.return_to.empty() ? JobPhase::unloading : JobPhase::returning);
  job.robot = robot.id;
  changed(job);
}

void CourierExecutive::dispatch(Robot& robot, double now_s) {
  if (robot.handover) {
    // Unanswered: the same request again (the simulator answers a repeat, never hands over twice).
    // Accepted and never completed (an answer lost): ask again too, the answer is repeated.
    const double wait = robot.handover->accepted ? settings_.accepted_timeout_s : settings_.request_timeout_s;
    if (now_s - robot.handover->sent_at_s >= wait) {
      robot.handover->sent_at_s = now_s;
      orders_.handovers.push_back(robot.handover->order);
    }
    return;
  }
  if (!robot.goal_id.empty() && !robot.goal_answered && now_s - robot.goal_sent_s >= settings_.goal_answer_s) {
    // The robot's behavior said nothing about its goal: the goal was lost (written before the
    // behavior's reader had matched ours again, e.g. after this process was stopped for a while:
    // a lockstep world runs 10 s in a few milliseconds), so it is sent again. Not a refusal: that
    // gave places up while DDS found its peers again. A behavior that is gone leaves the fleet
    // by its heartbeat, and its jobs are reallocated or stranded there.
    event(ExecutionEvent::Kind::goal_ended, "goal " + robot.goal_id + " unanswered: no answer from the behavior of " +
                                                robot.id + " within " +
                                                std::to_string(static_cast<int>(settings_.goal_answer_s)) +
                                                " s; sent again");
    robot.goal_id.clear();
    robot.goal_place.clear();
    robot.hold(now_s + settings_.goal_retry_s);
  }
  if (now_s < robot.hold_until_s) return;
  robot.held_for.clear();  // the wait is over
  // A robot waits for a room only while its next stop is there (a hold keeps its place in line):
  // wait_for_room says so again.
  const std::string waited = std::exchange(robot.waiting_for_room, {});
  const PlanStop* next = nullptr;
  for (const PlanStop& s : robot.route)
    if (still_needed(robot, s)) {
      next = &s;
      break;
    }
  if (!next) {
    // Waiting in sight of a door, or a return just started (planned and dispatched in this tick's
    // second round): not parked.
    if (!idle_policy(robot, now_s) && !reschedule_needed_) park(robot, now_s);
    return;
  }
  Job& job = jobs_.at(next->job_id);
  if (at(robot, next->place)) {
    send_handover(robot, *next, now_s);
    return;
  }
  if (robot.goal_place != next->place) {
    if (wait_for_room(robot, *next, waited, now_s)) return;
    send_goal(robot, next->place, now_s);
    const JobPhase phase = !job.return_to.empty() ? JobPhase::returning
                           : next->load            ? JobPhase::to_pickup
                                                   : JobPhase::to_destination;
    if (job.state != JobState::underway || job.phase != phase || job.robot != robot.id) {
      if (job.reason.rfind("reallocated: ", 0) == 0) job.reason.clear();  // taken up by this robot
      job.state = JobState::underway;
      job.phase = phase;
      job.robot = robot.id;
      changed(job);
    }
  }
}

Orders CourierExecutive::step(double now_s) {
  // Nothing can be planned before any robot is known to be somewhere; events wait for that.
  const bool located = std::any_of(robots_.begin(), robots_.end(), [](const auto& r) { return r.second.pose_known; });
  if (!located) {
    Orders out = std::move(orders_);
    orders_ = Orders{};
    return out;
  }
  settle(now_s);
  for (const std::string& door : doors_.expire_closed(now_s - settings_.closed_door_stale_s)) {
    event(ExecutionEvent::Kind::door_opened, door + " assumed open again: not seen for " +
                                                 std::to_string(static_cast<int>(settings_.closed_door_stale_s)) +
                                                 " s (" + clock_text(now_s) + ")");
    opportunity_pending_ = true;
    reschedule_needed_ = true;
    reconsider_returns(door, now_s);
  }
  if (schedule_retry_at_ && now_s >= *schedule_retry_at_) reschedule_needed_ = true;
  give_up_overdue(now_s);
  if (opportunity_pending_) opportunity_check(now_s);
  if (reschedule_needed_) reschedule(now_s);
  for (auto& [id, r] : robots_)
    if (r.pose_known) dispatch(r, now_s);
  // The idle policy may have turned jobs into returns: plan and start them in this same tick.
  if (reschedule_needed_) {
    reschedule(now_s);
    for (auto& [id, r] : robots_)
      if (r.pose_known) dispatch(r, now_s);
  }
  Orders out = std::move(orders_);
  orders_ = Orders{};
  return out;
}

}  // namespace autonomy::courier
