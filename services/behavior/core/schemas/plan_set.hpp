#pragma once
// Internalized plans used in parallel (Wagner & Arkin, "Internalized Plans for Communication-
// Sensitive Robot Team Behaviors", IROS 2003, section 2.3; after Payton, Rosenblatt & Keirsey,
// "Plan Guided Reaction", IEEE SMC 20(6), 1990).
//
// A PlanSet holds several plans towards the same goal, ordered from the least constrained (only
// physical obstacles) to the most constrained (obstacles plus communication-attenuating areas,
// plus further layers). Each more constrained plan blocks everything the previous one blocks, so
// following any plan never leads into an obstacle of a less constrained one, and a plan "affords a
// route" from a place exactly when its cost there is finite.
//
// Selectors turn a plan set and the robot's position into one advice vector:
//  - Static (paper, section 2.3 and 4): choose once, at the start, the most constrained plan with a
//    finite cost at the robot's position, then follow it to completion. Implemented as the pure
//    choice choose_static_plan() followed by a FixedPlanSelector on the chosen index; the caller
//    (MissionExecutor) makes the choice when it enters the state and keeps it.
//  - Dynamic: the same choice re-made at every query (DynamicPlanSelector).
//  - Blended (the paper's "cost functions with tunable gains that represent each constraint"):
//    advice = sum over plans i with finite cost at the position of gain_i * advice_i, where
//    advice_i is plan i's unit (8-direction) advice vector. Not normalised: the gains set the
//    strength, agreeing plans add up, disagreeing plans partly cancel (equal gains on exactly
//    opposite advice cancel to zero, so prefer unequal gains). Plans without a route contribute
//    nothing, so the blend degrades to the plans that can still reach the goal.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/cost_to_go_field.hpp"

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

// What one plan says about one position.
struct PlanQuery {
  float cost = std::numeric_limits<float>::infinity();  // metres to the goal; +inf: no route
  geometry::Vec2 advice = geometry::Vec2::Zero();        // unit or zero
};

// One internalized plan: a name (its constraint set, e.g. "obstacles+comm_attenuation") and a
// query. Usually a CostToGoField, but any callable works (tests, other planners' fields).
class Plan {
 public:
  using Query = std::function<PlanQuery(const geometry::Vec2& position)>;
  // Where the cost is +inf but the plan's free space is near (the robot was pushed into an
  // inflation margin or a constrained area by other schemas): the unit vector back to it; zero
  // otherwise. Asked only by a selector that follows this plan off its route: it searches.
  using WayBack = std::function<geometry::Vec2(const geometry::Vec2& position)>;

  // Throws std::invalid_argument on an empty query. Without a way back, way_back() is zero.
  Plan(std::string name, Query query, WayBack way_back = nullptr);
  // Queries the field at the cell holding the position: cost(cell) and advice(cell); outside the
  // grid, +inf and zero. The way back heads for the nearest reachable cell within
  // `way_back_within_m`. Throws std::invalid_argument on a null field.
  static Plan from_field(std::string name, std::shared_ptr<const CostToGoField> field,
                         double way_back_within_m = kWayBackWithinM);
  // How far a plan looks for its free space from a blocked position: a few metres, the distance
  // other schemas can push a robot over the edge of a plan before it notices.
  static constexpr double kWayBackWithinM = 5.0;

  const std::string& name() const { return name_; }
  [[nodiscard]] PlanQuery query(const geometry::Vec2& position) const { return query_(position); }
  [[nodiscard]] geometry::Vec2 way_back(const geometry::Vec2& position) const {
    return way_back_ ? way_back_(position) : geometry::Vec2::Zero();
  }

 private:
  std::string name_;
  Query query_;
  WayBack way_back_;
};

class PlanSet {
 public:
  // `least_to_most_constrained` must not be empty (std::invalid_argument).
  PlanSet(std::string name, geometry::Vec2 goal, std::vector<Plan> least_to_most_constrained);

  const std::string& name() const { return name_; }
  const geometry::Vec2& goal() const { return goal_; }
  const std::vector<Plan>& plans() const { return plans_; }
  std::size_t size() const { return plans_.size(); }

  // The most constrained plan with a finite cost at `position`; nullopt when none has a route.
  [[nodiscard]] std::optional<std::size_t> most_constrained_viable(
      const geometry::Vec2& position) const;

 private:
  std::string name_;
  geometry::Vec2 goal_;
  std::vector<Plan> plans_;
};

struct PlanSelection {
  std::optional<std::size_t> plan;  // the plan followed; for Blended the most constrained viable one
  geometry::Vec2 advice = geometry::Vec2::Zero();
  float cost = std::numeric_limits<float>::infinity();  // the followed plan's cost (Blended: same)
};

enum class PlanSelectionMode { Static, Dynamic, Blended };

// One work method, const: a selector's choice depends only on its construction and the query.
class PlanSelector {
 public:
  virtual ~PlanSelector() = default;
  [[nodiscard]] virtual PlanSelection select(const PlanSet& plans,
                                             const geometry::Vec2& position) const = 0;
};

// Always follows plan `index` (the outcome of a static choice). Off the plan (cost +inf) its
// advice is the way back, so a robot pushed into an area its plan avoids returns to the plan
// instead of drifting on with no advice. An index out of range gives no advice rather than
// undefined behaviour.
class FixedPlanSelector final : public PlanSelector {
 public:
  explicit FixedPlanSelector(std::size_t index) : index_(index) {}
  [[nodiscard]] PlanSelection select(const PlanSet& plans,
                                     const geometry::Vec2& position) const override;
  std::size_t index() const { return index_; }

 private:
  std::size_t index_;
};

class DynamicPlanSelector final : public PlanSelector {
 public:
  [[nodiscard]] PlanSelection select(const PlanSet& plans,
                                     const geometry::Vec2& position) const override;
};

class BlendedPlanSelector final : public PlanSelector {
 public:
  // One gain per plan, least constrained first; each finite and >= 0 (std::invalid_argument).
  // A plan without a gain (the list is shorter than the set) contributes nothing.
  explicit BlendedPlanSelector(std::vector<double> gains);
  [[nodiscard]] PlanSelection select(const PlanSet& plans,
                                     const geometry::Vec2& position) const override;
  const std::vector<double>& gains() const { return gains_; }

 private:
  std::vector<double> gains_;
};

// Static selection: the choice made once at `start`; nullptr when no plan has a route there
// (the caller may try again at a later position).
[[nodiscard]] std::unique_ptr<FixedPlanSelector> choose_static_plan(const PlanSet& plans,
                                                                     const geometry::Vec2& start);

}  // namespace autonomy::behavior
