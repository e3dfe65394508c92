#include "simulator/office/office_state.hpp"

#include "simulator/core/number_format.hpp"

#include <algorithm>
#include <stdexcept>

namespace autonomy::sim::office {

const char* to_string(HandoverKind kind) { return kind == HandoverKind::load ? "load" : "unload"; }

const char* to_string(HandoverRejection reason) {
  switch (reason) {
    case HandoverRejection::unknown_place: return "unknown_place";
    case HandoverRejection::unknown_object: return "unknown_object";
    case HandoverRejection::robot_not_at_place: return "robot_not_at_place";
    case HandoverRejection::nobody_present: return "nobody_present";
    case HandoverRejection::helper_busy: return "helper_busy";
    case HandoverRejection::robot_busy: return "robot_busy";
    case HandoverRejection::object_in_handover: return "object_in_handover";
    case HandoverRejection::object_not_at_place: return "object_not_at_place";
    case HandoverRejection::robot_full: return "robot_full";
    case HandoverRejection::object_not_carried_by_robot: return "object_not_carried_by_robot";
  }
  return "?";
}

const char* to_string(HandoverFailure failure) {
  return failure == HandoverFailure::robot_moved_away ? "robot_moved_away" : "robot_gone";
}

namespace {

const char* kStationHelper = "station";

std::string describe(const ObjectLocation& l) {
  return l.kind == ObjectLocation::Kind::place ? "at " + l.name : "carried by " + l.name;
}

}  // namespace

OfficeState::OfficeState(OfficeSpec spec) : spec_(std::move(spec)) {
  const auto problems = office_spec_problems(spec_);
  if (!problems.empty()) {
    std::string text = "unusable office:";
    for (const auto& p : problems) text += " " + p + ";";
    throw std::invalid_argument(text);
  }
  objects_ = spec_.objects;
}

const Place* OfficeState::place(const std::string& name) const {
  auto it = std::find_if(spec_.places.begin(), spec_.places.end(),
                         [&](const Place& p) { return p.name == name; });
  return it == spec_.places.end() ? nullptr : &*it;
}

const ObjectItem* OfficeState::object(const std::string& id) const {
  auto it = std::find_if(objects_.begin(), objects_.end(), [&](const ObjectItem& o) { return o.id == id; });
  return it == objects_.end() ? nullptr : &*it;
}

ObjectItem* OfficeState::mutable_object(const std::string& id) {
  return const_cast<ObjectItem*>(static_cast<const OfficeState*>(this)->object(id));
}

std::vector<std::string> OfficeState::carried_by(const std::string& robot_id) const {
  std::vector<std::string> ids;
  for (const auto& o : objects_)
    if (o.location.is_carried_by(robot_id)) ids.push_back(o.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::string> OfficeState::people_present(const std::string& place_name, double now_s) const {
  const double tod = spec_.clock.time_of_day(now_s);
  std::vector<std::string> names;
  for (const Person& p : spec_.people) {
    if (p.desk != place_name) continue;
    if (std::any_of(p.presence.begin(), p.presence.end(), [&](const DailyInterval& i) { return i.contains(tod); }))
      names.push_back(p.name);
  }
  return names;
}

bool OfficeState::has_station(const std::string& place_name) const {
  return std::any_of(spec_.stations.begin(), spec_.stations.end(),
                     [&](const LoadingStation& s) { return s.place == place_name; });
}

std::optional<double> OfficeState::next_presence(const std::string& place_name, double now_s) const {
  const double tod = spec_.clock.time_of_day(now_s);
  std::optional<double> today, tomorrow;
  for (const Person& p : spec_.people) {
    if (p.desk != place_name) continue;
    for (const DailyInterval& i : p.presence) {
      if (i.start_s > tod && (!today || i.start_s < *today)) today = i.start_s;
      if (!tomorrow || i.start_s < *tomorrow) tomorrow = i.start_s;
    }
  }
  return today ? today : tomorrow;
}

bool OfficeState::helper_busy(const std::string& helper, const std::string& place_name) const {
  return std::any_of(pending_.begin(), pending_.end(), [&](const Pending& p) {
    return p.outcome.helper == helper && p.outcome.place == place_name;
  });
}

HandoverTicket OfficeState::reject(HandoverRejection reason, std::string detail) const {
  HandoverTicket t;
  t.accepted = false;
  t.reason = reason;
  t.detail = std::move(detail);
  return t;
}

HandoverTicket OfficeState::request_load(const HandoverRequest& request, std::mt19937_64& rng) {
  return this->request(HandoverKind::load, request, rng);
}

HandoverTicket OfficeState::request_unload(const HandoverRequest& request, std::mt19937_64& rng) {
  return this->request(HandoverKind::unload, request, rng);
}

HandoverTicket OfficeState::request(HandoverKind kind, const HandoverRequest& r, std::mt19937_64& rng) {
  const Place* at = place(r.place);
  if (!at) return reject(HandoverRejection::unknown_place, "unknown place " + r.place);
  const ObjectItem* obj = object(r.object_id);
  if (!obj) return reject(HandoverRejection::unknown_object, "unknown object " + r.object_id);

  const double distance = (r.robot_position - at->position).norm();
  if (distance > at->radius)
    return reject(HandoverRejection::robot_not_at_place,
                  "robot " + r.robot_id + " is " + format_number(distance) + " m from " + at->name +
                      " (must be within " + format_number(at->radius) + " m)");

  if (kind == HandoverKind::load && !obj->location.is_at(at->name))
    return reject(HandoverRejection::object_not_at_place,
                  "object " + obj->id + " is not at " + at->name + " (it is " + describe(obj->location) + ")");
  if (kind == HandoverKind::unload && !obj->location.is_carried_by(r.robot_id))
    return reject(HandoverRejection::object_not_carried_by_robot,
                  "robot " + r.robot_id + " does not carry object " + obj->id + " (it is " +
                      describe(obj->location) + ")");

  for (const Pending& p : pending_) {
    if (p.outcome.object_id == obj->id)
      return reject(HandoverRejection::object_in_handover,
                    "object " + obj->id + " is being handed over to robot " + p.outcome.robot_id);
    if (p.outcome.robot_id == r.robot_id)
      return reject(HandoverRejection::robot_busy,
                    "robot " + r.robot_id + " is already in a handover (" + to_string(p.outcome.kind) + " of " +
                        p.outcome.object_id + " at " + p.outcome.place + ")");
  }

  if (kind == HandoverKind::load) {
    const size_t carried = carried_by(r.robot_id).size();
    if (r.capacity < 0 || carried >= static_cast<size_t>(r.capacity))
      return reject(HandoverRejection::robot_full, "robot " + r.robot_id + " carries " + std::to_string(carried) +
                                                       " objects, its capacity is " + std::to_string(r.capacity));
  }

  // Who hands over: a loading station if there is one, else the first present, free person.
  std::string helper;
  const HandoverTimeModel* model = nullptr;
  bool someone_busy = false;
  for (const LoadingStation& s : spec_.stations) {
    if (s.place != at->name) continue;
    if (helper_busy(kStationHelper, at->name)) {
      someone_busy = true;
    } else {
      helper = kStationHelper;
      model = &s.handover_time;
    }
  }
  const auto present = people_present(at->name, r.now_s);
  for (const std::string& name : present) {
    if (model) break;
    if (helper_busy(name, at->name)) {
      someone_busy = true;
      continue;
    }
    for (const Person& p : spec_.people)
      if (p.name == name) {
        helper = name;
        model = &p.handover_time;
      }
  }
  if (!model) {
    if (someone_busy)
      return reject(HandoverRejection::helper_busy, "everyone at " + at->name + " is handing over to another robot");
    const double tod = spec_.clock.time_of_day(r.now_s);
    std::string detail = "nobody at " + at->name + " at " + format_clock(tod);
    if (auto next = next_presence(at->name, r.now_s))
      detail += *next > tod ? " (somebody is back at " + format_clock(*next) + ")"
                            : " (nobody is back before tomorrow " + format_clock(*next) + ")";
    else
      detail += " (nobody works there)";
    return reject(HandoverRejection::nobody_present, detail);
  }

  const double duration = model->sample(rng);
  Pending p;
  p.outcome.handover_id = next_handover_id_++;
  p.outcome.kind = kind;
  p.outcome.robot_id = r.robot_id;
  p.outcome.object_id = obj->id;
  p.outcome.place = at->name;
  p.outcome.helper = helper;
  p.outcome.requested_at_s = r.now_s;
  p.completes_at_s = r.now_s + duration;
  pending_.push_back(p);

  HandoverTicket t;
  t.accepted = true;
  t.handover_id = p.outcome.handover_id;
  t.helper = helper;
  t.completes_at_s = p.completes_at_s;
  t.detail = std::string(to_string(kind)) + " of " + obj->id + " at " + at->name + " by " + helper + ", " +
             format_number(duration) + " s";
  return t;
}

std::vector<HandoverOutcome> OfficeState::advance(double now_s,
                                                  const std::map<std::string, geometry::Vec2>& robot_positions) {
  std::vector<HandoverOutcome> done;
  // Completions first, in time order, so an object handed over and then asked for again within
  // one call sees the right owner.
  std::vector<Pending> due, rest;
  for (auto& p : pending_) (p.completes_at_s <= now_s ? due : rest).push_back(std::move(p));
  std::stable_sort(due.begin(), due.end(), [](const Pending& a, const Pending& b) {
    return a.completes_at_s < b.completes_at_s ||
           (a.completes_at_s == b.completes_at_s && a.outcome.handover_id < b.outcome.handover_id);
  });
  for (auto& p : due) {
    ObjectItem* obj = mutable_object(p.outcome.object_id);
    obj->location = p.outcome.kind == HandoverKind::load ? ObjectLocation::carried_by(p.outcome.robot_id)
                                                          : ObjectLocation::at_place(p.outcome.place);
    p.outcome.succeeded = true;
    p.outcome.finished_at_s = p.completes_at_s;
    p.outcome.detail = std::string(to_string(p.outcome.kind)) + " of " + p.outcome.object_id + " at " +
                       p.outcome.place + " completed";
    done.push_back(std::move(p.outcome));
  }

  pending_.clear();
  for (auto& p : rest) {
    const Place* at = place(p.outcome.place);
    auto robot = robot_positions.find(p.outcome.robot_id);
    std::optional<HandoverFailure> failure;
    std::string detail;
    if (robot == robot_positions.end()) {
      failure = HandoverFailure::robot_gone;
      detail = "robot " + p.outcome.robot_id + " left the world";
    } else {
      const double distance = (robot->second - at->position).norm();
      if (distance > at->radius) {
        failure = HandoverFailure::robot_moved_away;
        detail = "robot " + p.outcome.robot_id + " moved away from " + at->name + " (" + format_number(distance) +
                 " m) before the " + to_string(p.outcome.kind) + " of " + p.outcome.object_id + " completed";
      }
    }
    if (!failure) {
      pending_.push_back(std::move(p));
      continue;
    }
    p.outcome.succeeded = false;
    p.outcome.failure = failure;
    p.outcome.finished_at_s = now_s;
    p.outcome.detail = detail;
    done.push_back(std::move(p.outcome));
  }
  return done;
}

}  // namespace autonomy::sim::office
