// BehaviorNode in goal mode, fleet traffic (docs/traffic.md): this robot's itinerary out, the
// others' in, the traffic rule's decision each tick (drive, wait at a holding point, give up),
// and the robots that hold nothing (no itinerary, a stale one, parked) planned around. The rule
// itself is services/behavior/core/traffic; this file only feeds it and carries out its decisions.
#include "services/behavior/dds/behavior_node.hpp"

#include "services/behavior/core/traffic/brake.hpp"
#include "services/behavior/core/traffic/field_path.hpp"
#include "services/behavior/core/traffic/give_way.hpp"
#include "services/behavior/core/traffic/holding_point.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>

namespace autonomy::behavior {

namespace {

constexpr double kItineraryLength_m = 10.0;    // how much of the path the itinerary shows
constexpr double kItineraryPeriod_s = 0.5;     // written at least this often while ready
constexpr double kObstacleRange_m = 6.0;       // robots that hold nothing are planned around within
constexpr double kObstacleMoved_m = 0.25;      // a robot obstacle that moved this far is replanned
constexpr double kHoldingTolerance_m = 0.15;
constexpr double kDroppedStill_m = 0.05;       // a waiting robot left out of the plan that moves more is tried again
// A robot standing with nothing to drive this long is planned around: one that stands a moment
// between goals is not (planning around every such robot lengthened the ten-robot swarm's goals
// past its 300 s bound), one waiting at a door's lookout for minutes is.
constexpr double kStandingLong_s = 15.0;

std::string format_xy(const geometry::Vec2& p) {
  char b[64];
  std::snprintf(b, sizeof b, "(%.2f, %.2f)", p.x(), p.y());
  return b;
}

}  // namespace

void BehaviorNode::open_traffic_topics() {
  const auto& p = service_.participant();
  itinerary_topic_ = std::make_unique<dds::Topic<msg::Itinerary>>(p, dds::topics::itinerary);
  // This process's own itineraries are not delivered to it (they were skipped below, after a
  // wake-up of the loop for each), and the others' are stored in the receive thread that delivers
  // them: a short handler, and no wake-up of the loop's thread per itinerary.
  dds::Qos qos = dds::make_qos(dds::topics::itinerary.qos);
  dds_qset_ignorelocal(qos.get(), DDS_IGNORELOCAL_PARTICIPANT);
  itinerary_reader_ = std::make_unique<dds::Reader<msg::Itinerary>>(p, *itinerary_topic_, qos.get());
  itinerary_writer_ = std::make_unique<dds::Writer<msg::Itinerary>>(p, *itinerary_topic_);
  service_.loop().on_samples_at_arrival<msg::Itinerary>(*itinerary_reader_, [this](auto samples) {
    for (auto& s : samples) {
      if (!s.valid || s.value.robot_id == options_.robot_id) continue;
      auto& held = itineraries_[s.value.robot_id];
      if (s.value.sim_time_ns >= held.sim_time_ns) held = std::move(s.value);
    }
  });
}

void BehaviorNode::start_traffic(double radius_m) {
  robot_radius_ = radius_m;
  traffic::PassageSettings ps;
  ps.robot_radius_m = radius_m;
  traffic_.emplace(traffic::narrow_passages(world_, ps), options_.robot_id, options_.traffic_rule);
  std::string names;
  for (const auto& p : traffic_->passages()) names += (names.empty() ? "" : ", ") + p.id;
  spdlog::info("robot {}: traffic: {} narrow passages reserved one robot at a time{}{}", options_.robot_id,
               traffic_->passages().size(), names.empty() ? "" : ": ", names);
}

std::vector<traffic::OtherRobot> BehaviorNode::other_robots(double now_s) const {
  std::vector<traffic::OtherRobot> out;
  for (const auto& [id, st] : teammate_states_) {
    traffic::OtherRobot o;
    o.id = id;
    o.position = geometry::Vec2(st.x, st.y);
    const auto it = itineraries_.find(id);
    if (it != itineraries_.end()) {
      const msg::Itinerary& i = it->second;
      o.has_itinerary = true;
      o.itinerary_age_s = now_s - static_cast<double>(i.sim_time_ns) * 1e-9;
      o.has_path = !i.path.empty();
      for (const auto& p : i.path) o.path.emplace_back(p.x, p.y);
      const auto state = traffic::claim_state_from(i.claim);
      if (state && *state != traffic::ClaimState::None)
        o.claim = {i.passage, *state, static_cast<double>(i.request_time_ns) * 1e-9};
    } else if (traffic_since_s_ && now_s - *traffic_since_s_ <= options_.traffic_rule.itinerary_expiry_s) {
      // Not heard of yet, just after this robot started: robots starting together publish
      // within the expiry, so it is taken as one that drives until then.
      o.has_itinerary = true;
      o.has_path = true;
    }
    out.push_back(std::move(o));
  }
  return out;
}

WorldMap BehaviorNode::planning_world() const {
  WorldMap w = doors_.apply(world_);
  for (const auto& [id, o] : robot_obstacles_)
    w.obstacles.push_back({o.position.x() - o.radius, o.position.y() - o.radius, o.position.x() + o.radius,
                           o.position.y() + o.radius});
  return w;
}

std::string BehaviorNode::planning_closures() const {
  const std::vector<std::string> closed = doors_.closed();
  std::string out = closed.empty() ? "" : describe_closed_doors(closed);
  for (const auto& [id, o] : robot_obstacles_) out += (out.empty() ? "" : "; ") + o.why;
  return out;
}

std::string BehaviorNode::describe_robot_obstacle(const std::string& id, const RobotObstacle& o) const {
  using Kind = RobotObstacle::Kind;
  std::string why;
  switch (o.kind) {
    case Kind::NoItinerary: why = id + " (no itinerary)"; break;
    case Kind::StaleItinerary: {
      char b[32];
      std::snprintf(b, sizeof b, "%.1f s", o.itinerary_age_s);
      why = id + " (no itinerary for " + b + ")";
      break;
    }
    case Kind::Parked: why = id + " (parked)"; break;
    case Kind::Waiting: why = id + " (waiting)"; break;
  }
  std::string where;
  for (const auto& q : traffic_->passages())
    if (q.contains(o.position)) where = " in " + q.name;
  return "robot " + why + " at " + format_xy(o.position) + where;
}

void BehaviorNode::refresh_robot_obstacles(const geometry::Vec2& me, double now_s, const std::string& force) {
  if (!force.empty()) forced_obstacles_.insert(force);
  const double expiry = options_.traffic_rule.itinerary_expiry_s;
  std::map<std::string, RobotObstacle> now;
  for (const auto& [id, st] : teammate_states_) {
    const geometry::Vec2 p(st.x, st.y);
    if ((p - me).norm() > kObstacleRange_m) continue;
    const auto it = itineraries_.find(id);
    // A robot never heard of counts from this robot's first traffic step: robots starting
    // together publish within the expiry.
    const double age = now_s - (it == itineraries_.end() ? *traffic_since_s_
                                                         : static_cast<double>(it->second.sim_time_ns) * 1e-9);
    using Kind = RobotObstacle::Kind;
    Kind kind;
    if (it == itineraries_.end()) {
      if (age <= expiry) continue;
      kind = Kind::NoItinerary;
    } else if (age > expiry) {
      kind = Kind::StaleItinerary;
    } else if (forced_obstacles_.count(id) && it->second.path.empty() && it->second.claim.empty()) {
      kind = Kind::Parked;
    } else if (it->second.claim == "waiting" && it->second.path.size() <= 1) {
      kind = Kind::Waiting;  // soft: planned around only while a route is left beside it
    } else if (it->second.path.empty() && it->second.claim.empty()) {
      // Standing with nothing to drive (parked, at a lookout): once it has stood kStandingLong_s,
      // soft like a waiting robot. Not planned around, it was driven up to in the open hallway and
      // the brake stalled the mover ("no progress for 10 s"), for minutes when it stood long.
      auto [at, fresh_stand] = standing_.try_emplace(id, Standing{p, now_s});
      if (!fresh_stand && (at->second.position - p).norm() > kObstacleMoved_m) at->second = {p, now_s};
      if (now_s - at->second.since_s < kStandingLong_s) continue;
      kind = Kind::Parked;
    } else {
      standing_.erase(id);
      continue;  // it drives or waits by the rule: not an obstacle
    }
    if (kind != Kind::Parked) standing_.erase(id);
    // Described (why) only when planned around: this runs at every tick. Only an obstacle the
    // traffic rule forced (a robot holding nothing in a passage) is hard.
    now[id] = {p, st.radius, "", kind == Kind::Waiting || (kind == Kind::Parked && !forced_obstacles_.count(id)), kind, age};
  }
  // Waiting robots dropped before for leaving no route stay dropped while they stand still.
  for (auto it = soft_dropped_.begin(); it != soft_dropped_.end();) {
    const auto n = now.find(it->first);
    it = n != now.end() && n->second.soft ? std::next(it) : soft_dropped_.erase(it);
  }
  for (auto it = now.begin(); it != now.end();) {
    const auto d = soft_dropped_.find(it->first);
    const bool still = d != soft_dropped_.end() && (d->second - it->second.position).norm() <= kDroppedStill_m;
    it = still ? now.erase(it) : std::next(it);
  }
  // A forced obstacle that drives again, or went away, is forgotten.
  for (auto it = forced_obstacles_.begin(); it != forced_obstacles_.end();)
    it = now.count(*it) ? std::next(it) : forced_obstacles_.erase(it);
  bool changed = now.size() != robot_obstacles_.size();
  for (const auto& [id, o] : now) {
    const auto old = robot_obstacles_.find(id);
    changed |= old == robot_obstacles_.end() || (old->second.position - o.position).norm() > kObstacleMoved_m;
  }
  if (!changed) return;
  for (auto& [id, o] : now) o.why = describe_robot_obstacle(id, o);
  robot_obstacles_ = std::move(now);
  spdlog::info("robot {}: planning around {}", options_.robot_id,
               robot_obstacles_.empty() ? std::string("no robots") : planning_closures());
  const OccupancyGrid& old = tracker_->grid();
  tracker_->set_grid(OccupancyGrid(planning_world(), old.geometry().resolution_m(), old.inflation_radius_m()),
                     planning_closures());
  if (follower_) update_map_obstacles();
  const auto target = tracker_->target();
  if (!target || !pursued_constraints_) return;
  std::string error;
  auto field = field_for(target->goal, *pursued_constraints_, &error);
  if (!field) {
    spdlog::warn("goal {}: cannot replan around robots: {}", target->id, error);
    return;
  }
  const auto routed = [&](const CostToGoField& f) {
    return std::isfinite(f.cost_at(me)) ||
           f.nearest_reachable(me, tracker_->config().route_search_radius_m).has_value();
  };
  bool soft = false;
  for (const auto& [id, o] : robot_obstacles_) soft |= o.soft;
  if (soft && !routed(*field)) {
    // Waiting robots leave no way past: they will move, so they are not planned around.
    for (auto it = robot_obstacles_.begin(); it != robot_obstacles_.end();) {
      if (it->second.soft) soft_dropped_[it->first] = it->second.position;
      it = it->second.soft ? robot_obstacles_.erase(it) : std::next(it);
    }
    tracker_->set_grid(OccupancyGrid(planning_world(), old.geometry().resolution_m(), old.inflation_radius_m()),
                       planning_closures());
    field = field_for(target->goal, *pursued_constraints_, &error);
    if (!field) return;
  }
  publish(tracker_->replan(std::move(*field), now_s));
  if (follower_ && tracker_->active()) {
    path_wanted_ = true;
    plan_path("robots in the way changed");
  }
}

void BehaviorNode::forget_waiting_robots() {
  soft_dropped_.clear();
  bool soft = false;
  for (auto it = robot_obstacles_.begin(); it != robot_obstacles_.end();) {
    soft |= it->second.soft;
    it = it->second.soft ? robot_obstacles_.erase(it) : std::next(it);
  }
  if (!soft || !tracker_) return;
  const OccupancyGrid& old = tracker_->grid();
  tracker_->set_grid(OccupancyGrid(planning_world(), old.geometry().resolution_m(), old.inflation_radius_m()),
                     planning_closures());
  if (follower_) update_map_obstacles();
}

std::optional<VelocityCommand> BehaviorNode::traffic_step(const geometry::Pose2& pose, double now_s) {
  path_ahead_.clear();
  const std::string last_reason = traffic_decision_.reason;
  traffic_decision_ = {};
  if (!traffic_) return std::nullopt;
  const geometry::Vec2 me = pose.position();
  if (!traffic_since_s_) traffic_since_s_ = now_s;
  refresh_robot_obstacles(me, now_s);
  if (!tracker_->active()) {
    traffic_->reset();
    holding_.reset();
    return std::nullopt;
  }
  // All the goal's waits together are bounded, not only each one.
  if (const auto target = tracker_->target(); target && target->id != waited_goal_) {
    waited_goal_ = target->id;
    waited_s_ = 0.0;
  }
  if (tracker_->waiting() && last_traffic_step_s_) waited_s_ += now_s - *last_traffic_step_s_;
  last_traffic_step_s_ = now_s;
  if (tracker_->waiting() && waited_s_ >= options_.traffic_rule.max_wait_s) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f s", waited_s_);
    publish(tracker_->block("waited " + std::string(b) + " in all for other robots (last: " + last_reason + ")"));
    traffic_->reset();
    holding_.reset();
    return VelocityCommand{};
  }
  path_ahead_ = traffic::field_path(*tracker_->field(), me, kItineraryLength_m);
  const std::vector<traffic::OtherRobot> others = other_robots(now_s);
  traffic_decision_ = traffic_->decide(me, path_ahead_, others, now_s);
  const traffic::TrafficDecision& d = traffic_decision_;
  switch (d.action) {
    case traffic::TrafficAction::Drive:
      if (const auto whom = traffic::give_way_to(
              options_.robot_id, me, traffic::meets_first(me, traffic_->claim(), traffic_->passages()), path_ahead_,
              others, traffic_->passages(), options_.traffic_rule.itinerary_expiry_s))
        return give_way(pose, *whom, others, now_s);
      if (tracker_->waiting()) {
        spdlog::info("robot {}: {}", options_.robot_id,
                     d.passage ? d.passage->name + " granted" : std::string("way clear"));
        publish(tracker_->proceed(now_s));
      }
      holding_.reset();
      return std::nullopt;
    case traffic::TrafficAction::Wait: {
      // The grant delay with nobody ahead: a pause of a few ticks, not worth a status.
      if (d.blocker.empty() && !tracker_->waiting()) return VelocityCommand{};
      if (!tracker_->waiting()) spdlog::info("robot {}: {}", options_.robot_id, d.reason);
      publish(tracker_->wait(d.reason, now_s));
      if (!holding_ || holding_->blocker != d.blocker) {
        holding_.emplace();
        holding_->blocker = d.blocker;
        std::vector<geometry::Vec2> keep_clear;
        if (const auto it = itineraries_.find(d.blocker); it != itineraries_.end())
          for (const auto& p : it->second.path) keep_clear.emplace_back(p.x, p.y);
        holding_->point = traffic::holding_point(tracker_->grid(), me, *d.passage, traffic_->passages(), keep_clear);
        if (holding_->point) holding_->field.emplace(tracker_->grid(), *holding_->point);
      }
      if (!holding_->field) return VelocityCommand{};
      return controller_->command(pose, *holding_->field, kHoldingTolerance_m).command;
    }
    case traffic::TrafficAction::Obstacle:
      spdlog::info("robot {}: {}; planning around it", options_.robot_id, d.reason);
      refresh_robot_obstacles(me, now_s, d.blocker);
      holding_.reset();
      return VelocityCommand{};
    case traffic::TrafficAction::GiveUp:
      publish(tracker_->block(d.reason));
      holding_.reset();
      return VelocityCommand{};
  }
  return std::nullopt;
}

