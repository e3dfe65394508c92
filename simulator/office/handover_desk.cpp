#include "simulator/office/handover_desk.hpp"

#include "common/msg/text_limits.hpp"
#include "simulator/core/robot_id.hpp"

namespace autonomy::sim::office {

const char* to_string(DeskAnswerState state) {
  switch (state) {
    case DeskAnswerState::accepted: return "accepted";
    case DeskAnswerState::rejected: return "rejected";
    case DeskAnswerState::completed: return "completed";
    case DeskAnswerState::failed: return "failed";
  }
  return "?";
}

namespace {

// Why the ids of a request cannot be served, or nothing.
std::optional<std::string> malformed(const DeskRequest& r) {
  if (r.request_id.empty()) return std::string("request_id is empty");
  if (auto problem = msg::first_length_problem({{"request_id", r.request_id, msg::kMaxIdLength},
                                                {"place", r.place, msg::kMaxNameLength},
                                                {"object_id", r.object_id, msg::kMaxNameLength}}))
    return problem;
  if (auto problem = robot_id_problem(r.robot_id)) return problem;
  if (r.kind != HandoverKind::load && r.kind != HandoverKind::unload) return std::string("kind is neither load nor unload");
  if (r.place.empty()) return std::string("place is empty");
  if (r.object_id.empty()) return std::string("object_id is empty");
  return std::nullopt;
}

}  // namespace

DeskAnswer no_office_answer(const DeskRequest& r, double now_s) {
  DeskAnswer a;
  a.request_id = msg::clipped_id(r.request_id);
  a.robot_id = r.robot_id;
  a.kind = r.kind;
  a.place = r.place;
  a.object_id = r.object_id;
  a.state = DeskAnswerState::rejected;
  a.reason = kNoOffice;
  a.detail = "this scenario has no office (people, objects or loading stations)";
  a.time_s = now_s;
  return a;
}

HandoverDesk::HandoverDesk(OfficeSpec spec, uint64_t seed) : office_(std::move(spec)), rng_(seed) {}

DeskAnswer HandoverDesk::answer(const DeskRequest& r, DeskAnswerState state, std::string reason, std::string detail,
                                double now_s) {
  DeskAnswer a;
  a.request_id = msg::clipped_id(r.request_id);
  a.robot_id = r.robot_id;
  a.kind = r.kind;
  a.place = r.place;
  a.object_id = r.object_id;
  a.state = state;
  a.reason = std::move(reason);
  a.detail = std::move(detail);
  a.time_s = now_s;
  return a;
}

DeskAnswer HandoverDesk::request(const DeskRequest& r, const std::optional<RobotAtDesk>& robot, double now_s) {
  if (auto problem = malformed(r)) {
    // Not remembered: a malformed request has no usable id to remember it by.
    return answer(r, DeskAnswerState::rejected, kInvalidRequest, *problem, now_s);
  }
  if (auto seen = answers_.find(r.request_id); seen != answers_.end()) return seen->second;

  DeskAnswer a;
  if (!robot) {
    a = answer(r, DeskAnswerState::rejected, kUnknownRobot, "robot " + r.robot_id + " is not in the world", now_s);
  } else {
    HandoverRequest h;
    h.robot_id = r.robot_id;
    h.robot_position = robot->position;
    h.place = r.place;
    h.object_id = r.object_id;
    h.now_s = now_s;
    h.capacity = robot->capacity;
    const HandoverTicket t = r.kind == HandoverKind::load ? office_.request_load(h, rng_) : office_.request_unload(h, rng_);
    if (t.accepted) {
      a = answer(r, DeskAnswerState::accepted, "", t.detail, now_s);
      a.helper = t.helper;
      a.completes_at_s = t.completes_at_s;
      request_of_[t.handover_id] = r.request_id;
    } else {
      a = answer(r, DeskAnswerState::rejected, to_string(t.reason), t.detail, now_s);
    }
  }
  answers_[r.request_id] = a;
  return a;
}

std::vector<DeskAnswer> HandoverDesk::advance(double now_s, const std::map<std::string, geometry::Vec2>& robot_positions) {
  std::vector<DeskAnswer> out;
  for (const HandoverOutcome& o : office_.advance(now_s, robot_positions)) {
    const auto id = request_of_.find(o.handover_id);
    if (id == request_of_.end()) continue;  // every accepted handover has a request; defensive
    DeskAnswer a = answers_.at(id->second);  // the accepted answer: ids, helper, planned time
    a.state = o.succeeded ? DeskAnswerState::completed : DeskAnswerState::failed;
    a.reason = o.failure ? to_string(*o.failure) : "";
    a.detail = o.detail;
    a.time_s = o.finished_at_s;
    answers_[id->second] = a;
    request_of_.erase(id);
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<ObjectItem> HandoverDesk::changed_objects() {
  std::vector<ObjectItem> out;
  for (const ObjectItem& o : office_.objects()) {
    auto it = published_.find(o.id);
    if (it != published_.end() && it->second == o.location) continue;
    published_[o.id] = o.location;
    out.push_back(o);
  }
  return out;
}

}  // namespace autonomy::sim::office
