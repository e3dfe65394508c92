#include "simulator/core/world.hpp"

#include "simulator/core/free_space.hpp"
#include "simulator/core/number_format.hpp"
#include "simulator/core/robot_id.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

namespace autonomy::sim {

namespace {

// Relative slack on limit checks, so a controller that asks for exactly max_speed after some
// arithmetic (hypot, scaling) is not rejected for a rounding error.
constexpr double kLimitTolerance = 1e-9;
// Slack on comparing accumulated simulated time with expiry times.
constexpr double kTimeTolerance = 1e-9;
// Spacing of collision samples along a path: fine enough that a disc cannot pass through an
// obstacle between samples, and only grazes one by less than 0.2 mm.
constexpr double kMaxSampleSpacing = 0.02;  // m
// Precision of the contact point found by bisection.
constexpr double kContactPrecision = 0.5e-3;  // m
// Cells of the robot grid: a few robot diameters, so a collision test touches 1 to 4 cells and a
// 15 m scan about 8 x 8.
constexpr double kRobotGridCellM = 4.0;

std::string point_text(const geometry::Vec2& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ")";
}

std::optional<std::string> non_finite(const char* name, double value) {
  if (std::isnan(value)) return std::string(name) + " is NaN";
  if (std::isinf(value)) return std::string(name) + " is infinite";
  return std::nullopt;
}

// Bodies and limits are configuration, checked with file positions by the scenario loader;
// here only so that a hand-built spec cannot make collision sampling divide by zero.
void check_body(const RobotSpec& r, const std::string& what) {
  if (!(r.radius > 0.0) || !(r.max_speed > 0.0) || !(r.max_omega > 0.0)) {
    throw std::invalid_argument(what + ": radius, max_speed and max_omega must be positive");
  }
}

bool above(double value, double limit) { return value > limit * (1.0 + kLimitTolerance); }

}  // namespace

World::World(WorldSpec spec) : spec_(std::move(spec)) {
  if (!(spec_.width > 0.0) || !(spec_.height > 0.0)) {
    throw std::invalid_argument("world size must be positive");
  }
  map_ = ObstacleMap(spec_.width, spec_.height, spec_.obstacles, spec_.polygons, spec_.rasters);
  rebuild_robot_grid();
  for (std::size_t i = 0; i < spec_.doors.size(); ++i) {
    const DoorSpec& d = spec_.doors[i];
    if (const auto problem = door_problem(d)) throw std::invalid_argument("door " + d.id + ": " + *problem);
    for (std::size_t j = 0; j < i; ++j) {
      if (spec_.doors[j].id == d.id) throw std::invalid_argument("duplicate door id " + d.id);
    }
    Door door;
    door.angle = door.target = d.angle;
    door.leaf = d.leaf(d.angle);
    door.schedule = DoorSchedule(d.schedule, d.angle, Rng::stream(spec_.seed, "door/" + d.id));
    doors_.push_back(std::move(door));
  }
  if (!(spec_.command_timeout_s > 0.0)) {
    throw std::invalid_argument("command timeout must be positive");
  }
  for (const auto* list : {&spec_.robots_at_start, &spec_.known_robots}) {
    for (const RobotSpec& r : *list) check_body(r, r.id);
  }
  check_body(spec_.attach_defaults, "attach_defaults");
  for (const RobotSpec& r : spec_.robots_at_start) {
    const SpawnResult result = spawn(r.id, r.start);
    if (!result.accepted) throw std::invalid_argument("cannot spawn " + r.id + ": " + result.reason);
  }
}

World::World(const World& other)
    : spec_(other.spec_), map_(other.map_), doors_(other.doors_), robots_(other.robots_),
      max_robot_radius_(other.max_robot_radius_), all_pairs_(other.all_pairs_), time_s_(other.time_s_) {
  rebuild_robot_grid();
}

World& World::operator=(const World& other) {
  if (this != &other) {
    World copy(other);
    *this = std::move(copy);
  }
  return *this;
}

void World::rebuild_robot_grid() {
  robot_grid_ = UniformGrid<const Robot*>(spec_.width, spec_.height, kRobotGridCellM);
  for (const auto& [id, robot] : robots_) robot_grid_.insert(&robot, robot.status.pose.position());
}

const RobotSpec* World::configured(const std::string& id) const {
  for (const auto* list : {&spec_.robots_at_start, &spec_.known_robots}) {
    for (const RobotSpec& r : *list) {
      if (r.id == id) return &r;
    }
  }
  return nullptr;
}

std::optional<std::string> World::placement_problem(const std::string& self,
                                                    const geometry::Vec2& center,
                                                    double radius) const {
  if (!fits_in_world(spec_.width, spec_.height, center, radius)) {
    return "does not fit inside the world [0, " + format_number(spec_.width) + "] x [0, " +
           format_number(spec_.height) + "]";
  }
  if (const auto hit = map_.overlap(center, radius)) return "overlaps " + map_.describe(*hit);
  for (std::size_t i = 0; i < doors_.size(); ++i) {
    if (disc_overlaps_leaf(doors_[i].leaf, center, radius)) return "overlaps door " + spec_.doors[i].id;
  }
  if (all_pairs_) {
    for (const auto& [id, other] : robots_) {
      if (id != self &&
          discs_overlap(center, radius, other.status.pose.position(), other.status.radius)) {
        return "overlaps robot " + id;
      }
    }
    return std::nullopt;
  }
  // The same answer from the grid: of the robots overlapping, the one with the smallest id.
  const Robot* first = nullptr;
  const double reach = radius + max_robot_radius_;
  robot_grid_.for_each_in_box(center - geometry::Vec2(reach, reach), center + geometry::Vec2(reach, reach),
                              [&](const Robot* other) {
                                if (discs_overlap(center, radius, other->status.pose.position(),
                                                  other->status.radius) &&
                                    other->status.id != self && (first == nullptr || other->status.id < first->status.id)) {
                                  first = other;
                                }
                              });
  if (first != nullptr) return "overlaps robot " + first->status.id;
  return std::nullopt;
}

bool World::is_free(const std::string& self, const geometry::Vec2& center, double radius) const {
  return !placement_problem(self, center, radius).has_value();
}

SpawnResult World::spawn(const std::string& id, std::optional<geometry::Pose2> pose) {
  if (const auto problem = robot_id_problem(id)) return SpawnResult::reject(*problem);
  if (robots_.count(id) != 0) {
    if (!pose) return SpawnResult::reattached();
    return SpawnResult::reject("robot " + id + " is already present");
  }
  const RobotSpec* config = configured(id);
  if (!pose) {
    if (config == nullptr) {
      return SpawnResult::reject("no start pose configured for robot " + id + "; pass one");
    }
    pose = config->start;
  }
  for (const auto& problem :
       {non_finite("x", pose->x), non_finite("y", pose->y), non_finite("theta", pose->theta)}) {
    if (problem) return SpawnResult::reject(*problem);
  }
  const RobotSpec& body = config != nullptr ? *config : spec_.attach_defaults;
  if (const auto problem = placement_problem(id, pose->position(), body.radius)) {
    return SpawnResult::reject("robot " + id + " at " + point_text(pose->position()) + " " +
                               *problem);
  }
  Robot robot;
  robot.status.id = id;
  robot.status.kinematics = body.kinematics;
  robot.status.pose = {pose->x, pose->y, geometry::wrap_angle(pose->theta)};
  robot.status.radius = body.radius;
  robot.status.max_speed = body.max_speed;
  robot.status.max_omega = body.max_omega;
  robot.body = body;
  robot.body.id = id;
  robot.noise = Rng::stream(spec_.seed, "robot/" + id);
  if (body.sensors.range.rays > 0 && body.sensors.range.max_range_m > 0.0) {
    robot.range.emplace(body.sensors.range);
  }
  const geometry::Vec2 at = robot.status.pose.position();
  const Robot& placed = robots_.emplace(id, std::move(robot)).first->second;
  robot_grid_.insert(&placed, at);
  max_robot_radius_ = std::max(max_robot_radius_, body.radius);
  return SpawnResult::spawned();
}

CommandResult World::submit(const VelocityCommand& c) {
  const auto it = robots_.find(c.robot_id);
  if (it == robots_.end()) return CommandResult::reject("robot " + c.robot_id + " unknown");
  const RobotStatus& s = it->second.status;
  for (const auto& problem :
       {non_finite("vx", c.vx), non_finite("vy", c.vy), non_finite("omega", c.omega)}) {
    if (problem) return CommandResult::reject(*problem);
  }
  if (s.kinematics == Kinematics::Unicycle && c.vy != 0.0) {
    return CommandResult::reject("vy must be 0 for unicycle robot " + s.id + " (got " +
                                 format_number(c.vy) + ")");
  }
  const double speed = s.kinematics == Kinematics::Holonomic ? std::hypot(c.vx, c.vy) : std::abs(c.vx);
  if (above(speed, s.max_speed)) {
    return CommandResult::reject("speed " + format_number(speed) + " m/s exceeds limit " +
                                 format_number(s.max_speed) + " m/s");
  }
  if (above(std::abs(c.omega), s.max_omega)) {
    return CommandResult::reject("|omega| " + format_number(std::abs(c.omega)) +
                                 " rad/s exceeds limit " + format_number(s.max_omega) + " rad/s");
  }
  it->second.held = {c.vx, c.vy, c.omega};
  it->second.held_until_s = time_s_ + spec_.command_timeout_s;
  return CommandResult::accept();
}

void World::step(double dt) {
  assert(std::isfinite(dt) && dt > 0.0);
  if (!(std::isfinite(dt) && dt > 0.0)) return;  // also in release builds: time never runs back
  for (auto& [id, robot] : robots_) {
    if (time_s_ + kTimeTolerance >= robot.held_until_s) robot.held = {};
    const geometry::Vec2 from = robot.status.pose.position();
    move(robot, dt);  // robots later in id order meet this one where it is now
    robot_grid_.move(&robot, from, robot.status.pose.position());
  }
  time_s_ += dt;
  for (std::size_t i = 0; i < doors_.size(); ++i) {
    // The tolerance keeps an event at t = 1.0 from missing the step that ends at 0.1 * 10.
    if (const auto angle = doors_[i].schedule.advance(time_s_ + kTimeTolerance)) doors_[i].target = *angle;
    try_move_door(i);
  }
}

void World::try_move_door(std::size_t i) {
  Door& door = doors_[i];
  if (door.angle == door.target) return;
  const DoorSpec& spec = spec_.doors[i];
  for (const auto& [id, robot] : robots_) {
    if (disc_in_sweep(spec, door.angle, door.target, robot.status.pose.position(), robot.status.radius)) {
      return;  // blocked: try again after the next step
    }
  }
  door.angle = door.target;
  door.leaf = spec.leaf(door.angle);
}

std::optional<RobotSpec> World::robot_spec(const std::string& id) const {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return std::nullopt;
  return it->second.body;
}

std::vector<DoorStatus> World::doors() const {
  std::vector<DoorStatus> out;
  out.reserve(doors_.size());
  for (std::size_t i = 0; i < doors_.size(); ++i) {
    const Door& d = doors_[i];
    out.push_back({spec_.doors[i].id, d.angle, d.target, d.angle != d.target, d.leaf});
  }
  return out;
}

std::optional<DoorStatus> World::door(const std::string& id) const {
  for (const DoorStatus& d : doors()) {
    if (d.id == id) return d;
  }
  return std::nullopt;
}

CommandResult World::set_door(const std::string& id, double angle) {
  for (std::size_t i = 0; i < doors_.size(); ++i) {
    const DoorSpec& spec = spec_.doors[i];
    if (spec.id != id) continue;
    if (!(angle >= 0.0 && angle <= spec.max_angle)) {
      return CommandResult::reject("door " + id + ": angle " + format_number(angle) + " is outside [0, " +
                                   format_number(spec.max_angle) + "]");
    }
    doors_[i].target = angle;
    try_move_door(i);
    return CommandResult::accept();
  }
  return CommandResult::reject("door " + id + " unknown");
}

std::vector<DoorView> World::door_views() const {
  std::vector<DoorView> views;
  views.reserve(doors_.size());
  for (std::size_t i = 0; i < doors_.size(); ++i) views.push_back({&spec_.doors[i], doors_[i].angle});
  return views;
}

DynamicObstacles World::dynamic_obstacles(const std::string& except_robot, const geometry::Vec2& center,
                                          double reach) const {
  DynamicObstacles out;
  out.leaves.reserve(doors_.size());
  for (const Door& d : doors_) out.leaves.push_back(d.leaf);
  if (all_pairs_) {
    out.robots.reserve(robots_.size());
    for (const auto& [id, robot] : robots_) {
      if (id != except_robot) out.robots.push_back({robot.status.pose.position(), robot.status.radius});
    }
    return out;
  }
  // The scan keeps the nearest hit over all discs, so their order does not matter.
  const double r = reach + max_robot_radius_;
  robot_grid_.for_each_in_box(center - geometry::Vec2(r, r), center + geometry::Vec2(r, r), [&](const Robot* robot) {
    if (robot->status.id != except_robot) out.robots.push_back({robot->status.pose.position(), robot->status.radius});
  });
  return out;
}

bool World::line_of_sight(const geometry::Vec2& a, const geometry::Vec2& b) const {
  return visible(map_, door_views(), a, b);
}

std::optional<RangeScan> World::sense(const std::string& id) {
  const auto it = robots_.find(id);
  if (it == robots_.end() || !it->second.range) return std::nullopt;
  Robot& robot = it->second;
  return robot.range->scan(robot.status.pose, map_,
                           dynamic_obstacles(id, robot.status.pose.position(), robot.range->spec().max_range_m),
                           &robot.noise);
}

std::optional<RangeScan> World::sense(const std::string& id, const RangeSensorSpec& sensor) {
  const auto it = robots_.find(id);
  if (it == robots_.end() || sensor.rays < 1 || !(sensor.max_range_m > 0.0)) return std::nullopt;
  Robot& robot = it->second;
  return RangeSensor(sensor).scan(robot.status.pose, map_,
                                  dynamic_obstacles(id, robot.status.pose.position(), sensor.max_range_m),
                                  &robot.noise);
}

std::vector<DoorObservation> World::observe_doors(const std::string& id) {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return {};
  return observe_doors(id, it->second.body.sensors.doors);
}

std::vector<DoorObservation> World::observe_doors(const std::string& id, const DoorSensorSpec& sensor) {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return {};
  Robot& robot = it->second;
  return DoorObserver(sensor).observe(robot.status.pose, map_, door_views(), &robot.noise);
}

std::optional<geometry::Pose2> World::observe_pose(const std::string& id) {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return std::nullopt;
  Robot& robot = it->second;
  const PoseSensorSpec& noise = robot.body.sensors.pose;
  geometry::Pose2 p = robot.status.pose;
  if (noise.position_noise_m > 0.0) {
    p.x = robot.noise.normal(p.x, noise.position_noise_m);
    p.y = robot.noise.normal(p.y, noise.position_noise_m);
  }
  if (noise.heading_noise_rad > 0.0) p.theta = geometry::wrap_angle(robot.noise.normal(p.theta, noise.heading_noise_rad));
  return p;
}

void World::move(Robot& robot, double dt) {
  RobotStatus& s = robot.status;
  const Velocity& v = robot.held;
  const geometry::Pose2 start = s.pose;
  const double length = path_length(s.kinematics, v, dt);
  const auto position_at = [&](double fraction) {
    return advance(start, s.kinematics, v, fraction * dt).position();
  };

  // Largest fraction of the motion whose whole path is free: walk samples until the first
  // blocked one, then bisect between it and the last free one.
  double free_fraction = 1.0;
  const int samples = static_cast<int>(std::ceil(length / std::min(kMaxSampleSpacing, s.radius / 4)));
  for (int i = 1; i <= samples; ++i) {
    const double fraction = static_cast<double>(i) / samples;
    if (is_free(s.id, position_at(fraction), s.radius)) continue;
    double lo = static_cast<double>(i - 1) / samples;
    double hi = fraction;
    while ((hi - lo) * length > kContactPrecision) {
      const double mid = 0.5 * (lo + hi);
      (is_free(s.id, position_at(mid), s.radius) ? lo : hi) = mid;
    }
    free_fraction = lo;
    break;
  }

  s.in_collision = free_fraction < 1.0;
  s.pose = advance(start, s.kinematics, v, free_fraction * dt);
  // Turning is always allowed (a disc's footprint does not depend on heading), so a blocked
  // robot still completes its rotation and can turn away from what stopped it.
  s.pose.theta = advance(start, s.kinematics, v, dt).theta;
  s.vx = v.vx * free_fraction;
  s.vy = v.vy * free_fraction;
  s.omega = v.omega;
  s.distance_travelled += free_fraction * length;
}

bool World::remove(const std::string& id) {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return false;
  robot_grid_.erase(&it->second, it->second.status.pose.position());
  robots_.erase(it);
  return true;
}

std::vector<RobotStatus> World::robots() const {
  std::vector<RobotStatus> out;
  out.reserve(robots_.size());
  for (const auto& [id, robot] : robots_) out.push_back(robot.status);
  return out;
}

std::optional<RobotStatus> World::robot(const std::string& id) const {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return std::nullopt;
  return it->second.status;
}

}  // namespace autonomy::sim