VelocityCommand BehaviorNode::give_way(const geometry::Pose2& pose, const std::string& whom,
                                       const std::vector<traffic::OtherRobot>& others, double now_s) {
  traffic_decision_.action = traffic::TrafficAction::Wait;
  traffic_decision_.blocker = whom;
  traffic_decision_.reason = "giving way to " + whom;
  if (!holding_ || holding_->blocker != whom) {
    if (!tracker_->waiting() || !holding_) spdlog::info("robot {}: {}", options_.robot_id, traffic_decision_.reason);
    publish(tracker_->wait(traffic_decision_.reason, now_s));
    holding_.emplace();
    holding_->blocker = whom;
    std::vector<geometry::Vec2> their_path;
    for (const auto& o : others)
      if (o.id == whom) {
        their_path = o.path;
        their_path.push_back(o.position);
      }
    std::vector<geometry::Vec2> robots;
    for (const auto& o : others)
      if (o.id != whom) robots.push_back(o.position);
    holding_->point = traffic::side_point(tracker_->grid(), pose.position(), their_path, traffic_->passages(), robots);
    if (holding_->point) holding_->field.emplace(tracker_->grid(), *holding_->point);
  }
  if (!holding_->field) return VelocityCommand{};
  return controller_->command(pose, *holding_->field, kHoldingTolerance_m).command;
}

