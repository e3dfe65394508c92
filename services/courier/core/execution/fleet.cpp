// The executive's fleet: robots joining and leaving while jobs run, their poses, and what happens
// to the jobs of a robot that is gone (reallocated, or stranded with the object it carries).
#include "services/courier/core/execution/courier_executive.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace autonomy::courier {

std::vector<std::string> CourierExecutive::robot_ids() const {
  std::vector<std::string> ids;
  for (const auto& [id, r] : robots_) ids.push_back(id);
  return ids;
}

void CourierExecutive::add_robot(const std::string& id, int capacity) {
  if (const auto member = robots_.find(id); member != robots_.end()) {
    member->second.capacity = std::max(1, capacity);
    reschedule_needed_ = true;
    return;
  }
  Robot r;
  bool back = false;
  if (const auto old = departed_.find(id); old != departed_.end()) {
    // Its counters go on, so no goal or request id repeats; an answer it never got is asked for
    // again with the same id (the simulator answers a repeat with its latest answer).
    back = true;
    r.goal_seq = old->second.goal_seq;
    r.request_seq = old->second.request_seq;
    r.handover = old->second.handover;
    if (r.handover) r.handover->sent_at_s = -1e18;
    departed_.erase(old);
  }
  r.id = id;
  r.capacity = std::max(1, capacity);
  for (auto it = restored_handovers_.begin(); it != restored_handovers_.end();) {
    if (it->robot != id) {
      ++it;
      continue;
    }
    r.handover = PendingHandover{*it, -1e18, false};
    it = restored_handovers_.erase(it);
  }
  robots_[id] = std::move(r);
  event(ExecutionEvent::Kind::robot_joined,
        id + (back ? " is back in the fleet" : " joined the fleet") + " (capacity " +
            std::to_string(std::max(1, capacity)) + ")");
  for (auto& [job_id, job] : jobs_) {
    if (job.state != JobState::stranded || job.robot != id) continue;
    job.state = JobState::queued;
    job.phase = JobPhase::none;
    job.reason.clear();
    event(ExecutionEvent::Kind::resumed, "job " + job_id + " goes on: " + id + " is back");
    changed(job);
  }
  reschedule_needed_ = true;
}

void CourierExecutive::restore_pending_handover(const HandoverOrder& order) {
  const auto it = robots_.find(order.robot);
  if (it == robots_.end()) {
    restored_handovers_.push_back(order);
    return;
  }
  // sent_at far back: the first step sends it again at once.
  it->second.handover = PendingHandover{order, -1e18, false};
}

void CourierExecutive::on_pose(const std::string& robot, double x, double y) {
  const auto it = robots_.find(robot);
  if (it == robots_.end() || !std::isfinite(x) || !std::isfinite(y)) return;
  if (!it->second.pose_known) reschedule_needed_ = true;  // it can be planned for from now on
  it->second.x = x;
  it->second.y = y;
  it->second.pose_known = true;
  if (!it->second.home_known) {
    it->second.home_known = true;
    it->second.home_x = x;
    it->second.home_y = y;
  }
}

std::optional<CourierExecutive::ParkingPlace> CourierExecutive::parking_place(Robot& robot) {
  for (const auto& spot : floor_.parking)
    if (spot.name == robot.parking) return ParkingPlace{spot.x, spot.y, spot.name};
  const Floor::ParkingSpot* best = nullptr;
  double best_m = std::numeric_limits<double>::infinity();
  // Not in the room it waits for: parked there, it would be in the way of the robot inside.
  const auto waited = floor_.room_areas.find(robot.waiting_for_room);
  for (const auto& spot : floor_.parking) {
    if (waited != floor_.room_areas.end() && waited->second.contains(spot.x, spot.y)) continue;
    bool taken = false;
    for (const auto& [id, other] : robots_) {
      if (id == robot.id) continue;
      taken = taken || other.parking == spot.name ||
              (other.pose_known && std::hypot(other.x - spot.x, other.y - spot.y) <= kParkedM);
    }
    const double m = robot.pose_known ? std::hypot(robot.x - spot.x, robot.y - spot.y) : 0.0;
    if (!taken && m < best_m) {
      best = &spot;
      best_m = m;
    }
  }
  if (best) {
    robot.parking = best->name;
    return ParkingPlace{best->x, best->y, best->name};
  }
  if (robot.home_known) return ParkingPlace{robot.home_x, robot.home_y, ""};
  return std::nullopt;
}

