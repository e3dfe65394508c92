// When the courier may let the world run without it (quiet ticks, idl/clock.idl): every robot
// parked with nothing to do, nothing to plan, and the next change that time alone brings known.
#include "services/courier/core/execution/courier_executive.hpp"

#include <algorithm>
#include <limits>

namespace autonomy::courier {

std::optional<double> CourierExecutive::idle_until_s(double now_s) const {
  if (reschedule_needed_ || opportunity_pending_ || !orders_.empty() || robots_.empty()) return std::nullopt;
  double until = std::numeric_limits<double>::infinity();
  for (const auto& [id, r] : robots_) {
    // Driving, handing over, or not located yet (the first pose makes a plan): at work.
    if (!r.pose_known || r.handover || !r.goal_id.empty()) return std::nullopt;
    if (r.hold_until_s > now_s) {
      until = std::min(until, r.hold_until_s);  // then it goes on, or home
      continue;
    }
    if (std::any_of(r.route.begin(), r.route.end(), [&](const PlanStop& s) { return still_needed(r, s); }))
      return std::nullopt;
  }
  if (schedule_retry_at_) until = std::min(until, *schedule_retry_at_);
  // A closed door not seen again is assumed open when its sighting goes stale: a change of plan.
  for (const auto& [id, door] : doors_.doors())
    if (!door.open) until = std::min(until, door.seen_at_s + settings_.closed_door_stale_s);
  // A job waiting for a door believed closed is given up when its deadline is long past (one
  // whose door is believed open waits for the idle policy instead: no wake-up for it).
  if (settings_.give_up_after_deadline_s >= 0.0)
    for (const auto& [id, job] : jobs_) {
      if (job.state != JobState::opportunistic || !job.deadline_s) continue;
      const std::string& place = next_step(job) == NextStep::load ? job.object_place : job.target_place();
      if (closed_door_for(place)) until = std::min(until, *job.deadline_s + settings_.give_up_after_deadline_s);
    }
  return until;
}

}  // namespace autonomy::courier
