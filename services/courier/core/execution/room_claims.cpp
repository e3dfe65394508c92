// The fleet's rule for rooms: one robot in a room at a time.
//
// Why: the office's rooms are entered by a 1 m door and hold one desk; two robots bound for one
// desk at overlapping times (the schedule knows nothing of the other robots' bodies) met inside,
// blocked each other ("no progress for 10 s" beside the desk) and the second gave its job up as
// unreachable. Now a robot whose next stop is in a room that another robot holds does not drive
// in: it waits beside the room's door, out of the doorway, and goes in once the room is free.
//
// Why this cannot deadlock: a robot holds at most one room (the one it is in or bound for), and
// a robot that waits holds none: it is sent out to a lookout in the hallway (or, not first in
// line, to a parking spot outside the room it waits for, or it stays where it is, outside). A
// holder is never waiting, so it only drives to its stop, hands over (bounded by the handover
// timeouts) and leaves, or is given up (blocked goals, refused handovers): every wait ends.
// Robots waiting for one room go in the order they began to wait (ties by id), so none waits for
// ever behind later ones.
//
// A handover place in no room (a desk or a station in the hallway) is claimed the same way, by
// itself: one robot bound for it, handing over at it or standing on it; the next waits where it
// is (or parked, when not first in line). A robot standing on such a place while it waits holds
// it no more, so the rule stays free of cycles: a robot on a hallway place waiting for a room
// does not keep the robot in that room from coming out to the place.
#include "services/courier/core/execution/courier_executive.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::courier {

namespace {
// The prefix of a job's reason while its robot waits for a room; cleared when it goes in.
constexpr char kWaitingPrefix[] = "waiting for ";
}  // namespace

std::string CourierExecutive::claim_of(const std::string& place) const {
  const FloorPlace* p = floor_.place(place);
  if (!p) return {};
  return floor_.door_to(place) ? p->room : place;
}

bool CourierExecutive::within_claim(const std::string& claim, const std::string& place) const {
  if (place.empty()) return false;
  if (place == claim) return true;
  const FloorPlace* p = floor_.place(place);
  return p && !p->room.empty() && p->room == claim && floor_.door_of_room.count(claim);
}

const CourierExecutive::Robot* CourierExecutive::room_holder(const Robot& robot, const std::string& claim) const {
  const auto area = floor_.room_areas.find(claim);
  const FloorPlace* spot_claimed = floor_.door_of_room.count(claim) ? nullptr : floor_.place(claim);
  for (const auto& [id, other] : robots_) {
    if (id == robot.id || !other.pose_known) continue;
    if (within_claim(claim, other.goal_place)) return &other;
    if (other.handover && within_claim(claim, other.handover->order.place)) return &other;
    // Standing on a hallway place holds it unless the robot waits (for a room elsewhere): then
    // it is on its way out of everybody's claim. A waiting robot inside a room still holds the
    // room until it is out (it leaves for the lookout, outside).
    const bool on_it = spot_claimed ? other.waiting_for_room.empty() &&
                                          std::hypot(other.x - spot_claimed->x, other.y - spot_claimed->y) <=
                                              spot_claimed->radius
                                    : area != floor_.room_areas.end() && area->second.contains(other.x, other.y);
    if (!on_it) continue;
    bool parked = other.at_place == kHomePlace;
    for (const auto& spot : floor_.parking)
      parked = parked || (spot.name == other.parking && std::hypot(other.x - spot.x, other.y - spot.y) <= kParkedM);
    if (!parked) return &other;
  }
  return nullptr;
}

