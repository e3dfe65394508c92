#include "services/behavior/core/schemas/plan_set.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace autonomy::behavior {

Plan::Plan(std::string name, Query query, WayBack way_back)
    : name_(std::move(name)), query_(std::move(query)), way_back_(std::move(way_back)) {
  if (!query_) throw std::invalid_argument("plan " + name_ + " has no query");
}

Plan Plan::from_field(std::string name, std::shared_ptr<const CostToGoField> field, double way_back_within_m) {
  if (!field) throw std::invalid_argument("plan " + name + " has no field");
  auto query = [field](const geometry::Vec2& p) {
    PlanQuery q;
    const auto cell = field->geometry().cell_at(p);
    if (!cell) return q;
    q.cost = field->cost(*cell);
    if (std::isfinite(q.cost)) q.advice = field->advice(*cell);
    return q;
  };
  auto way_back = [field, way_back_within_m](const geometry::Vec2& p) -> geometry::Vec2 {
    if (std::isfinite(field->cost_at(p))) return geometry::Vec2::Zero();
    const auto back = field->nearest_reachable(p, way_back_within_m);
    if (!back) return geometry::Vec2::Zero();
    const geometry::Vec2 to = field->geometry().centre(*back) - p;
    return to.norm() > 1e-9 ? geometry::Vec2(to.normalized()) : geometry::Vec2::Zero();
  };
  return Plan(std::move(name), std::move(query), std::move(way_back));
}

PlanSet::PlanSet(std::string name, geometry::Vec2 goal, std::vector<Plan> least_to_most_constrained)
    : name_(std::move(name)), goal_(std::move(goal)), plans_(std::move(least_to_most_constrained)) {
  if (plans_.empty()) throw std::invalid_argument("plan set " + name_ + " has no plans");
}

std::optional<std::size_t> PlanSet::most_constrained_viable(const geometry::Vec2& position) const {
  for (std::size_t i = plans_.size(); i-- > 0;) {
    if (std::isfinite(plans_[i].query(position).cost)) return i;
  }
  return std::nullopt;
}

PlanSelection FixedPlanSelector::select(const PlanSet& plans, const geometry::Vec2& position) const {
  PlanSelection s;
  if (index_ >= plans.size()) return s;
  const PlanQuery q = plans.plans()[index_].query(position);
  s.plan = index_;
  s.cost = q.cost;
  s.advice = std::isfinite(q.cost) ? q.advice : plans.plans()[index_].way_back(position);
  return s;
}

PlanSelection DynamicPlanSelector::select(const PlanSet& plans, const geometry::Vec2& position) const {
  // Top-down: the first finite cost is the answer, so the query is not repeated for it.
  for (std::size_t i = plans.size(); i-- > 0;) {
    const PlanQuery q = plans.plans()[i].query(position);
    if (std::isfinite(q.cost)) return {i, q.advice, q.cost};
  }
  return {};
}

BlendedPlanSelector::BlendedPlanSelector(std::vector<double> gains) : gains_(std::move(gains)) {
  for (double g : gains_) {
    if (!(std::isfinite(g) && g >= 0.0)) {
      throw std::invalid_argument("blended plan gains must be finite and >= 0");
    }
  }
}

PlanSelection BlendedPlanSelector::select(const PlanSet& plans, const geometry::Vec2& position) const {
  PlanSelection s;
  const std::size_t n = std::min(plans.size(), gains_.size());
  for (std::size_t i = 0; i < n; ++i) {
    const PlanQuery q = plans.plans()[i].query(position);
    if (!std::isfinite(q.cost)) continue;
    s.advice += gains_[i] * q.advice;
    s.plan = i;  // ends at the most constrained viable plan
    s.cost = q.cost;
  }
  return s;
}

std::unique_ptr<FixedPlanSelector> choose_static_plan(const PlanSet& plans,
                                                      const geometry::Vec2& start) {
  const auto index = plans.most_constrained_viable(start);
  if (!index) return nullptr;
  return std::make_unique<FixedPlanSelector>(*index);
}

}  // namespace autonomy::behavior
