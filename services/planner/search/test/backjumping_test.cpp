// Conflict-directed backjumping (backjumping.cpp): it skips decisions that took no part in a
// failure, and it never skips a plan: on the shipped models, the shipped job shops and random
// small problems it finds what chronological backtracking finds, in no more decisions.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "plan_validator.hpp"
#include "planner.hpp"
#include "planner_language.hpp"
#include "shipped_jobshop.hpp"

namespace autonomy::planner {
namespace {

// A model and a problem from text; `relations` are added to the problem as (from, to, kind,
// lb, ub) between goal labels (the problem language has no syntax for them).
struct GoalRelation {
  std::string from, to;
  pb::TemporalRelation::Kind kind;
  double lb, ub;
};
std::optional<ShippedShop> load_with_relations(const std::string& model_text, const std::string& problem_text,
                           const std::vector<GoalRelation>& relations = {}) {
  Diagnostics errors;
  auto m = parse_model(model_text, "test.model", &errors);
  auto model = m ? build_domain_model(*m, &errors) : std::nullopt;
  auto p = parse_problem(problem_text, "test.problem", &errors);
  if (!model || !p) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  for (const GoalRelation& r : relations) {
    pb::FactRelation* fr = p->add_relations();
    fr->set_from(r.from);
    fr->set_to(r.to);
    fr->mutable_relation()->set_kind(r.kind);
    fr->mutable_relation()->mutable_bounds()->set_lb(r.lb);
    fr->mutable_relation()->mutable_bounds()->set_ub(r.ub);
  }
  auto problem = build_problem(*model, *p, &errors);
  if (!problem) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  return ShippedShop{*model, *problem};
}

struct SearchRun {
  SearchStatus status;
  std::size_t decisions;
};

SearchRun solve_with(const ShippedShop& l, bool backjumping, std::size_t max_decisions = 200000) {
  TokenNetwork net(l.model, l.problem);
  if (!net.initialize()) return {SearchStatus::kExhausted, 0};
  EngineOptions options;
  options.backjumping = backjumping;
  auto engine = make_search_engine("chronological", options);
  Termination term;
  term.max_decisions = max_decisions;
  SearchOutcome out = engine->solve(net, term);
  return {out.status, out.statistics.decisions};
}

const char* kBusyModel =
    "model m\npredicate busy(j: int[0, 99]) duration [10, 10]\nclass M { attribute x = busy }\n";

// Five tokens on p.x, free to go in any order, are decided first (they start earliest); then
// a and c on q.x must end together, which two tokens of one timeline cannot. Chronological
// backtracking tries both orders of c against a under each of the 5! orders on p.x;
// backjumping learns that c's failures depend only on the decision that placed a, whose
// timeline was empty: the search ends after a's and c's first tries.
TEST(Backjumping, SkipsTheDecisionsAFailureDoesNotDependOn) {
  std::string problem = "problem p\nhorizon 1000\nobject p : M\nobject q : M\n";
  for (int i = 0; i < 5; ++i)
    problem += "goal g" + std::to_string(i) + ": p.x == busy(" + std::to_string(i) +
               ") start [0, 500]\n";
  problem += "goal a: q.x == busy(50) start [100, 800]\ngoal c: q.x == busy(51) start [100, 800]\n";
  auto l = load_with_relations(kBusyModel, problem, {{"a", "c", pb::TemporalRelation::ENDS_BEFORE, 0, 0}});
  ASSERT_TRUE(l);
  const SearchRun chronological = solve_with(*l, false), jumping = solve_with(*l, true);
  EXPECT_EQ(chronological.status, SearchStatus::kExhausted);
  EXPECT_EQ(jumping.status, SearchStatus::kExhausted);
  // 5 insertions on p.x, a's one slot, c's two slots.
  EXPECT_EQ(jumping.decisions, 5u + 1 + 2);
  // Every order on p.x (5! = 120 leaves) is tried before the proof.
  EXPECT_GT(chronological.decisions, 120u * 3);
}

// make_plan without and with backjumping at one decision budget: the same status, a plan
// from both or neither (the validator accepts backjumping's), no more decisions with it.
std::pair<PlanResult, PlanResult> plan_both_ways(const ShippedShop& l, std::size_t decisions,
                                                 const std::string& name) {
  PlanningOptions a, b;
  a.termination.max_decisions = b.termination.max_decisions = decisions;
  b.engine_options.backjumping = true;
  PlanResult ra = make_plan(l.model, l.problem, a), rb = make_plan(l.model, l.problem, b);
  EXPECT_EQ(ra.status, rb.status) << name;
  EXPECT_LE(rb.statistics.decisions, ra.statistics.decisions) << name;
  EXPECT_EQ(bool(ra.plan), bool(rb.plan)) << name;
  if (rb.plan) {
    EXPECT_EQ(validate_plan(l.model, l.problem, *rb.plan), std::vector<std::string>{}) << name;
  }
  return {std::move(ra), std::move(rb)};
}

// The same plans and proofs on the shipped job shops (with makespan bounds, as the anytime
// loop sets them) and the shipped models.
TEST(Backjumping, FindsWhatChronologicalBacktrackingFindsOnTheShippedProblems) {
  for (const char* name : {"ft06", "la01", "la05"}) {
    auto shop = load_shipped_jobshop(name);
    ASSERT_TRUE(shop);
    const auto [ra, rb] = plan_both_ways(*shop, 2000, name);
    ASSERT_TRUE(ra.plan && rb.plan) << name;
    EXPECT_EQ(ra.plan->makespan, rb.plan->makespan) << name;
  }
  for (const char* name : {"camera", "rover", "field-rover", "ds1"}) {
    Diagnostics errors;
    const std::string dir = PLANNER_EXAMPLES_DIR "/";
    const std::string problem_file =
        dir + (std::string(name) == "ds1" ? "ds1-day" : name) + ".problem";
    auto mt = read_text_file(dir + name + ".model", &errors);
    auto pt = read_text_file(problem_file, &errors);
    ASSERT_TRUE(mt && pt) << to_string(errors);
    auto l = load_with_relations(*mt, *pt);
    ASSERT_TRUE(l) << name;
    plan_both_ways(*l, 5000, name);
  }
}

// Random small problems on three timelines with random windows and relations between goals:
// backjumping finds a plan exactly when chronological backtracking does (both searches are
// complete here, within the budget), and never makes more decisions.
TEST(Backjumping, NeverSkipsAPlanOnRandomSmallProblems) {
  std::mt19937 rng(29);
  const pb::TemporalRelation::Kind kinds[] = {
      pb::TemporalRelation::BEFORE, pb::TemporalRelation::ENDS_BEFORE,
      pb::TemporalRelation::STARTS_BEFORE, pb::TemporalRelation::AFTER};
  std::size_t feasible = 0, infeasible = 0, fewer = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string problem = "problem p\nhorizon 160\nobject o0 : M\nobject o1 : M\nobject o2 : M\n";
    const int goals = 4 + int(rng() % 6);
    for (int g = 0; g < goals; ++g) {
      const int lo = int(rng() % 60), width = 20 + int(rng() % 60);
      problem += "goal g" + std::to_string(g) + ": o" + std::to_string(rng() % 3) +
                 ".x == busy(" + std::to_string(g) + ") start [" + std::to_string(lo) + ", " +
                 std::to_string(lo + width) + "]\n";
    }
    std::vector<GoalRelation> relations;
    const int count = int(rng() % 6);
    for (int r = 0; r < count; ++r) {
      const int a = int(rng() % goals), b = int(rng() % goals);
      if (a == b) continue;
      // Small bounds: two tokens whose ends (or starts) must be close clash only once they
      // share a timeline and are ordered, which search finds, not the first propagation.
      const double lb = double(rng() % 12), ub = lb + double(rng() % 12);
      relations.push_back(
          {"g" + std::to_string(a), "g" + std::to_string(b), kinds[rng() % 4], lb, ub});
    }
    auto l = load_with_relations(kBusyModel, problem, relations);
    ASSERT_TRUE(l);
    const SearchRun chronological = solve_with(*l, false), jumping = solve_with(*l, true);
    ASSERT_NE(chronological.status, SearchStatus::kOutOfBudget) << problem;
    EXPECT_EQ(chronological.status, jumping.status) << problem;
    EXPECT_LE(jumping.decisions, chronological.decisions) << problem;
    (chronological.status == SearchStatus::kPlanFound ? feasible : infeasible)++;
    if (jumping.decisions < chronological.decisions) ++fewer;
  }
  // The draw gives both kinds of problem, and some where backjumping saves decisions.
  EXPECT_GT(feasible, 200u);
  EXPECT_GT(infeasible, 200u);
  EXPECT_GT(fewer, 5u);
}

}  // namespace
}  // namespace autonomy::planner
