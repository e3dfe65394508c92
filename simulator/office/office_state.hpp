#pragma once
// The ground truth of the office while a run goes on: where every object is, who carries what,
// and the handovers (loads and unloads) under way. What robots perceive of it is computed
// separately (perception.hpp); robots never read this state directly.
//
// A handover follows FAXBOT's routine plan "navigate to the place, wait until the letter is
// loaded": the robot asks, the request is checked at once (accepted or rejected with a reason),
// and an accepted request takes time: it completes after a duration drawn from the helper's
// handover model (the person at the place, or the loading station). Who carries what changes only
// on completion. If the robot leaves the place (or the world) before then, the handover fails
// and nothing changes. A person who has started a handover finishes it even if their presence
// interval ends meanwhile.
//
// Pure and deterministic: time is passed in (simulated seconds since the start of the run), the
// random generator is passed in, and nothing here reads clocks or files.
#include "common/geometry/geometry.hpp"
#include "simulator/office/office_spec.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace autonomy::sim::office {

enum class HandoverKind { load, unload };
const char* to_string(HandoverKind kind);

enum class HandoverRejection {
  unknown_place,
  unknown_object,
  robot_not_at_place,           // farther than the place's radius
  nobody_present,               // no person at the place now and no loading station
  helper_busy,                  // the person or station is handing something to another robot
  robot_busy,                   // the robot already has a handover under way
  object_in_handover,           // another handover of this object is under way
  object_not_at_place,          // load: the object lies elsewhere or is carried
  robot_full,                   // load: the robot carries `capacity` objects already
  object_not_carried_by_robot,  // unload
};
const char* to_string(HandoverRejection reason);

struct HandoverRequest {
  std::string robot_id;
  geometry::Vec2 robot_position{0.0, 0.0};
  std::string place;
  std::string object_id;
  double now_s = 0.0;  // simulated time of the request
  int capacity = 1;    // how many objects the robot can carry (load only)
};

struct HandoverTicket {
  bool accepted = false;
  HandoverRejection reason = HandoverRejection::unknown_place;  // when rejected
  std::string detail;  // one sentence for logs and replies, e.g. "nobody at desk-a at 12:10; ..."
  uint64_t handover_id = 0;      // when accepted: identifies the completion in advance()
  std::string helper;            // when accepted: the person's name or "station"
  double completes_at_s = 0.0;   // when accepted: simulated time of completion if the robot stays
};

enum class HandoverFailure { robot_moved_away, robot_gone };
const char* to_string(HandoverFailure failure);

struct HandoverOutcome {
  uint64_t handover_id = 0;
  HandoverKind kind = HandoverKind::load;
  std::string robot_id;
  std::string object_id;
  std::string place;
  std::string helper;
  double requested_at_s = 0.0;
  double finished_at_s = 0.0;  // completion time, or the time the failure was noticed
  bool succeeded = false;
  std::optional<HandoverFailure> failure;
  std::string detail;
};

class OfficeState {
 public:
  // Throws std::invalid_argument listing office_spec_problems(spec) when there are any.
  explicit OfficeState(OfficeSpec spec);

  [[nodiscard]] HandoverTicket request_load(const HandoverRequest& request, std::mt19937_64& rng);
  [[nodiscard]] HandoverTicket request_unload(const HandoverRequest& request, std::mt19937_64& rng);

  // Moves time to now_s (non-decreasing) given where every robot in the world is now. First
  // completes every pending handover due at or before now_s, then fails those still pending
  // whose robot is absent from robot_positions or outside the place's radius. Returns them
  // ordered by finished_at_s, then by handover id. Call it every tick.
  std::vector<HandoverOutcome> advance(double now_s,
                                       const std::map<std::string, geometry::Vec2>& robot_positions);

  // Ground-truth queries.
  const OfficeSpec& spec() const { return spec_; }
  const Place* place(const std::string& name) const;
  const ObjectItem* object(const std::string& id) const;
  const std::vector<ObjectItem>& objects() const { return objects_; }
  std::vector<std::string> carried_by(const std::string& robot_id) const;  // object ids, sorted
  // Names of the people at `place` at simulated time now_s, in declaration order.
  std::vector<std::string> people_present(const std::string& place, double now_s) const;
  bool has_station(const std::string& place) const;
  // Clock time when somebody is next at `place` after now_s, today or tomorrow; nothing when
  // nobody ever is (and no station).
  std::optional<double> next_presence(const std::string& place, double now_s) const;
  size_t pending_count() const { return pending_.size(); }

 private:
  struct Pending {
    HandoverOutcome outcome;  // filled in as far as known
    double completes_at_s = 0.0;
  };
  HandoverTicket request(HandoverKind kind, const HandoverRequest& r, std::mt19937_64& rng);
  HandoverTicket reject(HandoverRejection reason, std::string detail) const;
  ObjectItem* mutable_object(const std::string& id);
  bool helper_busy(const std::string& helper, const std::string& place) const;

  OfficeSpec spec_;
  std::vector<ObjectItem> objects_;
  std::vector<Pending> pending_;  // in request order
  uint64_t next_handover_id_ = 1;
};

}  // namespace autonomy::sim::office
