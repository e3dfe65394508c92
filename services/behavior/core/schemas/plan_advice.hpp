#pragma once
// plan advice: the internalized plan's vote (Wagner & Arkin 2003, section 2.2). The robot indexes
// the plan with its own position and gets a unit vector towards the cheapest neighbouring cell
// (one of eight directions), or zero where no plan has a route or at the goal cell. Blending it
// with move-to-goal, avoid-obstacles and noise smooths the plan's 8-direction digitisation.
//
// Which plan of the set is asked is the selector's business (plan_set.hpp); the schema holds both
// and stays const: a static choice is made before construction (choose_static_plan).
#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/schemas/motor_schema.hpp"
#include "services/behavior/core/schemas/plan_set.hpp"

#include <memory>

namespace autonomy::behavior {

class PlanAdvice final : public MotorSchema {
 public:
  // Throws std::invalid_argument on a null plan set or selector.
  PlanAdvice(std::shared_ptr<const PlanSet> plans, std::shared_ptr<const PlanSelector> selector);
  // A single plan: a set of one followed with FixedPlanSelector(0).
  explicit PlanAdvice(std::shared_ptr<const CostToGoField> field);

  [[nodiscard]] geometry::Vec2 vote(const Perception& p) const override;
  std::string_view name() const override { return "plan"; }

  // The full selection behind the vote (which plan, its cost), for events and logs.
  [[nodiscard]] PlanSelection selection(const geometry::Vec2& position) const;
  const PlanSet& plans() const { return *plans_; }

 private:
  std::shared_ptr<const PlanSet> plans_;
  std::shared_ptr<const PlanSelector> selector_;
};

}  // namespace autonomy::behavior