void CourierExecutive::park(Robot& robot, double now_s, const std::string& why) {
  if (robots_.size() > 1 && robot.goal_place == kHomePlace) return;  // on its way
  const std::optional<ParkingPlace> parking = robots_.size() > 1 && robot.pose_known ? parking_place(robot) : std::nullopt;
  if (parking && std::hypot(robot.x - parking->x, robot.y - parking->y) > kParkedM) {
    const bool spot = !parking->spot.empty();
    robot.goal_id = robot.id + (spot ? "/park/" : "/home/") + settings_.id_tag + "." + std::to_string(++robot.goal_seq);
    robot.goal_place = kHomePlace;
    robot.goal_sent_s = now_s;
    robot.goal_answered = false;
    robot.at_place.clear();
    orders_.goals.push_back({robot.id, robot.goal_id, parking->x, parking->y, settings_.goal_tolerance_m});
    char where[64];
    std::snprintf(where, sizeof where, "(%.1f, %.1f)", parking->x, parking->y);
    event(ExecutionEvent::Kind::heading,
          robot.id + (spot ? " parks at " + parking->spot + " " + where : " heads home to " + std::string(where)) +
              ", out of the way: " + why + " (" + clock_text(now_s) + ")");
    return;
  }
  if (robot.goal_id.empty() || robot.goal_place == kHomePlace) return;
  // The place it drives to is no longer needed (its job went to another robot, or ended).
  const std::string reason = "nothing left for " + robot.id + " at " + robot.goal_place;
  orders_.cancels.push_back({robot.id, robot.goal_id, reason});
  event(ExecutionEvent::Kind::goal_cancelled,
        "goal " + robot.goal_id + " cancelled: " + reason + " (" + clock_text(now_s) + ")");
  robot.goal_id.clear();
  robot.goal_place.clear();
}

std::string CourierExecutive::last_seen(const Robot& robot) const {
  if (!robot.pose_known) return "at an unknown place";
  char at[64];
  std::snprintf(at, sizeof at, "at (%.1f, %.1f)", robot.x, robot.y);
  std::string text = at;
  const std::string* nearest = nullptr;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [name, p] : floor_.places) {
    const double d = std::hypot(p.x - robot.x, p.y - robot.y);
    if (d < best) {
      best = d;
      nearest = &name;
    }
  }
  constexpr double kNearM = 3.0;  // farther than this, a place name would mislead
  if (nearest && best <= kNearM) {
    text += " near " + *nearest;
    const std::string& room = floor_.places.at(*nearest).room;
    if (!room.empty()) text += " in " + room;
  }
  return text;
}

void CourierExecutive::remove_robot(const std::string& id, const std::string& why, double now_s) {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return;
  Robot r = std::move(it->second);
  robots_.erase(it);
  const std::string where = last_seen(r) + " at " + clock_text(now_s);
  event(ExecutionEvent::Kind::robot_left, id + " left the fleet (" + why + "), last seen " + where);
  for (auto& [job_id, job] : jobs_) {
    if (job.finished() || job.state == JobState::stranded) continue;
    const bool handing_over = r.handover && r.handover->order.job_id == job_id;
    if (job.object_carrier == id || handing_over) {
      // Its object is aboard the robot that is gone (or in a handover nobody answered yet): no
      // other robot can do anything for it, and the user must know where it is.
      std::string what = job.object.id + " stranded aboard " + id;
      if (handing_over) {
        const HandoverOrder& h = r.handover->order;
        what = job.object.id + (h.load ? " may be aboard " : " may still be aboard ") + id +
               " (its " + (h.load ? "load" : "unload") + " at " + h.place + " was not answered)";
      }
      job.state = JobState::stranded;
      job.phase = JobPhase::none;
      job.robot = id;
      job.estimated_completion_s.reset();
      job.allocation.clear();
      job.reason = what + ", last seen " + where + ": " + why;
      event(ExecutionEvent::Kind::stranded, "job " + job_id + ": " + job.reason);
      changed(job);
    } else if (job.robot == id) {
      job.robot.clear();
      job.state = job.state == JobState::opportunistic ? JobState::opportunistic : JobState::queued;
      job.phase = JobPhase::none;
      job.estimated_completion_s.reset();
      job.allocation.clear();
      if (job.state != JobState::opportunistic)
        job.reason = "reallocated: " + id + " left (" + why + ") at " + clock_text(now_s);
      event(ExecutionEvent::Kind::reallocated,
            "job " + job_id + " reallocated: " + id + " left (" + why + ")");
      changed(job);
    }
  }
  r.route.clear();
  r.pose_known = false;
  departed_[id] = std::move(r);
  reschedule_needed_ = true;
}

}  // namespace autonomy::courier
