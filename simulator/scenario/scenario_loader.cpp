#include "simulator/scenario/scenario_loader.hpp"

#include "idl/scenario.pb.h"
#include "simulator/core/free_space.hpp"
#include "simulator/core/number_format.hpp"
#include "simulator/core/robot_id.hpp"

#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace autonomy::sim {

namespace {

namespace pb = google::protobuf;
using ParseInfoTree = pb::TextFormat::ParseInfoTree;

struct Position {
  int line = 1;  // 1-based
  int column = 1;
};

// Where the parser saw each field, so semantic errors point at the offending text. A field that
// is absent has no position of its own: errors about it point at the enclosing message.
class Locator {
 public:
  Locator(const ParseInfoTree* tree, const pb::Descriptor* type, Position self)
      : tree_(tree), type_(type), self_(self) {}

  Position self() const { return self_; }

  Position at(const char* field, int index = -1) const {
    const pb::FieldDescriptor* f = type_->FindFieldByName(field);
    if (tree_ == nullptr || f == nullptr) return self_;
    const pb::TextFormat::ParseLocation location = tree_->GetLocation(f, index);
    if (location.line < 0) return self_;
    return {location.line + 1, location.column + 1};
  }

  Locator nested(const char* field, int index = -1) const {
    const pb::FieldDescriptor* f = type_->FindFieldByName(field);
    const ParseInfoTree* tree = tree_ != nullptr ? tree_->GetTreeForNested(f, index) : nullptr;
    return {tree, f->message_type(), at(field, index)};
  }

 private:
  const ParseInfoTree* tree_;
  const pb::Descriptor* type_;
  Position self_;
};

class SyntaxErrors : public pb::io::ErrorCollector {
 public:
  SyntaxErrors(const std::string& source, std::vector<ScenarioError>& errors)
      : source_(source), errors_(errors) {}

  void AddError(int line, pb::io::ColumnNumber column, const std::string& message) override {
    errors_.push_back({source_, line + 1, column + 1, message});
  }

 private:
  const std::string& source_;
  std::vector<ScenarioError>& errors_;
};

std::string point_text(double x, double y) {
  return "(" + format_number(x) + ", " + format_number(y) + ")";
}

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// Checks a parsed scenario and converts it to plain structs, collecting every problem.
class ScenarioChecker {
 public:
  ScenarioChecker(const std::string& source, std::vector<ScenarioError>& errors)
      : source_(source), errors_(errors) {}

  Scenario check(const config::Scenario& file, const ParseInfoTree& tree) {
    const Locator root(&tree, config::Scenario::descriptor(), Position{});
    Scenario out;
    out.world.name = file.name();
    world(file, root, out.world);
    out.world.attach_defaults = attach_defaults(file.attach_defaults(), root.nested("attach_defaults"));
    robots(file, root, out.world);
    simulation(file.simulation(), root.nested("simulation"), out);
    return out;
  }

 private:
  void error(Position at, std::string message) {
    errors_.push_back({source_, at.line, at.column, std::move(message)});
  }

  // An explicit value must be a positive finite number; an absent one takes `fallback`.
  double positive(bool present, double value, double fallback, const std::string& what,
                  Position at) {
    if (!present) return fallback;
    if (!(std::isfinite(value) && value > 0.0)) {
      error(at, what + " must be positive (got " + format_number(value) + ")");
    }
    return value;
  }

  void world(const config::Scenario& file, const Locator& root, WorldSpec& out) {
    if (!file.has_world()) {
      error(root.self(), "world is missing");
      return;
    }
    const config::World& w = file.world();
    const Locator at = root.nested("world");
    out.width = positive(true, w.width(), 0.0, "world: width", at.at("width"));
    out.height = positive(true, w.height(), 0.0, "world: height", at.at("height"));
    world_valid_ = std::isfinite(out.width) && out.width > 0.0 && std::isfinite(out.height) &&
                   out.height > 0.0;
    for (int i = 0; i < w.obstacles_size(); ++i) {
      const config::Rectangle& r = w.obstacles(i);
      const geometry::Rect rect{r.min_x(), r.min_y(), r.max_x(), r.max_y()};
      const Position where = at.at("obstacles", i);
      const std::string name = "obstacle " + std::to_string(i);
      if (!all_finite({rect.min_x, rect.min_y, rect.max_x, rect.max_y})) {
        error(where, name + " has a coordinate that is not finite");
      } else if (!rect.valid()) {
        error(where, name + " is empty or inverted: min " + point_text(rect.min_x, rect.min_y) +
                         " must be below max " + point_text(rect.max_x, rect.max_y));
      } else if (world_valid_ && (rect.min_x < 0.0 || rect.min_y < 0.0 ||
                                  rect.max_x > out.width || rect.max_y > out.height)) {
        error(where, name + " from " + point_text(rect.min_x, rect.min_y) + " to " +
                         point_text(rect.max_x, rect.max_y) + " extends outside the world " +
                         world_text(out));
      }
      // Invalid obstacles are kept out of the robot checks, so one typo gives one error.
      if (rect.valid() && all_finite({rect.min_x, rect.min_y, rect.max_x, rect.max_y})) {
        checked_obstacles_.emplace_back(i, rect);
      }
      out.obstacles.push_back(rect);
    }
  }

