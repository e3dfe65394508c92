// The repair-based engine: valid plans for the shipped models whatever the seed, the same run
// for the same seed, repairs that keep the previous plan's other choices, termination by the
// decision budget and by the stop predicate, and proofs only where the space was exhausted.
#include <gtest/gtest.h>

#include <cstdio>

#include "jobshop_instance.hpp"
#include "plan_validator.hpp"
#include "planner.hpp"
#include "planner_language.hpp"
#include "shipped_jobshop.hpp"

namespace autonomy::planner {
namespace {

using Choice = EngineOptions::Choice;

struct LoadedRepair {
  DomainModel model;
  PlanningProblem problem;
};

std::optional<LoadedRepair> load_files(const std::string& model_name, const std::string& problem_text,
                                 const std::string& problem_file = "test.problem") {
  Diagnostics errors;
  const std::string model_file = std::string(PLANNER_EXAMPLES_DIR "/") + model_name;
  auto text = read_text_file(model_file, &errors);
  auto m = text ? parse_model(*text, model_file, &errors) : std::nullopt;
  auto model = m ? build_domain_model(*m, &errors) : std::nullopt;
  auto p = model ? parse_problem(problem_text, problem_file, &errors) : std::nullopt;
  auto problem = p ? build_problem(*model, *p, &errors) : std::nullopt;
  if (!problem) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  return LoadedRepair{*model, *problem};
}

std::optional<LoadedRepair> load_shipped(const std::string& model_name, const std::string& problem_name) {
  Diagnostics errors;
  const std::string file = std::string(PLANNER_EXAMPLES_DIR "/") + problem_name;
  auto text = read_text_file(file, &errors);
  if (!text) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  return load_files(model_name, *text, file);
}

std::optional<LoadedRepair> load_jobshop(const std::string& name) {
  auto shop = load_shipped_jobshop(name);
  if (!shop) return std::nullopt;
  return LoadedRepair{shop->model, shop->problem};
}

struct Recorded {
  Decision decision;
  Choice choice;
  bool applied;
  std::size_t solve;  // which solve() of the anytime run (0, 1, ...)
};

struct RepairRun {
  PlanResult result;
  std::vector<Recorded> decisions;
};

RepairRun plan_by_repair(const LoadedRepair& c, unsigned seed, std::size_t budget) {
  RepairRun run;
  PlanningOptions options;
  options.engine = "repair";
  options.engine_options.seed = seed;
  options.termination.max_decisions = budget;
  std::size_t solve = 0;
  options.engine_options.on_decision = [&](const Decision& d, Choice choice, bool applied) {
    run.decisions.push_back({d, choice, applied, solve});
  };
  options.on_improvement = [&](const FlexiblePlan&) { ++solve; };
  run.result = make_plan(c.model, c.problem, options);
  return run;
}

TEST(RepairEngine, PlansTheShippedModelsWithEverySeedAndTheValidatorAgrees) {
  auto camera = load_shipped("camera.model", "camera.problem");
  auto rover = load_shipped("rover.model", "rover.problem");
  auto ft06 = load_jobshop("ft06");
  ASSERT_TRUE(camera && rover && ft06);
  for (unsigned seed : {1u, 2u, 3u, 17u}) {
    for (const LoadedRepair* c : {&*camera, &*rover, &*ft06}) {
      RepairRun run = plan_by_repair(*c, seed, 50000);
      ASSERT_TRUE(run.result.plan) << "seed " << seed << ": " << to_string(run.result.status);
      EXPECT_NE(run.result.status, PlanStatus::kInfeasible);
      EXPECT_EQ(validate_plan(c->model, c->problem, *run.result.plan), std::vector<std::string>{})
          << "seed " << seed;
    }
  }
}

TEST(RepairEngine, TheSameSeedRunsTheSameSearch) {
  auto la01 = load_jobshop("la01");
  ASSERT_TRUE(la01);
  RepairRun a = plan_by_repair(*la01, 5, 4000), b = plan_by_repair(*la01, 5, 4000);
  ASSERT_TRUE(a.result.plan && b.result.plan);
  EXPECT_GT(a.result.statistics.backtracks, 0u);  // repairs, where the seed matters
  EXPECT_EQ(a.result.plan->makespan, b.result.plan->makespan);
  EXPECT_EQ(a.result.statistics.decisions, b.result.statistics.decisions);
  EXPECT_EQ(a.result.statistics.backtracks, b.result.statistics.backtracks);
  EXPECT_EQ(a.result.statistics.dead_ends, b.result.statistics.dead_ends);
  ASSERT_EQ(a.decisions.size(), b.decisions.size());
  for (std::size_t i = 0; i < a.decisions.size(); ++i) {
    ASSERT_EQ(a.decisions[i].decision.describe(), b.decisions[i].decision.describe()) << i;
    ASSERT_EQ(a.decisions[i].choice, b.decisions[i].choice) << i;
  }
}

// The memory of the previous plan: anytime job-shop, each tighter solve re-applies the last
// schedule's choices (repairing them where the bound breaks them) instead of starting over.
TEST(RepairEngine, EachTighterSolveReplaysTheLastSchedulesChoices) {
  auto ft06 = load_jobshop("ft06");
  ASSERT_TRUE(ft06);
  RepairRun run = plan_by_repair(*ft06, 1, 50000);
  ASSERT_TRUE(run.result.plan);
  std::size_t repairs = 0, remembered = 0, heuristic = 0;
  for (const Recorded& r : run.decisions) {
    repairs += r.choice == Choice::kRepair && r.applied;
    remembered += r.choice == Choice::kRemembered;
    heuristic += r.choice == Choice::kHeuristic;
  }
  std::printf("ft06 by repair: %zu decisions, %zu repairs, %zu remembered, %zu heuristic\n",
              run.decisions.size(), repairs, remembered, heuristic);
  EXPECT_GT(run.result.improvements, 1u);
  // The first solve has no memory; every later one begins with the previous plan's choice.
  for (const Recorded& r : run.decisions) {
    if (r.solve == 0) {
      EXPECT_NE(r.choice, Choice::kRemembered);
    }
  }
  for (std::size_t s = 1; s < run.result.improvements; ++s) {
    auto first = std::find_if(run.decisions.begin(), run.decisions.end(),
                              [&](const Recorded& r) { return r.solve == s; });
    ASSERT_NE(first, run.decisions.end()) << "solve " << s;
    EXPECT_EQ(first->choice, Choice::kRemembered) << "solve " << s;
  }
  // Most decisions after the first solve are replays.
  std::size_t later = 0, later_remembered = 0;
  for (const Recorded& r : run.decisions)
    if (r.solve > 0) ++later, later_remembered += r.choice == Choice::kRemembered;
  EXPECT_GT(later_remembered * 2, later);
}

TEST(RepairEngine, TheDs1DayIsRepairedIntoAValidPlan) {
  auto day = load_shipped("ds1.model", "ds1-day.problem");
  ASSERT_TRUE(day);
  RepairRun run = plan_by_repair(*day, 1, 200000);
  ASSERT_EQ(run.result.status, PlanStatus::kPlanFound) << run.result.explanation;
  EXPECT_EQ(validate_plan(day->model, day->problem, *run.result.plan), std::vector<std::string>{});
  std::size_t repairs = 0, remembered = 0;
  for (const Recorded& r : run.decisions) {
    repairs += r.choice == Choice::kRepair && r.applied;
    remembered += r.choice == Choice::kRemembered && r.applied;
  }
  // The day needs repairs. Within one solve the memory only holds the choices of decisions a
  // repair undid, so every remembered decision is one the previous plan had, re-applied after
  // a repair instead of being searched again; they outnumber the repairs.
  EXPECT_GT(repairs, 0u);
  EXPECT_GT(remembered, repairs);
  std::printf("DS1 day by repair: %zu decisions, %zu repairs, %zu remembered\n",
              run.decisions.size(), repairs, remembered);
}

// The engine alone on a network: both ends of the termination condition stop it and leave
// the network as it was.
TEST(RepairEngine, TheDecisionBudgetAndTheStopPredicateEndTheSearch) {
  auto la01 = load_jobshop("la01");
  ASSERT_TRUE(la01);
  TokenNetwork net(la01->model, la01->problem);
  ASSERT_TRUE(net.initialize());
  const std::size_t flaws = net.flaws().size();
  auto engine = make_search_engine("repair");
  ASSERT_TRUE(engine);
  EXPECT_EQ(engine->name(), "repair");
  // la01 has 50 operations: 30 decisions cannot complete a schedule.
  Termination budget;
  budget.max_decisions = 30;
  SearchOutcome out = engine->solve(net, budget);
  EXPECT_EQ(out.status, SearchStatus::kOutOfBudget);
  EXPECT_EQ(out.statistics.decisions, 30u);
  EXPECT_EQ(net.flaws().size(), flaws);

  std::size_t asked = 0;
  Termination cancel;
  cancel.stop = [&] { return ++asked > 12; };
  out = engine->solve(net, cancel);
  EXPECT_EQ(out.status, SearchStatus::kOutOfBudget);
  EXPECT_EQ(out.statistics.decisions, 12u);
  EXPECT_EQ(net.flaws().size(), flaws);

  // Unbounded, it finishes the schedule and leaves the network in it.
  out = engine->solve(net, {});
  EXPECT_EQ(out.status, SearchStatus::kPlanFound);
  EXPECT_TRUE(net.flaws().empty());
}

// Incomplete, yet a space it did exhaust is answered as such: two pictures that cannot share
// the camera fail at every option, down to the root. A feasible problem is never infeasible
// (the shipped models above); an unfinished one is out of budget.
TEST(RepairEngine, ClaimsInfeasibleOnlyWhenItExhaustedTheSpace) {
  auto two = load_files("camera.model",
                        "problem p\nhorizon 100\nobject s : Spacecraft\n"
                        "initial s.attitude == pointAt(comet)\n"
                        "goal a: s.camera == picture(comet) start [30, 30]\n"
                        "goal b: s.camera == picture(comet) start [32, 32] duration [9, 9]\n");
  ASSERT_TRUE(two);
  RepairRun run = plan_by_repair(*two, 1, 100000);
  EXPECT_EQ(run.result.status, PlanStatus::kInfeasible) << to_string(run.result.status);
  auto la01 = load_jobshop("la01");
  ASSERT_TRUE(la01);
  RepairRun partial = plan_by_repair(*la01, 1, 25);
  EXPECT_EQ(partial.result.status, PlanStatus::kOutOfBudget);
}

}  // namespace
}  // namespace autonomy::planner
