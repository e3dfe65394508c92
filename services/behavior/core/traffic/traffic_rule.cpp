#include "services/behavior/core/traffic/traffic_rule.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>

namespace autonomy::behavior::traffic {

namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f s", s);
  return b;
}

}  // namespace

const char* to_string(ClaimState s) {
  switch (s) {
    case ClaimState::None: return "";
    case ClaimState::Waiting: return "waiting";
    case ClaimState::Holding: return "holding";
  }
  return "";
}

std::optional<ClaimState> claim_state_from(const std::string& word) {
  if (word.empty()) return ClaimState::None;
  if (word == "waiting") return ClaimState::Waiting;
  if (word == "holding") return ClaimState::Holding;
  return std::nullopt;
}

TrafficRule::TrafficRule(std::vector<Passage> passages, std::string robot_id, TrafficSettings settings)
    : passages_(std::move(passages)), robot_id_(std::move(robot_id)), settings_(settings) {
  if (robot_id_.empty()) throw std::invalid_argument("traffic rule: empty robot id");
  if (!positive_finite(settings.lookahead_m) || !positive_finite(settings.approach_m) ||
      !std::isfinite(settings.grant_delay_s) || settings.grant_delay_s < 0.0 || !std::isfinite(settings.quiet_radius_m) ||
      settings.quiet_radius_m < 0.0 ||
      !positive_finite(settings.itinerary_expiry_s) || !positive_finite(settings.max_wait_s))
    throw std::invalid_argument("traffic rule settings must be positive and finite (grant delay >= 0)");
}

const Passage* TrafficRule::inside(const geometry::Vec2& p) const {
  for (const Passage& q : passages_)
    if (q.contains(p)) return &q;
  return nullptr;
}

const Passage* TrafficRule::find(const std::string& id) const {
  for (const Passage& q : passages_)
    if (q.id == id) return &q;
  return nullptr;
}

void TrafficRule::reset() {
  claim_ = {};
  waiting_since_s_.reset();
}

TrafficDecision TrafficRule::decide(const geometry::Vec2& me, const std::vector<geometry::Vec2>& path_ahead,
                                    const std::vector<OtherRobot>& others, double now_s) {
  TrafficDecision d;
  // The passage this robot is in, else the first one its path enters within the lookahead.
  const Passage* target = inside(me);
  const bool in_it = target != nullptr;
  if (!target && !path_ahead.empty()) {
    double along = 0.0;
    geometry::Vec2 prev = me;
    for (const geometry::Vec2& p : path_ahead) {
      along += (p - prev).norm();
      prev = p;
      if (along > settings_.lookahead_m) break;
      if ((target = inside(p))) break;
    }
  }
  if (!target) {
    reset();
    d.claim = claim_;
    return d;
  }
  if (claim_.passage != target->id || claim_.state == ClaimState::None) {
    claim_ = {target->id, ClaimState::Waiting, now_s};
    waiting_since_s_.reset();
  }
  d.passage = *target;

  // Who is in the way: a robot in the box holding nothing makes the passage an obstacle; the
  // first of the others in the total order, if it comes before this robot, makes it wait.
  using Key = std::tuple<int, double, std::string>;
  const Key mine{in_it ? 0 : 1, claim_.request_time_s, robot_id_};
  const OtherRobot* first = nullptr;
  Key first_key;
  for (const OtherRobot& o : others) {
    if (o.id == robot_id_) continue;
    const bool o_inside = target->contains(o.position);
    const bool fresh = o.has_itinerary && o.itinerary_age_s <= settings_.itinerary_expiry_s;
    if (o_inside && (!fresh || (!o.has_path && o.claim.state == ClaimState::None))) {
      if (in_it) continue;  // already inside with it: drive on (the simulator stops a collision)
      d.action = TrafficAction::Obstacle;
      d.blocker = o.id;
      d.reason = target->name + " blocked by " + o.id +
                 (!o.has_itinerary ? std::string(" (no itinerary)")
                  : !fresh        ? " (no itinerary for " + seconds(o.itinerary_age_s) + ")"
                                  : std::string(" (parked)"));
      claim_ = {};
      waiting_since_s_.reset();
      d.claim = claim_;
      return d;
    }
    if (!fresh) continue;
    const bool claims = o.claim.state != ClaimState::None && o.claim.passage == target->id;
    if (!o_inside && !claims) continue;
    const Key k{o_inside ? 0 : 1, claims ? o.claim.request_time_s : now_s, o.id};
    if (!first || k < first_key) {
      first = &o;
      first_key = k;
    }
  }
  const bool ahead_of_me = first && first_key < mine;
  // The grant delay lets a request made at the same moment arrive; with no other robot near
  // the passage, none can ask in time to matter, so a lone robot does not stop at every door.
  bool anyone_near = false;
  for (const OtherRobot& o : others)
    anyone_near |= o.id != robot_id_ && target->distance(o.position) <= settings_.quiet_radius_m;
  const bool delay_over = !anyone_near || now_s - claim_.request_time_s >= settings_.grant_delay_s;
  if (in_it || (!ahead_of_me && delay_over)) {
    claim_.state = ClaimState::Holding;
    waiting_since_s_.reset();
    d.claim = claim_;
    return d;
  }
  // Not granted (yet): drive on while far from the box, wait outside it once close.
  claim_.state = ClaimState::Waiting;
  d.claim = claim_;
  if (target->distance(me) > settings_.approach_m) return d;
  if (!waiting_since_s_) waiting_since_s_ = now_s;
  d.blocker = ahead_of_me ? first->id : "";
  d.reason = ahead_of_me ? "waiting for " + first->id + " to clear " + target->name : "requesting " + target->name;
  if (now_s - *waiting_since_s_ >= settings_.max_wait_s) {
    d.action = TrafficAction::GiveUp;
    d.reason = "waited " + seconds(now_s - *waiting_since_s_) + " for " +
               (ahead_of_me ? first->id + " to clear " : std::string("")) + target->name;
    reset();
    d.claim = claim_;
    return d;
  }
  d.action = TrafficAction::Wait;
  return d;
}

}  // namespace autonomy::behavior::traffic