  static std::string world_text(const WorldSpec& w) {
    return "[0, " + format_number(w.width) + "] x [0, " + format_number(w.height) + "]";
  }

  std::optional<Kinematics> kinematics(config::Kinematics k, const std::string& who,
                                       Position at) {
    switch (k) {
      case config::HOLONOMIC: return Kinematics::Holonomic;
      case config::UNICYCLE: return Kinematics::Unicycle;
      case config::KINEMATICS_UNSPECIFIED: return std::nullopt;
      default: break;
    }
    error(at, who + ": unknown kinematics value " + std::to_string(static_cast<int>(k)));
    return Kinematics::Holonomic;
  }

  // Body and limits shared by all robots: the fallback for what a robot leaves out.
  RobotSpec attach_defaults(const config::Robot& r, const Locator& at) {
    const std::string who = "attach_defaults";
    for (const char* meaningless : {"id", "start", "spawn_at_start"}) {
      const pb::FieldDescriptor* f = config::Robot::descriptor()->FindFieldByName(meaningless);
      if (r.GetReflection()->HasField(r, f)) {
        error(at.at(meaningless), who + ": " + meaningless + " has no meaning here; remove it");
      }
    }
    const RobotSpec builtin;
    RobotSpec spec;
    spec.kinematics = kinematics(r.kinematics(), who, at.at("kinematics"))
                          .value_or(Kinematics::Holonomic);
    spec.radius = positive(r.has_radius(), r.radius(), builtin.radius, who + ": radius", at.at("radius"));
    spec.max_speed = positive(r.has_max_speed(), r.max_speed(), builtin.max_speed,
                              who + ": max_speed", at.at("max_speed"));
    spec.max_omega = positive(r.has_max_omega(), r.max_omega(), builtin.max_omega,
                              who + ": max_omega", at.at("max_omega"));
    return spec;
  }

  void robots(const config::Scenario& file, const Locator& root, WorldSpec& out) {
    std::map<std::string, int> first_line;  // id -> line of its first definition
    for (int i = 0; i < file.robots_size(); ++i) {
      const config::Robot& r = file.robots(i);
      const Locator at = root.nested("robots", i);
      const std::string who = "robot " + (r.id().empty() ? "#" + std::to_string(i) : r.id());

      if (const auto problem = robot_id_problem(r.id())) {
        error(at.at("id"), *problem);
      } else if (const auto [it, fresh] = first_line.emplace(r.id(), at.at("id").line); !fresh) {
        error(at.at("id"), "duplicate robot id " + r.id() + " (first defined at line " +
                               std::to_string(it->second) + ")");
      }

      RobotSpec spec;
      spec.id = r.id();
      const auto k = kinematics(r.kinematics(), who, at.at("kinematics"));
      if (!k) error(at.at("kinematics"), who + ": kinematics must be HOLONOMIC or UNICYCLE");
      spec.kinematics = k.value_or(Kinematics::Holonomic);
      const RobotSpec& d = out.attach_defaults;
      spec.radius = positive(r.has_radius(), r.radius(), d.radius, who + ": radius", at.at("radius"));
      spec.max_speed = positive(r.has_max_speed(), r.max_speed(), d.max_speed,
                                who + ": max_speed", at.at("max_speed"));
      spec.max_omega = positive(r.has_max_omega(), r.max_omega(), d.max_omega,
                                who + ": max_omega", at.at("max_omega"));

      if (!r.has_start()) {
        error(at.self(), who + ": start pose is missing");
      } else {
        spec.start = {r.start().x(), r.start().y(), r.start().theta()};
        place(who, spec, at.at("start"), out);
      }
      (r.spawn_at_start() ? out.robots_at_start : out.known_robots).push_back(spec);
    }
  }

