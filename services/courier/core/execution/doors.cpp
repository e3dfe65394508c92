// The executive's door policy: sightings folded into the door belief, a door seen closed that an
// open step needs fails its job over to the opportunistic primaries, a door seen open triggers the
// opportunity check (taken up only if no other job gets later).
#include "services/courier/core/execution/courier_executive.hpp"

#include <algorithm>

namespace autonomy::courier {

std::optional<std::string> CourierExecutive::closed_door_for(const std::string& place) const {
  const auto door = floor_.door_to(place);
  if (door && !doors_.believed_open(*door)) return door;
  return std::nullopt;
}

std::string CourierExecutive::closed_reason(const std::string& door) const {
  const auto view = doors_.view(door);
  return door + " closed at " + clock_text(view ? view->seen_at_s : 0.0);
}

void CourierExecutive::on_door(const std::string& robot, const std::string& door_id, double angle_rad,
                               double now_s) {
  if (!robots_.count(robot)) return;             // only our own robots' eyes
  if (!settings_.monitor_doors) return;          // not watching doors: waits at them instead
  if (!floor_.doors.count(door_id)) return;       // not a door of our floor
  const DoorChange change = doors_.observe(door_id, angle_rad, now_s, robot);
  if (doors_.view(door_id)) experience_.door(door_id, now_s, doors_.believed_open(door_id), settings_.day);
  if (change == DoorChange::none) return;
  if (change == DoorChange::closed) {
    event(ExecutionEvent::Kind::door_closed, door_id + " seen closed by " + robot + " at " + clock_text(now_s));
    // A broken assumption: each open job whose next step lies behind this door fails over to the
    // opportunistic primaries, and the rest is rescheduled in this same tick.
    for (auto& [id, job] : jobs_) {
      if (job.finished() || job.state == JobState::opportunistic || job.state == JobState::stranded) continue;
      const NextStep step = next_step(job);
      const std::string& place = step == NextStep::load ? job.object_place : job.target_place();
      if (step != NextStep::none && floor_.door_to(place) == door_id) {
        if (!job.return_to.empty()) continue;  // a return finds another place in reschedule()
        make_opportunistic(job, closed_reason(door_id), now_s);
      }
    }
    reschedule_needed_ = true;
  } else {
    event(ExecutionEvent::Kind::door_opened, door_id + " seen open by " + robot + " at " + clock_text(now_s));
    for (const auto& [id, job] : jobs_)
      if (job.state == JobState::opportunistic) opportunity_pending_ = true;
    reconsider_returns(door_id, now_s);
    reschedule_needed_ = true;
  }
}

void CourierExecutive::opportunity_check(double now_s) {
  opportunity_pending_ = false;
  for (auto& [id, job] : jobs_) {
    if (job.state != JobState::opportunistic) continue;
    const NextStep step = next_step(job);
    const std::string& place = step == NextStep::load ? job.object_place : job.target_place();
    if (closed_door_for(place)) continue;  // still no way in
    const Plan without = scheduler_.plan(request_for(now_s, {}));
    PlanRequest with_request = request_for(now_s, {id});
    with_request.first = {id};
    const Plan with = scheduler_.plan(with_request);
    if (with.gone_for_good.count(id)) {
      // Its door is open but a person it needs is not there again today: it can no longer be done.
      const auto why = with.unschedulable.find(id);
      give_up_job(job, "cannot be done today: " + (why != with.unschedulable.end() ? why->second : "nobody present"),
                  now_s);
      continue;
    }
    if (without.failed || with.failed || with.unschedulable.count(id)) continue;
    // Keeps every other deadline: no other job later than it would be without the opportunity.
    int late_without = 0, late_with = 0;
    double lateness_without = 0.0, lateness_with = 0.0;
    for (const auto& [other_id, other] : jobs_) {
      if (other_id == id || !other.deadline_s) continue;
      const auto a = without.completion_s.find(other_id);
      const auto b = with.completion_s.find(other_id);
      if (a != without.completion_s.end()) {
        late_without += a->second > *other.deadline_s;
        lateness_without += std::max(0.0, a->second - *other.deadline_s);
      }
      if (b != with.completion_s.end()) {
        late_with += b->second > *other.deadline_s;
        lateness_with += std::max(0.0, b->second - *other.deadline_s);
      } else if (a != without.completion_s.end()) {
        ++late_with;  // the detour would leave it out altogether
      }
    }
    if (late_with > late_without || lateness_with > lateness_without + 1e-6) {
      event(ExecutionEvent::Kind::opportunity_declined, "opportunity for job " + id + " declined: it would make other jobs later");
      continue;
    }
    job.state = JobState::queued;
    job.reason.clear();
    event(ExecutionEvent::Kind::opportunity_taken, "opportunity: job " + id + " taken up now (" + clock_text(now_s) + ")");
    changed(job);
    adopt(with, now_s);
    reschedule_needed_ = false;
  }
}

}  // namespace autonomy::courier
