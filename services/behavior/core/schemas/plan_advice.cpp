#include "services/behavior/core/schemas/plan_advice.hpp"

#include <stdexcept>
#include <utility>

namespace autonomy::behavior {

PlanAdvice::PlanAdvice(std::shared_ptr<const PlanSet> plans,
                       std::shared_ptr<const PlanSelector> selector)
    : plans_(std::move(plans)), selector_(std::move(selector)) {
  if (!plans_ || !selector_) throw std::invalid_argument("plan advice needs a plan set and a selector");
}

namespace {
std::shared_ptr<const PlanSet> single_plan(std::shared_ptr<const CostToGoField> field) {
  if (!field) throw std::invalid_argument("plan advice needs a field");
  const geometry::Vec2 goal = field->goal();
  std::vector<Plan> plans;
  plans.push_back(Plan::from_field("plan", std::move(field)));
  return std::make_shared<const PlanSet>("plan", goal, std::move(plans));
}
}  // namespace

PlanAdvice::PlanAdvice(std::shared_ptr<const CostToGoField> field)
    : PlanAdvice(single_plan(std::move(field)), std::make_shared<const FixedPlanSelector>(0)) {}

PlanSelection PlanAdvice::selection(const geometry::Vec2& position) const {
  return selector_->select(*plans_, position);
}

geometry::Vec2 PlanAdvice::vote(const Perception& p) const {
  return selection(p.pose.position()).advice;
}

}  // namespace autonomy::behavior
