#pragma once
// A robot's mission as plain values (the loader converts idl/mission.proto into these; tests and
// tools may build them directly). A mission is a graph of states: each runs one behavior and
// leaves it when a transition's perceptual trigger fires (Wagner & Arkin 2003, "plans in serial").
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/schemas/plan_set.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

// Effective weights of the motor schemas (already multiplied out: the file's `reactive` factor is
// folded into move_to_goal and avoid_obstacles).
struct SchemaGains {
  double move_to_goal = 0.0;
  double avoid_obstacles = 0.0;
  double plan = 0.0;
  double noise = 0.0;
  double avoid_teammates = 0.0;
  double stay_near_teammates = 0.0;

  bool operator==(const SchemaGains& o) const {
    return move_to_goal == o.move_to_goal && avoid_obstacles == o.avoid_obstacles &&
           plan == o.plan && noise == o.noise && avoid_teammates == o.avoid_teammates &&
           stay_near_teammates == o.stay_near_teammates;
  }
};

struct SchemaParameters {
  double slowdown_radius_m = 2.0;
  double sphere_of_influence_m = 3.0;
  double safety_margin_m = 0.5;
  double noise_persistence_s = 2.0;
  double teammate_spacing_m = 3.0;
  double comfort_radius_m = 15.0;
  double max_radius_m = 40.0;
};

struct Circle {
  geometry::Vec2 center = geometry::Vec2::Zero();
  double radius = 0.0;
};

// A circle or a rectangle (borders included).
struct Area {
  enum class Shape { Circle, Rect };
  Shape shape = Shape::Circle;
  Circle circle;
  geometry::Rect rect;

  bool contains(const geometry::Vec2& p) const {
    return shape == Shape::Rect ? rect.contains(p) : (p - circle.center).norm() <= circle.radius;
  }
};

struct TriggerSpec {
  enum class Kind { AtGoal, InArea, LostContact, ContactRestored, Timeout, AllOf, AnyOf };
  Kind kind = Kind::Timeout;
  Area area;                          // InArea
  std::string teammate;               // LostContact ("" = any), ContactRestored ("" = all)
  double seconds = 0.0;               // Timeout
  std::vector<TriggerSpec> children;  // AllOf, AnyOf
};

struct TransitionSpec {
  std::string to;
  TriggerSpec when;
};

struct BehaviorSpec {
  enum class Kind { GoTo, Wait, Wander, Stop };
  Kind kind = Kind::Stop;
  // GoTo only: the plan set whose goal is pursued ("" = reactive only, towards `goal`).
  std::string plan_set;
  geometry::Vec2 goal = geometry::Vec2::Zero();  // GoTo: the plan set's goal, or the file's point
  double tolerance_m = 2.0;                      // GoTo: for AtGoal
  SchemaGains gains;                             // GoTo and Wander
};

struct StateSpec {
  std::string name;
  BehaviorSpec behavior;
  std::vector<TransitionSpec> transitions;  // checked in order; the first that fires wins
};

struct ConstraintLayerSpec {
  std::string name;
  std::vector<geometry::Rect> areas;
};

inline constexpr const char* kObstaclesLayer = "obstacles";

struct PlanSetSpec {
  std::string name;
  geometry::Vec2 goal = geometry::Vec2::Zero();
  std::vector<std::string> layers;  // layers[0] == "obstacles"; plan k avoids layers[0..k]
  PlanSelectionMode selection = PlanSelectionMode::Static;
  std::vector<double> blend_gains;  // Blended: one per layer
};

struct MissionSpec {
  std::string name;
  std::string robot;
  std::vector<std::string> teammates;
  std::string initial_state;
  SchemaParameters schemas;
  std::vector<ConstraintLayerSpec> layers;
  std::vector<PlanSetSpec> plan_sets;
  std::vector<StateSpec> states;

  const StateSpec* state(const std::string& name) const {
    for (const StateSpec& s : states) {
      if (s.name == name) return &s;
    }
    return nullptr;
  }
  const PlanSetSpec* plan_set(const std::string& name) const {
    for (const PlanSetSpec& p : plan_sets) {
      if (p.name == name) return &p;
    }
    return nullptr;
  }
};

}  // namespace autonomy::behavior
