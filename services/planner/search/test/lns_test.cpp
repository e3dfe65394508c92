// The large-neighbourhood search engine: it starts from a greedy first plan (the chronological
// engine's without a makespan objective) and improves on it, every plan it hands over is
// valid, the same seed runs the same search, its proofs come only from exhausted full
// searches, and the budget and the stop predicate end it with the best plan so far.
#include <gtest/gtest.h>

#include <algorithm>

#include "plan_validator.hpp"
#include "planner.hpp"
#include "shipped_jobshop.hpp"

namespace autonomy::planner {
namespace {

struct ShopRun {
  PlanResult result;
  std::vector<FlexiblePlan> improvements;
};

ShopRun plan_shop(const ShippedShop& shop, const std::string& engine, std::size_t budget, unsigned seed = 1) {
  ShopRun run;
  PlanningOptions options;
  options.engine = engine;
  options.engine_options.seed = seed;
  options.termination.max_decisions = budget;
  options.on_improvement = [&](const FlexiblePlan& p) { run.improvements.push_back(p); };
  run.result = make_plan(shop.model, shop.problem, options);
  return run;
}

// la01 (10 jobs x 5 machines, optimum 666): within 20,000 decisions the chronological engine
// ends at 773 unproved; lns starts from a better first plan (greedy dives by active schedule
// generation), the neighbourhoods reach 666 and the full search proves it.
TEST(LnsEngine, ImprovesOnTheFirstPlanAndEveryPlanIsValid) {
  auto la01 = load_shipped_jobshop("la01");
  ASSERT_TRUE(la01);
  ShopRun chrono = plan_shop(*la01, "chronological", 20000);
  ShopRun lns = plan_shop(*la01, "lns", 20000);
  ASSERT_TRUE(chrono.result.plan && lns.result.plan);
  ASSERT_GE(lns.improvements.size(), 2u);
  // A better first plan than the chronological engine's, then strictly better ones.
  EXPECT_LT(lns.improvements.front().makespan, chrono.improvements.front().makespan);
  for (std::size_t i = 1; i < lns.improvements.size(); ++i)
    EXPECT_LT(lns.improvements[i].makespan, lns.improvements[i - 1].makespan) << i;
  for (const FlexiblePlan& p : lns.improvements)
    EXPECT_EQ(validate_plan(la01->model, la01->problem, p), std::vector<std::string>{});
  EXPECT_EQ(lns.result.plan->makespan, 666);
  EXPECT_EQ(lns.result.status, PlanStatus::kOptimal);
  EXPECT_GT(chrono.result.plan->makespan, 666);  // what the same budget gives without it
  EXPECT_EQ(chrono.result.status, PlanStatus::kPlanFound);
  EXPECT_LE(lns.result.statistics.decisions, 20000u);
}

TEST(LnsEngine, TheSameSeedRunsTheSameSearchAndAnotherSeedAnother) {
  auto la03 = load_shipped_jobshop("la03");
  ASSERT_TRUE(la03);
  ShopRun a = plan_shop(*la03, "lns", 3000, 7), b = plan_shop(*la03, "lns", 3000, 7);
  ASSERT_TRUE(a.result.plan && b.result.plan);
  ASSERT_EQ(a.improvements.size(), b.improvements.size());
  for (std::size_t i = 0; i < a.improvements.size(); ++i)
    EXPECT_EQ(a.improvements[i].makespan, b.improvements[i].makespan) << i;
  EXPECT_EQ(a.result.statistics.decisions, b.result.statistics.decisions);
  EXPECT_EQ(a.result.statistics.dead_ends, b.result.statistics.dead_ends);
  // Seeds pick other neighbourhoods: the runs differ somewhere after the first plan.
  bool differs = false;
  for (unsigned seed : {8u, 9u, 10u}) {
    ShopRun c = plan_shop(*la03, "lns", 3000, seed);
    ASSERT_TRUE(c.result.plan);
    differs |= c.result.statistics.dead_ends != a.result.statistics.dead_ends ||
               c.improvements.size() != a.improvements.size();
  }
  EXPECT_TRUE(differs);
}

// A decision budget too small for any proof: the best plan found, never "optimal" (the
// neighbourhoods' exhaustion proves nothing, as they keep part of the plan fixed), and the
// stop predicate ends a run the same way.
TEST(LnsEngine, TheBudgetAndTheStopPredicateEndItWithTheBestPlan) {
  auto la03 = load_shipped_jobshop("la03");
  ASSERT_TRUE(la03);
  ShopRun small = plan_shop(*la03, "lns", 600);
  ASSERT_TRUE(small.result.plan);
  EXPECT_EQ(small.result.status, PlanStatus::kPlanFound);
  EXPECT_EQ(small.result.plan->makespan, small.improvements.back().makespan);
  EXPECT_EQ(validate_plan(la03->model, la03->problem, *small.result.plan),
            std::vector<std::string>{});

  PlanningOptions options;
  options.engine = "lns";
  int asked = 0;
  options.termination.stop = [&] { return ++asked > 2000; };
  PlanResult r = make_plan(la03->model, la03->problem, options);
  ASSERT_TRUE(r.plan);
  EXPECT_EQ(r.status, PlanStatus::kPlanFound);
  EXPECT_EQ(validate_plan(la03->model, la03->problem, *r.plan), std::vector<std::string>{});
}

// Plans of one token and of two on one timeline: the neighbourhoods' size never exceeds the
// plan, and the full search proves the optimum.
TEST(LnsEngine, TinyPlansAreProved) {
  for (const auto& [text, optimum] : {std::pair{"1 1\n0 5\n", 5}, std::pair{"2 1\n0 3\n0 4\n", 7}}) {
    Diagnostics errors;
    auto inst = parse_jobshop(text, "tiny", &errors);
    ASSERT_TRUE(inst) << to_string(errors);
    auto model = build_domain_model(jobshop_model(*inst), &errors);
    ASSERT_TRUE(model) << to_string(errors);
    auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
    ASSERT_TRUE(problem) << to_string(errors);
    ShopRun run = plan_shop({*model, *problem}, "lns", 10000);
    ASSERT_TRUE(run.result.plan) << to_string(run.result.status);
    EXPECT_EQ(run.result.status, PlanStatus::kOptimal);
    EXPECT_EQ(run.result.plan->makespan, optimum);
  }
}

// The engine is reached by name like the others.
TEST(LnsEngine, IsMadeByName) {
  auto engine = make_search_engine("lns");
  ASSERT_TRUE(engine);
  EXPECT_EQ(engine->name(), "lns");
  const auto names = search_engine_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "lns"), names.end());
}

}  // namespace
}  // namespace autonomy::planner
