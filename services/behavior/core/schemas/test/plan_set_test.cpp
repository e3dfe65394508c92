// Parallel plans on tiny hand-built fields: the "comm" plan is the "obstacles" plan with an extra
// blocked region standing for a communication-attenuating area.
#include "services/behavior/core/schemas/plan_advice.hpp"
#include "services/behavior/core/schemas/plan_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace autonomy::behavior {
namespace {

using geometry::Vec2;

const double kR = 1.0 / std::sqrt(2.0);

std::shared_ptr<const CostToGoField> field(const std::vector<std::string>& picture, Vec2 goal) {
  return std::make_shared<const CostToGoField>(OccupancyGrid::from_picture(picture, 1.0), goal);
}

// Goal at cell (4, 1). Row 0 is the bottom row (last string).
//   obstacles:      comm (col 2 blocked in rows 1-2):
//   .....           ..#..
//   .....           ..#..
//   .....           .....
PlanSet two_plans(const std::vector<std::string>& comm_picture = {"..#..", "..#..", "....."}) {
  const Vec2 goal(4.5, 1.5);
  std::vector<Plan> plans;
  plans.push_back(Plan::from_field("obstacles", field({".....", ".....", "....."}, goal)));
  plans.push_back(Plan::from_field("obstacles+comm", field(comm_picture, goal)));
  return PlanSet("to_goal", goal, std::move(plans));
}

const Vec2 kStart(0.5, 1.5);       // cell (0, 1)
const Vec2 kInComm(2.5, 1.5);      // cell (2, 1): blocked in the comm plan only

TEST(PlanSet, QueriesFieldAtTheRobotsCell) {
  const PlanSet set = two_plans();
  const PlanQuery open = set.plans()[0].query(kStart);
  EXPECT_FLOAT_EQ(open.cost, 4.0f);
  EXPECT_EQ(open.advice, Vec2(1.0, 0.0));
  const PlanQuery comm = set.plans()[1].query(kStart);
  EXPECT_FLOAT_EQ(comm.cost, static_cast<float>(2.0 + 2.0 * std::sqrt(2.0)));  // under the area
  EXPECT_NEAR(comm.advice.x(), kR, 1e-6);
  EXPECT_NEAR(comm.advice.y(), -kR, 1e-6);
  EXPECT_FALSE(std::isfinite(set.plans()[0].query({-1.0, 0.0}).cost));  // off the grid
}

TEST(PlanSet, MostConstrainedViable) {
  const PlanSet set = two_plans();
  EXPECT_EQ(set.most_constrained_viable(kStart), 1u);
  EXPECT_EQ(set.most_constrained_viable(kInComm), 0u);
  EXPECT_EQ(set.most_constrained_viable({50.0, 50.0}), std::nullopt);
  EXPECT_THROW(PlanSet("empty", Vec2(0, 0), {}), std::invalid_argument);
}

TEST(StaticSelection, ChoosesTheMostConstrainedPlanOnceAndKeepsIt) {
  const PlanSet set = two_plans();
  const auto chosen = choose_static_plan(set, kStart);
  ASSERT_NE(chosen, nullptr);
  EXPECT_EQ(chosen->index(), 1u);
  // Later, pushed into the attenuating area: static selection does not switch plans; its advice
  // leads back out of the area, one cell, to where the plan has a route again.
  const PlanSelection s = chosen->select(set, kInComm);
  EXPECT_EQ(s.plan, 1u);
  EXPECT_FALSE(std::isfinite(s.cost));
  EXPECT_NEAR(s.advice.norm(), 1.0, 1e-12);
  EXPECT_TRUE(std::isfinite(set.plans()[1].query(kInComm + s.advice).cost)) << s.advice.transpose();
}

TEST(Plan, WayBackLeadsToTheNearestCellWithARouteWithinReach) {
  // Columns 2-3 of the top two rows are blocked: from cell (2, 2) the nearest free cell is (1, 2).
  const Plan plan = Plan::from_field("comm", field({"..##.", "..##.", "....."}, Vec2(4.5, 1.5)));
  const PlanQuery q = plan.query({2.5, 2.5});
  EXPECT_FALSE(std::isfinite(q.cost));
  EXPECT_EQ(q.advice, Vec2::Zero());
  EXPECT_EQ(plan.way_back({2.5, 2.5}), Vec2(-1.0, 0.0));
  EXPECT_EQ(plan.way_back({0.5, 0.5}), Vec2::Zero());  // on the plan: no way back needed

  // A 13 x 13 block in a 15 x 15 grid: from its middle the nearest free cell is 7 m away, beyond
  // reach; near its west edge the way back is west.
  std::vector<std::string> picture(13, "." + std::string(13, '#') + ".");
  picture.insert(picture.begin(), std::string(15, '.'));
  picture.push_back(std::string(15, '.'));
  const Plan deep = Plan::from_field("deep", field(picture, Vec2(0.5, 0.5)), 5.0);
  EXPECT_EQ(deep.way_back({7.5, 7.5}), Vec2::Zero());
  EXPECT_EQ(deep.way_back({2.5, 7.5}), Vec2(-1.0, 0.0));
}

TEST(StaticSelection, FallsBackToTheLessConstrainedPlanWhenTheOtherHasNoRoute) {
  // The attenuating area cuts the map in two: the comm plan cannot reach the goal from the start.
  const PlanSet set = two_plans({"..#..", "..#..", "..#.."});
  const auto chosen = choose_static_plan(set, kStart);
  ASSERT_NE(chosen, nullptr);
  EXPECT_EQ(chosen->index(), 0u);
  EXPECT_EQ(chosen->select(set, kStart).advice, Vec2(1.0, 0.0));
  EXPECT_EQ(choose_static_plan(set, {50.0, 50.0}), nullptr);
}

TEST(DynamicSelection, ReChoosesAtEveryPosition) {
  const PlanSet set = two_plans();
  const DynamicPlanSelector dynamic;
  const PlanSelection at_start = dynamic.select(set, kStart);
  EXPECT_EQ(at_start.plan, 1u);
  EXPECT_NEAR(at_start.advice.x(), kR, 1e-6);
  const PlanSelection inside = dynamic.select(set, kInComm);
  EXPECT_EQ(inside.plan, 0u);
  EXPECT_EQ(inside.advice, Vec2(1.0, 0.0));
  EXPECT_FLOAT_EQ(inside.cost, 2.0f);
  const PlanSelection nowhere = dynamic.select(set, {50.0, 50.0});
  EXPECT_EQ(nowhere.plan, std::nullopt);
  EXPECT_EQ(nowhere.advice, Vec2::Zero());
}

TEST(BlendedSelection, WeightedSumOfViablePlansAdvice) {
  const PlanSet set = two_plans();
  const BlendedPlanSelector blended({0.25, 0.75});
  const PlanSelection s = blended.select(set, kStart);
  EXPECT_NEAR(s.advice.x(), 0.25 + 0.75 * kR, 1e-6);
  EXPECT_NEAR(s.advice.y(), -0.75 * kR, 1e-6);
  EXPECT_EQ(s.plan, 1u);
  // Inside the area only the obstacles plan has a route: it alone contributes.
  const PlanSelection inside = blended.select(set, kInComm);
  EXPECT_NEAR(inside.advice.x(), 0.25, 1e-12);
  EXPECT_NEAR(inside.advice.y(), 0.0, 1e-12);
  EXPECT_THROW(BlendedPlanSelector({-1.0}), std::invalid_argument);
}

TEST(PlanAdvice, VotesTheSelectedAdvice) {
  auto set = std::make_shared<const PlanSet>(two_plans());
  const PlanAdvice dynamic(set, std::make_shared<const DynamicPlanSelector>());
  Perception p;
  p.pose = {kInComm.x(), kInComm.y(), 0.0};
  EXPECT_EQ(dynamic.vote(p), Vec2(1.0, 0.0));

  const PlanAdvice single(field({"...", "...", "..."}, Vec2(0.5, 2.5)));  // goal top left
  p.pose = {2.5, 0.5, 0.0};
  const Vec2 v = single.vote(p);
  EXPECT_NEAR(v.x(), -kR, 1e-6);
  EXPECT_NEAR(v.y(), kR, 1e-6);
}

TEST(Plan, AnyCallableCanBeAPlan) {
  const Plan ramp("ramp", [](const Vec2& p) { return PlanQuery{static_cast<float>(p.x()), Vec2(-1, 0)}; });
  EXPECT_FLOAT_EQ(ramp.query({3.0, 0.0}).cost, 3.0f);
  EXPECT_THROW(Plan("none", nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