bool CourierExecutive::wait_for_room(Robot& robot, const PlanStop& stop, const std::string& waited,
                                     double now_s) {
  Job& job = jobs_.at(stop.job_id);
  const auto go_in = [&] {
    robot.waiting_behind.clear();
    if (job.reason.rfind(kWaitingPrefix, 0) == 0) {
      job.reason.clear();
      changed(job);
    }
    return false;
  };
  if (robots_.size() < 2) return go_in();
  const auto door = floor_.door_to(stop.place);
  const std::string room = claim_of(stop.place);  // the room, or the place itself in the hallway
  if (room.empty()) return go_in();               // not a place of the floor
  // Already inside (a second stop in the room): leaving to wait would only cost time.
  const auto area = floor_.room_areas.find(room);
  if (door && area != floor_.room_areas.end() && area->second.contains(robot.x, robot.y)) return go_in();

  const Robot* holder = room_holder(robot, room);
  // Robots that began to wait for the room before this one go first.
  const double since = waited == room ? robot.waiting_since_s : now_s;
  const Robot* ahead = nullptr;
  for (const auto& [id, other] : robots_) {
    if (id == robot.id || other.waiting_for_room != room) continue;
    if (other.waiting_since_s < since || (other.waiting_since_s == since && id < robot.id)) {
      if (!ahead || other.waiting_since_s < ahead->waiting_since_s) ahead = &other;
    }
  }
  if (!holder && !ahead) return go_in();

  robot.waiting_for_room = room;
  robot.waiting_since_s = since;
  const std::string& blocker = holder ? holder->id : ahead->id;
  const std::string why = kWaitingPrefix + blocker + (holder ? " to clear " : ", first in line for ") + room;
  if (job.reason != why || job.state != JobState::underway || job.robot != robot.id) {
    job.state = JobState::underway;
    job.phase = stop.load ? JobPhase::to_pickup : JobPhase::to_destination;
    if (!job.return_to.empty()) job.phase = JobPhase::returning;
    job.robot = robot.id;
    job.reason = why;
    changed(job);
  }
  const std::string text =
      robot.id + " waits for " + blocker + (holder ? " to clear " : " to go first into ") + room + " before " +
      stop.place + " (" + clock_text(now_s) + ")";
  if (robot.waiting_behind != blocker) {
    robot.waiting_behind = blocker;
    event(ExecutionEvent::Kind::waiting, text);
  }
  // The first in line waits beside the door; the others park, out of the hallway (the lookout
  // is taken, and a robot standing in the hallway is in everybody's way), or, with no spot to
  // park at, stop where they are. The first in line for a place in the hallway stops where it is:
  // the wait is one handover.
  if (!ahead && door && go_to_lookout(robot, *door, {}, now_s)) return true;
  if (!floor_.parking.empty() && (door || ahead)) {
    park(robot, now_s, "waiting for " + room);
    return true;
  }
  if (!robot.goal_id.empty() && !is_lookout(robot.goal_place)) {
    const std::string reason = robot.id + " waits for " + room;
    orders_.cancels.push_back({robot.id, robot.goal_id, reason});
    event(ExecutionEvent::Kind::goal_cancelled,
          "goal " + robot.goal_id + " cancelled: " + reason + " (" + clock_text(now_s) + ")");
    robot.goal_id.clear();
    robot.goal_place.clear();
  }
  return true;
}

double CourierExecutive::free_to_go_s(const Robot& robot, double now_s) const {
  if (robot.waiting_for_room.empty()) return now_s;
  const Robot* holder = room_holder(robot, robot.waiting_for_room);
  if (!holder) return now_s;
  // Its next stops while they are in the room (one visit), as the last schedule timed them; none
  // when it goes elsewhere next (it is leaving).
  double leaves = now_s;
  for (const PlanStop& stop : holder->route) {
    if (!still_needed(*holder, stop)) continue;
    if (!within_claim(robot.waiting_for_room, stop.place)) break;
    leaves = std::max(leaves, stop.finish_s);
  }
  // Leaving the room and clearing its doorway takes a little while in any case.
  constexpr double kClearRoomS = 10.0;
  return std::max(leaves, now_s + kClearRoomS);
}

bool CourierExecutive::go_to_lookout(Robot& robot, const std::string& door, const std::string& why, double now_s) {
  const auto lookout = floor_.door_lookouts.find(door);
  if (lookout == floor_.door_lookouts.end()) return false;
  const std::string place = kLookoutPrefix + door;
  if (robot.goal_place == place || robot.at_place == place) return true;  // on its way, or there
  constexpr double kThereM = 0.5;
  if (robot.pose_known && std::hypot(robot.x - lookout->second.x, robot.y - lookout->second.y) <= kThereM) {
    robot.at_place = place;
    return true;
  }
  robot.goal_id = robot.id + "/lookout-" + door + "/" + settings_.id_tag + "." + std::to_string(++robot.goal_seq);
  robot.goal_place = place;
  robot.parking.clear();
  robot.goal_from.clear();
  robot.goal_sent_s = now_s;
  robot.goal_answered = false;
  robot.at_place.clear();
  orders_.goals.push_back({robot.id, robot.goal_id, lookout->second.x, lookout->second.y, settings_.goal_tolerance_m});
  if (!why.empty()) event(ExecutionEvent::Kind::heading, why);
  return true;
}

}  // namespace autonomy::courier