VelocityCommand BehaviorNode::brake_for_robots(const geometry::Pose2& pose, const VelocityCommand& command) const {
  if (!traffic_) return command;
  std::vector<traffic::Disc> near;
  for (const auto& [id, st] : teammate_states_) near.push_back({geometry::Vec2(st.x, st.y), st.radius});
  return traffic::brake_for_robots(pose, controller_->kinematics(), robot_radius_, command, near);
}

void BehaviorNode::publish_itinerary(double now_s, int64_t tick) {
  if (!traffic_ || !itinerary_writer_ || !state_) return;
  const traffic::Claim& c = traffic_->claim();
  const std::string key = std::string(traffic::to_string(c.state)) + "|" + c.passage + "|" + traffic_decision_.blocker +
                          "|" + (tracker_ && tracker_->waiting() ? "w" : "");
  if (key == last_itinerary_key_ && now_s - last_itinerary_s_ < kItineraryPeriod_s) return;
  msg::Itinerary it;
  it.robot_id = options_.robot_id;
  it.tick = tick;
  it.sim_time_ns = state_->sim_time_ns;
  it.radius = robot_radius_;
  it.x = state_->x;
  it.y = state_->y;
  // Expected times at full speed from now; a waiting robot shows where it waits.
  geometry::Vec2 prev(state_->x, state_->y);
  double t = now_s;
  const double speed = std::max(state_->max_speed, 1e-3);
  std::vector<geometry::Vec2> points = path_ahead_;
  if (tracker_ && tracker_->waiting()) {
    points.clear();
    if (holding_ && holding_->point) points.push_back(*holding_->point);
  }
  for (const geometry::Vec2& p : points) {
    t += (p - prev).norm() / speed;
    prev = p;
    it.path.push_back({p.x(), p.y(), static_cast<int64_t>(std::llround(t * 1e9))});
  }
  it.passage = c.passage;
  // Giving way (Wait without a passage claim) is published as waiting on no passage: the others
  // then see a robot standing aside (give_way.hpp's standing()) and plan around it.
  const bool giving_way = traffic_decision_.action == traffic::TrafficAction::Wait && c.state == traffic::ClaimState::None;
  it.claim = giving_way ? "waiting" : traffic::to_string(c.state);
  it.request_time_ns = static_cast<int64_t>(std::llround(c.request_time_s * 1e9));
  it.waiting_for = traffic_decision_.action == traffic::TrafficAction::Wait ? traffic_decision_.blocker : "";
  itinerary_writer_->write(it);
  last_itinerary_s_ = now_s;
  last_itinerary_key_ = key;
}

}  // namespace autonomy::behavior
