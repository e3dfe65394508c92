#include <gtest/gtest.h>

#include <cstdio>

#include "jobshop_instance.hpp"
#include "plan_validator.hpp"
#include "planner.hpp"
#include "planner_language.hpp"

namespace autonomy::planner {
namespace {

struct Loaded {
  DomainModel model;
  PlanningProblem problem;
};

Loaded load(const std::string& model_file, const std::string& problem_text) {
  Diagnostics errors;
  auto text = read_text_file(model_file, &errors);
  auto m = parse_model(*text, model_file, &errors);
  auto model = build_domain_model(*m, &errors);
  EXPECT_TRUE(model) << to_string(errors);
  auto p = parse_problem(problem_text, "test.problem", &errors);
  EXPECT_TRUE(p) << to_string(errors);
  auto problem = build_problem(*model, *p, &errors);
  EXPECT_TRUE(problem) << to_string(errors);
  return {*model, *problem};
}

const char* kCameraModel = PLANNER_EXAMPLES_DIR "/camera.model";

const PlanToken* find(const FlexiblePlan& plan, const std::string& timeline,
                      const std::string& predicate, const std::string& parameter = "") {
  for (const PlanToken& t : plan.tokens)
    if (t.timeline() == timeline && t.predicate == predicate &&
        (parameter.empty() || (!t.parameters.empty() && t.parameters[0] == parameter)))
      return &t;
  return nullptr;
}

TEST(Search, TheCameraExamplePlansATurnThenThePicture) {
  Diagnostics errors;
  Loaded c = load(kCameraModel, *read_text_file(PLANNER_EXAMPLES_DIR "/camera.problem", &errors));
  for (const std::string& engine : search_engine_names()) {
    PlanningOptions options;
    options.engine = engine;
    options.termination.max_decisions = 10000;
    PlanResult r = make_plan(c.model, c.problem, options);
    ASSERT_EQ(r.status, PlanStatus::kPlanFound) << engine << ": " << r.explanation;
    const FlexiblePlan& plan = *r.plan;
    EXPECT_EQ(validate_plan(c.model, c.problem, plan), std::vector<std::string>{}) << engine;
    const PlanToken* picture = find(plan, "dsone.camera", "picture", "asteroid");
    const PlanToken* turn = find(plan, "dsone.attitude", "turning");
    const PlanToken* point = find(plan, "dsone.attitude", "pointAt", "asteroid");
    ASSERT_TRUE(picture && turn && point) << engine;
    EXPECT_EQ(turn->parameters, (std::vector<std::string>{"star", "asteroid"}));
    // The turn takes at least 20, so the picture starts no earlier than 20; it must end by 150.
    EXPECT_GE(picture->start_lb, 20);
    EXPECT_LE(picture->end_ub, 150);
    // Flexible: the picture can still slide (its start has a window, not a time).
    EXPECT_LT(picture->start_lb, picture->start_ub);
    EXPECT_LE(point->start_ub, picture->start_ub);
    // The camera is ready right before and after: three tokens on its timeline.
    EXPECT_EQ(plan.timelines[1].name, "dsone.camera");
    EXPECT_EQ(plan.timelines[1].tokens.size(), 3u) << engine;
    EXPECT_EQ(to_message(plan).tokens_size(), int(plan.tokens.size()));
  }
}

TEST(Search, ATooShortWindowIsInfeasibleFromTheStartWithItsStatements) {
  Loaded c = load(kCameraModel,
                  "problem p\nhorizon 100\nobject s : Spacecraft\n"
                  "goal g: s.camera == picture(comet) start [10, 20] end [0, 12]\n");
  PlanResult r = make_plan(c.model, c.problem, {});
  EXPECT_EQ(r.status, PlanStatus::kInfeasible);
  EXPECT_NE(r.explanation.find("test.problem:4"), std::string::npos) << r.explanation;
  EXPECT_NE(r.explanation.find("duration of picture"), std::string::npos) << r.explanation;
}

TEST(Search, TwoPicturesAtOnceExhaustTheSearch) {
  // Each is fine alone; the camera cannot take both (they would overlap on one timeline).
  Loaded c = load(kCameraModel,
                  "problem p\nhorizon 100\nobject s : Spacecraft\n"
                  "initial s.attitude == pointAt(comet)\n"
                  "goal a: s.camera == picture(comet) start [30, 30]\n"
                  "goal b: s.camera == picture(comet) start [32, 32] duration [9, 9]\n");
  PlanningOptions options;
  options.termination.max_decisions = 100000;
  PlanResult r = make_plan(c.model, c.problem, options);
  EXPECT_EQ(r.status, PlanStatus::kInfeasible) << to_string(r.status);
  EXPECT_GT(r.statistics.backtracks, 0u);
  // Deletion filtering names the two goals (each with its line), not the initial value.
  EXPECT_EQ(r.explanation,
            "search exhausted: no plan achieves together: goal a (test.problem:5); goal b "
            "(test.problem:6)");
  // A third goal that fits with either is left out of the explanation.
  Loaded three = load(kCameraModel,
                      "problem p\nhorizon 100\nobject s : Spacecraft\n"
                      "initial s.attitude == pointAt(comet)\n"
                      "goal z: s.camera == picture(comet) start [80, 90]\n"
                      "goal a: s.camera == picture(comet) start [30, 30]\n"
                      "goal b: s.camera == picture(comet) start [32, 32] duration [9, 9]\n");
  PlanResult t = make_plan(three.model, three.problem, options);
  EXPECT_EQ(t.status, PlanStatus::kInfeasible) << to_string(t.status);
  EXPECT_EQ(t.explanation,
            "search exhausted: no plan achieves together: goal a (test.problem:6); goal b "
            "(test.problem:7)");
}

Loaded load_text(const std::string& model_text, const std::string& problem_text) {
  Diagnostics errors;
  auto m = parse_model(model_text, "test.model", &errors);
  EXPECT_TRUE(m) << to_string(errors);
  auto model = build_domain_model(*m, &errors);
  EXPECT_TRUE(model) << to_string(errors);
  auto p = parse_problem(problem_text, "test.problem", &errors);
  EXPECT_TRUE(p) << to_string(errors);
  auto problem = build_problem(*model, *p, &errors);
  EXPECT_TRUE(problem) << to_string(errors);
  return {*model, *problem};
}

// Each of the twelve relations, with bounds, yields a slave the independent validator accepts
// (the token network's and the validator's readings of the relation agree) and whose distance
// sits inside the bounds at the earliest times.
TEST(Search, EveryTemporalRelationIsPlannedAsTheValidatorReadsIt) {
  const char* relations[] = {"before",     "after",       "startsBefore",    "startsAfter",
                             "endsBefore", "endsAfter",   "startsBeforeEnd", "endsAfterStart",
                             "contains",   "containedBy", "parallels",       "paralleledBy"};
  for (const char* rel : relations) {
    Loaded c = load_text(
        std::string("model r\npredicate a() duration [10, 10]\npredicate b() duration [4, 30]\n"
                    "class C { attribute x = a  attribute y = b }\n(x == a) ") +
            rel + "[2, 5](y == b)\n",
        "problem p\nhorizon 200\nobject o : C\ngoal g: o.x == a start [50, 50]\n");
    PlanResult r = make_plan(c.model, c.problem, {});
    ASSERT_EQ(r.status, PlanStatus::kPlanFound) << rel << ": " << r.explanation;
    EXPECT_EQ(validate_plan(c.model, c.problem, *r.plan), std::vector<std::string>{}) << rel;
    const PlanToken* b = find(*r.plan, "o.y", "b");
    ASSERT_TRUE(b) << rel;
    EXPECT_EQ(b->origin, std::string(rel) + " of token 0") << rel;
  }
  // And a relation that cannot hold: b must end 2..5 before a starts yet start after a ends.
  Loaded bad = load_text(
      "model r\npredicate a() duration [10, 10]\npredicate b() duration [4, 30]\n"
      "class C { attribute x = a  attribute y = b }\n(x == a) after[2, 5](y == b) startsAfter(y == "
      "b)\n"
      "(y == b) startsAfter[20, 30](x == a)\n",
      "problem p\nhorizon 200\nobject o : C\ngoal g: o.x == a start [50, 50]\n");
  EXPECT_EQ(make_plan(bad.model, bad.problem, {}).status, PlanStatus::kInfeasible);
}

// The paper's record(s, r, d, e): s + r * d == e with d the token's duration, in both
// directions between the constraint network and the temporal network.
TEST(Search, ADurationInAParameterConstraintFixesTheTokensLength) {
  Loaded c = load_text(
      "model rec\npredicate record(s: real[0, 100], r: real[1, 2], e: real[0, 100]) duration [1, "
      "80]\n"
      "  where s + r * duration == e\nclass Recorder { attribute data = record }\n",
      "problem p\nhorizon 200\nobject rec : Recorder\ngoal g: rec.data == record(10, 2, 50)\n");
  PlanResult r = make_plan(c.model, c.problem, {});
  ASSERT_EQ(r.status, PlanStatus::kPlanFound) << r.explanation;
  const PlanToken* t = find(*r.plan, "rec.data", "record");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->duration_lb, 20);
  EXPECT_EQ(t->duration_ub, 20);
  EXPECT_EQ(validate_plan(c.model, c.problem, *r.plan), std::vector<std::string>{});
}

TEST(Search, AnOptionalGoalThatCannotFitIsLeftOutWithItsPenalty) {
  Loaded c = load(
      kCameraModel,
      "problem p\nhorizon 100\nobject s : Spacecraft\n"
      "initial s.attitude == pointAt(comet)\n"
      "goal a: s.camera == picture(comet) start [30, 30]\n"
      "optional goal b: s.camera == picture(comet) start [32, 32] duration [9, 9] penalty 4\n");
  PlanResult r = make_plan(c.model, c.problem, {});
  ASSERT_EQ(r.status, PlanStatus::kPlanFound) << r.explanation;
  EXPECT_EQ(r.plan->omitted_goals, std::vector<std::string>{"b"});
  EXPECT_EQ(r.plan->penalty, 4);
  EXPECT_EQ(validate_plan(c.model, c.problem, *r.plan), std::vector<std::string>{});
}

TEST(Search, AReusableResourceSequencesTokensThatWouldExceedItsCapacity) {
  const char* model =
      "model power\npredicate idle()\npredicate heat() duration [10, 10] uses power 60\n"
      "predicate shoot() duration [10, 10] uses power 50\n"
      "class Craft { attribute heater = idle | heat  attribute camera = shoot  reusable power "
      "capacity 100 }\n";
  Loaded c =
      load_text(model,
                "problem p\nhorizon 100\nobject c : Craft\ngoal h: c.heater == heat start [0, 20]\n"
                "goal s: c.camera == shoot start [0, 20]\n");
  PlanResult r = make_plan(c.model, c.problem, {});
  ASSERT_EQ(r.status, PlanStatus::kPlanFound) << r.explanation;
  EXPECT_EQ(validate_plan(c.model, c.problem, *r.plan), std::vector<std::string>{});
  const PlanToken *h = find(*r.plan, "c.heater", "heat"), *s = find(*r.plan, "c.camera", "shoot");
  ASSERT_TRUE(h && s);
  // Ordered in the flexible plan, not only at the earliest times.
  EXPECT_TRUE(h->end_ub <= s->start_lb || s->end_ub <= h->start_lb || h->end_lb <= s->start_lb ||
              s->end_lb <= h->start_lb);
  Loaded tight =
      load_text(model,
                "problem p\nhorizon 100\nobject c : Craft\ngoal h: c.heater == heat start [0, 5]\n"
                "goal s: c.camera == shoot start [0, 5]\n");
  EXPECT_EQ(make_plan(tight.model, tight.problem, {}).status, PlanStatus::kInfeasible);
}

TEST(Search, AReservoirIsFilledBeforeItIsDrained) {
  Loaded c = load_text(
      "model store\npredicate take() duration [5, 5] produces storage 40\n"
      "predicate send() duration [5, 5] consumes storage 50\n"
      "class Craft { attribute camera = take  attribute radio = send  reservoir storage [0, 60] "
      "initial 20 }\n",
      "problem p\nhorizon 100\nobject c : Craft\ngoal s: c.radio == send\ngoal t: c.camera == take "
      "start [30, 60]\n");
  PlanResult r = make_plan(c.model, c.problem, {});
  ASSERT_EQ(r.status, PlanStatus::kPlanFound) << r.explanation;
  EXPECT_EQ(validate_plan(c.model, c.problem, *r.plan), std::vector<std::string>{});
  const PlanToken *s = find(*r.plan, "c.radio", "send"), *t = find(*r.plan, "c.camera", "take");
  ASSERT_TRUE(s && t);
  EXPECT_LE(t->end_lb, s->end_lb);
}

TEST(Search, AnUnknownEngineIsAnInvalidRequest) {
  Loaded c = load(kCameraModel, "problem p\nhorizon 100\nobject s : Spacecraft\n");
  PlanningOptions options;
  options.engine = "annealing";
  EXPECT_EQ(make_plan(c.model, c.problem, options).status, PlanStatus::kInvalidRequest);
  EXPECT_EQ(make_search_engine("annealing"), nullptr);
}

TEST(Search, TheDecisionBudgetStopsTheRun) {
  Diagnostics errors;
  Loaded c = load(kCameraModel, *read_text_file(PLANNER_EXAMPLES_DIR "/camera.problem", &errors));
  PlanningOptions options;
  options.termination.max_decisions = 2;
  EXPECT_EQ(make_plan(c.model, c.problem, options).status, PlanStatus::kOutOfBudget);
  bool stopped = false;
  options.termination.max_decisions = static_cast<std::size_t>(-1);
  options.termination.stop = [&] { return stopped = true; };
  EXPECT_EQ(make_plan(c.model, c.problem, options).status, PlanStatus::kOutOfBudget);
  EXPECT_TRUE(stopped);
}

// Tokens that cannot all fit on their timeline from the start are named with their statements.
TEST(Search, AnOverloadNamesTheGoalsThatCannotFit) {
  Loaded c = load_text(
      "model m\npredicate busy(j: int[0, 9]) duration [10, 10]\nclass M { attribute x = busy }\n",
      "problem p\nhorizon 100\nobject o : M\ngoal a: o.x == busy(1) end [0, 15]\n"
      "goal z: o.x == busy(3) start [40, 90]\ngoal b: o.x == busy(2) end [0, 15]\n");
  PlanResult r = make_plan(c.model, c.problem, {});
  EXPECT_EQ(r.status, PlanStatus::kInfeasible);
  EXPECT_EQ(r.explanation,
            "overload on o.x in [0, 15]: the durations of o.x == busy(1) (goal a, "
            "test.problem:4); o.x == busy(2) (goal b, test.problem:6) add up to 20, more than "
            "the window holds");
}

// Parameter propagation before any search (issue 29): `where a < b, b < a` on a range of 2^52
// would step both bounds by one a call; the cycle is found and named at once. A constraint
// loop that is no cycle of differences still steps, and the budget ends it inside propagation
// (the stop condition here counts its own calls: deterministic, no clock).
TEST(Search, PropagationFindsCyclesAndHonoursTheBudget) {
  const std::string problem = "problem p\nhorizon 100\nobject o : C\ngoal o.x == p(_, _";
  Loaded cycle = load_text(
      "model m\npredicate p(a: int[0, 4503599627370495], b: int[0, 4503599627370495])"
      " where a < b, b < a\nclass C { attribute x = p }\n",
      problem + ")\n");
  for (const std::string& engine : search_engine_names()) {
    PlanningOptions options;
    options.engine = engine;
    PlanResult r = make_plan(cycle.model, cycle.problem, options);
    EXPECT_EQ(r.status, PlanStatus::kInfeasible) << engine;
    EXPECT_NE(r.explanation.find("no values satisfy a + 1 <= b, b + 1 <= a"), std::string::npos)
        << r.explanation;
  }
  Loaded loop = load_text(
      "model m\npredicate p(a: int[1, 4503599627370495], b: int[0, 4503599627370495],"
      " c: int[0, 4503599627370495]) where a + 1 * b == c, c < b\n"
      "class C { attribute x = p }\n",
      problem + ", _)\n");
  PlanningOptions options;
  int asked = 0;
  options.termination.stop = [&] { return ++asked > 100; };
  PlanResult r = make_plan(loop.model, loop.problem, options);
  EXPECT_EQ(r.status, PlanStatus::kOutOfBudget) << r.explanation;
  EXPECT_NE(r.explanation.find("stopped during parameter propagation"), std::string::npos)
      << r.explanation;
  EXPECT_EQ(asked, 101);  // it stopped the first time the budget said so
}

// Job-shop instances as timelines: valid schedules, makespans against the known optimum.
struct JobShopCase {
  const char* name;
  long optimum;
  std::size_t budget;
  bool proof_expected;  // within the budget (decisions are deterministic, not timed)
};

class JobShop : public ::testing::TestWithParam<JobShopCase> {};

TEST_P(JobShop, SchedulesAreValidAndNoBetterThanTheOptimum) {
  const JobShopCase& jc = GetParam();
  Diagnostics errors;
  const std::string file = std::string(PLANNER_EXAMPLES_DIR "/jobshop/") + jc.name;
  auto inst = parse_jobshop(*read_text_file(file, &errors), file, &errors);
  ASSERT_TRUE(inst) << to_string(errors);
  auto model = build_domain_model(jobshop_model(*inst), &errors);
  auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
  ASSERT_TRUE(model && problem) << to_string(errors);
  PlanningOptions options;
  options.termination.max_decisions = jc.budget;
  std::vector<std::int64_t> improvements;
  options.on_improvement = [&](const FlexiblePlan& p) { improvements.push_back(p.makespan); };
  PlanResult r = make_plan(*model, *problem, options);
  ASSERT_TRUE(r.plan) << to_string(r.status);
  EXPECT_EQ(validate_plan(*model, *problem, *r.plan), std::vector<std::string>{});
  const std::int64_t makespan = r.plan->makespan;
  // No valid schedule beats the optimum; a proof must land on it exactly.
  EXPECT_GE(makespan, jc.optimum);
  if (r.status == PlanStatus::kOptimal) {
    EXPECT_EQ(makespan, jc.optimum);
  }
  if (jc.proof_expected) {
    EXPECT_EQ(r.status, PlanStatus::kOptimal);
  }
  for (std::size_t i = 1; i < improvements.size(); ++i)
    EXPECT_LT(improvements[i], improvements[i - 1]);
  std::printf(
      "%s: makespan %lld (optimum %ld, gap %.1f%%), %s, %zu decisions, %zu backtracks, %zu plans\n",
      jc.name, static_cast<long long>(makespan), jc.optimum,
      100.0 * double(makespan - jc.optimum) / double(jc.optimum), to_string(r.status),
      r.statistics.decisions, r.statistics.backtracks, improvements.size());
}

// Limited discrepancy search finds good schedules early, and its last, unlimited probe keeps
// it complete: la01 proved optimal within 40000 decisions (plain backtracking takes 46000).
TEST(JobShopEngines, LimitedDiscrepancyProvesLa01) {
  Diagnostics errors;
  const std::string file = std::string(PLANNER_EXAMPLES_DIR "/jobshop/la01");
  auto inst = parse_jobshop(*read_text_file(file, &errors), file, &errors);
  ASSERT_TRUE(inst) << to_string(errors);
  auto model = build_domain_model(jobshop_model(*inst), &errors);
  auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
  ASSERT_TRUE(model && problem) << to_string(errors);
  PlanningOptions options;
  options.engine = "discrepancy";
  options.termination.max_decisions = 40000;
  PlanResult r = make_plan(*model, *problem, options);
  ASSERT_TRUE(r.plan);
  EXPECT_EQ(validate_plan(*model, *problem, *r.plan), std::vector<std::string>{});
  EXPECT_EQ(r.status, PlanStatus::kOptimal);
  EXPECT_EQ(r.plan->makespan, 666);
}

INSTANTIATE_TEST_SUITE_P(Instances, JobShop,
                         ::testing::Values(JobShopCase{"ft06", 55, 20000, true},
                                           JobShopCase{"la05", 593, 20000, true},
                                           JobShopCase{"la01", 666, 20000, false},
                                           JobShopCase{"la02", 655, 20000, true},
                                           JobShopCase{"la03", 597, 20000, false},
                                           JobShopCase{"la04", 590, 20000, true}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace autonomy::planner