  // Checks the start pose against the world, the obstacles and the robots placed before.
  void place(const std::string& who, const RobotSpec& spec, Position at, const WorldSpec& world) {
    const geometry::Pose2& p = spec.start;
    if (!all_finite({p.x, p.y, p.theta})) {
      error(at, who + ": start pose is not finite");
      return;
    }
    if (!(std::isfinite(spec.radius) && spec.radius > 0.0)) return;  // reported already
    const std::string where = who + " at " + point_text(p.x, p.y);
    const geometry::Vec2 center = p.position();
    if (world_valid_ && !fits_in_world(world.width, world.height, center, spec.radius)) {
      error(at, where + " does not fit inside the world " + world_text(world));
    }
    for (const auto& [index, rect] : checked_obstacles_) {
      if (geometry::circle_overlaps(rect, center, spec.radius)) {
        error(at, where + " overlaps obstacle " + std::to_string(index));
      }
    }
    for (const RobotSpec& other : placed_) {
      if (discs_overlap(center, spec.radius, other.start.position(), other.radius)) {
        error(at, where + " overlaps robot " + other.id);
      }
    }
    placed_.push_back(spec);
  }

  void simulation(const config::Simulation& s, const Locator& at, Scenario& out) {
    SimulationSettings& settings = out.simulation;
    const SimulationSettings defaults;
    switch (s.mode()) {
      case config::CLOCK_MODE_UNSPECIFIED:
      case config::LOCKSTEP: settings.mode = ClockMode::Lockstep; break;
      case config::PACED: settings.mode = ClockMode::Paced; break;
      default:
        error(at.at("mode"),
              "simulation: unknown mode value " + std::to_string(static_cast<int>(s.mode())));
    }
    settings.step_s = positive(s.has_step_s(), s.step_s(), defaults.step_s, "simulation: step_s",
                               at.at("step_s"));
    settings.warp = positive(s.has_warp(), s.warp(), defaults.warp, "simulation: warp", at.at("warp"));
    settings.seed = s.seed();
    settings.ack_timeout_s = positive(s.has_ack_timeout_s(), s.ack_timeout_s(), defaults.ack_timeout_s,
                                      "simulation: ack_timeout_s", at.at("ack_timeout_s"));
    out.world.command_timeout_s =
        positive(s.has_command_timeout_s(), s.command_timeout_s(), WorldSpec{}.command_timeout_s,
                 "simulation: command_timeout_s", at.at("command_timeout_s"));
  }

  const std::string& source_;
  std::vector<ScenarioError>& errors_;
  bool world_valid_ = false;
  std::vector<std::pair<int, geometry::Rect>> checked_obstacles_;  // index in the file, rect
  std::vector<RobotSpec> placed_;
};

}  // namespace

std::string ScenarioLoadResult::error_text() const {
  std::string text;
  for (const ScenarioError& e : errors) text += e.to_string() + "\n";
  return text;
}

ScenarioLoadResult load_scenario_text(const std::string& text, const std::string& source_name) {
  ScenarioLoadResult result;
  SyntaxErrors syntax(source_name, result.errors);
  ParseInfoTree tree;
  pb::TextFormat::Parser parser;
  parser.RecordErrorsTo(&syntax);
  parser.WriteLocationsTo(&tree);
  config::Scenario file;
  if (!parser.ParseFromString(text, &file)) {
    if (result.errors.empty()) result.errors.push_back({source_name, 0, 0, "cannot parse"});
    return result;
  }
  Scenario scenario = ScenarioChecker(source_name, result.errors).check(file, tree);
  std::stable_sort(result.errors.begin(), result.errors.end(),
                   [](const ScenarioError& a, const ScenarioError& b) {
                     return std::tie(a.line, a.column) < std::tie(b.line, b.column);
                   });
  if (result.errors.empty()) result.scenario = std::move(scenario);
  return result;
}

ScenarioLoadResult load_scenario_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ScenarioLoadResult result;
    result.errors.push_back({path, 0, 0, std::string("cannot read file: ") + std::strerror(errno)});
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return load_scenario_text(text.str(), path);
}

}  // namespace autonomy::sim
